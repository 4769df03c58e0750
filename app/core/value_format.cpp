#include "app/core/value_format.h"

#include <QJsonArray>
#include <QStringList>

namespace rbw {

QString formatNumber(double x, int digits)
{
    if (x == 0.0) {
        return QStringLiteral("0");   // no "-0"
    }
    return QString::number(x, 'g', digits);
}

namespace {

QString joinNumbers(const double* values, int n, int digits)
{
    QStringList parts;
    for (int i = 0; i < n; ++i) {
        parts << formatNumber(values[i], digits);
    }
    return parts.join(QStringLiteral(", "));
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
            [&](const Vec3& v) { return '(' + joinNumbers(v.data(), 3, digits) + ')'; },
            [&](const Quat& q) {
                const std::array<double, 4> c = toWxyz(q);
                return QStringLiteral("[w x y z] = [") + joinNumbers(c.data(), 4, digits) + ']';
            },
            [&](const Mat3& m) {
                QStringList rows;
                for (int r = 0; r < 3; ++r) {
                    const double row[3] = {m(r, 0), m(r, 1), m(r, 2)};
                    rows << '[' + joinNumbers(row, 3, digits) + ']';
                }
                return '[' + rows.join(QStringLiteral(", ")) + ']';
            },
        },
        value);
}

QString latexValue(const TraceValue& value, int digits)
{
    return std::visit(
        Overloaded{
            [&](double x) { return formatNumber(x, digits); },
            [&](const Vec3& v) {
                return QStringLiteral("\\begin{pmatrix} %1 \\\\ %2 \\\\ %3 \\end{pmatrix}")
                    .arg(formatNumber(v.x(), digits), formatNumber(v.y(), digits), formatNumber(v.z(), digits));
            },
            [&](const Quat& q) {
                const std::array<double, 4> c = toWxyz(q);
                return QStringLiteral("(%1,\\ %2,\\ %3,\\ %4)")
                    .arg(formatNumber(c[0], digits), formatNumber(c[1], digits), formatNumber(c[2], digits),
                         formatNumber(c[3], digits));
            },
            [&](const Mat3& m) {
                QStringList rows;
                for (int r = 0; r < 3; ++r) {
                    rows << QStringLiteral("%1 & %2 & %3")
                                .arg(formatNumber(m(r, 0), digits), formatNumber(m(r, 1), digits),
                                     formatNumber(m(r, 2), digits));
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
