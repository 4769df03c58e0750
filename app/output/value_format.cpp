#include "app/output/value_format.h"

#include <QJsonArray>
#include <QStringList>

#include <algorithm>
#include <cmath>

namespace rbw {

QString formatNumber(double x, int digits)
{
    if (x == 0.0) {
        return QStringLiteral("0");   // no "-0"
    }
    return QString::number(x, 'g', digits);
}

namespace {

// For display only: an entry smaller than 1e-12 of the largest entry of the same
// value is round-off (e.g. cos 90 deg = 6e-17 in R) and is shown as 0. JSON output keeps
// every bit.
double chop(double x, double scale)
{
    return std::abs(x) < 1e-12 * scale ? 0.0 : x;
}

double largest(const double* values, int n)
{
    double m = 0.0;
    for (int i = 0; i < n; ++i) m = std::max(m, std::abs(values[i]));
    return m;
}

QString joinNumbers(const double* values, int n, int digits, double scale)
{
    QStringList parts;
    for (int i = 0; i < n; ++i) {
        parts << formatNumber(chop(values[i], scale), digits);
    }
    return parts.join(QStringLiteral(", "));
}

// "[a, b, c]" per row, round-off chopped against the matrix's largest entry.
QStringList matrixRows(const Mat3& m, int digits)
{
    const double scale = m.cwiseAbs().maxCoeff();
    QStringList rows;
    for (int r = 0; r < 3; ++r) {
        const double row[3] = {m(r, 0), m(r, 1), m(r, 2)};
        rows << '[' + joinNumbers(row, 3, digits, scale) + ']';
    }
    return rows;
}

template <class... Ts>
struct Overloaded : Ts... {
    using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

} // namespace

QString formatValue(const TraceValue& value, int digits)
{
    return std::visit(
        Overloaded{
            [&](double x) { return formatNumber(x, digits); },
            [&](const Vec3& v) { return '(' + joinNumbers(v.data(), 3, digits, largest(v.data(), 3)) + ')'; },
            [&](const Quat& q) {
                const std::array<double, 4> c = toWxyz(q);
                return QStringLiteral("[w x y z] = [") + joinNumbers(c.data(), 4, digits, largest(c.data(), 4)) + ']';
            },
            [&](const Mat3& m) { return '[' + matrixRows(m, digits).join(QStringLiteral(", ")) + ']'; },
        },
        value);
}

QString formatValueLines(const TraceValue& value, int digits)
{
    // One number per line, as the derivation's column vectors; a matrix one row per line.
    auto lines = [&](const double* values, int n, const char* const* labels) {
        const double scale = largest(values, n);
        QStringList out;
        for (int i = 0; i < n; ++i) {
            out << (labels != nullptr ? QString::fromLatin1(labels[i]) + ' ' : QString()) +
                       formatNumber(chop(values[i], scale), digits);
        }
        return out.join('\n');
    };
    return std::visit(
        Overloaded{
            [&](double x) { return formatNumber(x, digits); },
            [&](const Vec3& v) { return lines(v.data(), 3, nullptr); },
            [&](const Quat& q) {
                static const char* const wxyz[4] = {"w", "x", "y", "z"};
                const std::array<double, 4> c = toWxyz(q);
                return lines(c.data(), 4, wxyz);
            },
            [&](const Mat3& m) { return matrixRows(m, digits).join('\n'); },
        },
        value);
}

QString latexValue(const TraceValue& value, int digits)
{
    return std::visit(
        Overloaded{
            [&](double x) { return formatNumber(x, digits); },
            [&](const Vec3& v) {
                const double s = largest(v.data(), 3);
                return QStringLiteral("\\begin{pmatrix} %1 \\\\ %2 \\\\ %3 \\end{pmatrix}")
                    .arg(formatNumber(chop(v.x(), s), digits), formatNumber(chop(v.y(), s), digits),
                         formatNumber(chop(v.z(), s), digits));
            },
            [&](const Quat& q) {
                const std::array<double, 4> c = toWxyz(q);
                const double s = largest(c.data(), 4);
                return QStringLiteral("(%1,\\ %2,\\ %3,\\ %4)")
                    .arg(formatNumber(chop(c[0], s), digits), formatNumber(chop(c[1], s), digits),
                         formatNumber(chop(c[2], s), digits), formatNumber(chop(c[3], s), digits));
            },
            [&](const Mat3& m) {
                const double s = m.cwiseAbs().maxCoeff();
                QStringList rows;
                for (int r = 0; r < 3; ++r) {
                    rows << QStringLiteral("%1 & %2 & %3")
                                .arg(formatNumber(chop(m(r, 0), s), digits), formatNumber(chop(m(r, 1), s), digits),
                                     formatNumber(chop(m(r, 2), s), digits));
                }
                return QStringLiteral("\\begin{pmatrix} ") + rows.join(QStringLiteral(" \\\\ ")) +
                       QStringLiteral(" \\end{pmatrix}");
            },
        },
        value);
}

QJsonValue jsonVec3(const Vec3& v)
{
    return QJsonArray{v.x(), v.y(), v.z()};
}

QJsonValue jsonQuat(const Quat& q)
{
    return QJsonArray{q.w(), q.x(), q.y(), q.z()};
}

QJsonValue jsonMat3(const Mat3& m)
{
    QJsonArray rows;
    for (int r = 0; r < 3; ++r) {
        rows.append(QJsonArray{m(r, 0), m(r, 1), m(r, 2)});
    }
    return rows;
}

QJsonValue jsonValue(const TraceValue& value)
{
    return std::visit(Overloaded{
                          [](double x) { return QJsonValue(x); },
                          [](const Vec3& v) { return jsonVec3(v); },
                          [](const Quat& q) { return jsonQuat(q); },
                          [](const Mat3& m) { return jsonMat3(m); },
                      },
                      value);
}

QString valueKind(const TraceValue& value)
{
    static const char* const kinds[] = {"scalar", "vector", "quaternion", "matrix"};
    return QString::fromLatin1(kinds[value.index()]);
}

} // namespace rbw
