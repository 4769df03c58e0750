#include "app/exercise/answer_parser.h"

#include <QRegularExpression>
#include <QStringList>

#include <cmath>

namespace rbw {

namespace {

// One component: a decimal number ("-2.4", "1e-3", "+.5") or a fraction of two
// ("64/27", "-5/27", "1.5/2"). False with `error` set when it is neither.
bool readComponent(const QString& token, double* out, QString* error)
{
    const int slash = token.indexOf(QLatin1Char('/'));
    bool ok = false;
    if (slash < 0) {
        *out = token.toDouble(&ok);
    } else {
        bool okNum = false;
        bool okDen = false;
        const double num = token.left(slash).toDouble(&okNum);
        const double den = token.mid(slash + 1).toDouble(&okDen);
        ok = okNum && okDen;
        if (ok && den == 0.0) {
            *error = QStringLiteral("division by zero in '%1'").arg(token);
            return false;
        }
        if (ok) *out = num / den;
    }
    if (!ok || !std::isfinite(*out)) {
        *error = QStringLiteral("cannot read '%1'").arg(token);
        return false;
    }
    return true;
}

} // namespace

ParsedAnswer parseAnswerText(const QString& text, int expectedCount)
{
    ParsedAnswer r;
    QString t = text;
    // The minus sign a word processor or a copy from the app's LaTeX gives.
    t.replace(QChar(0x2212), QLatin1Char('-'));
    static const QRegularExpression brackets(QStringLiteral("[()\\[\\]{}]"));
    t.replace(brackets, QStringLiteral(" "));
    // "64 / 27" is one fraction: glue a slash to its neighbours.
    static const QRegularExpression spacedSlash(QStringLiteral("\\s*/\\s*"));
    t.replace(spacedSlash, QStringLiteral("/"));
    static const QRegularExpression separators(QStringLiteral("[\\s,;]+"));
    const QStringList tokens = t.split(separators, Qt::SkipEmptyParts);
    if (tokens.isEmpty()) {
        r.error = QStringLiteral("nothing written");
        return r;
    }
    for (const QString& token : tokens) {
        double v = 0.0;
        if (!readComponent(token, &v, &r.error)) {
            r.values.clear();
            return r;
        }
        r.values.push_back(v);
    }
    if (static_cast<int>(r.values.size()) != expectedCount) {
        r.error = expectedCount == 1
                      ? QStringLiteral("1 number expected, got %1").arg(r.values.size())
                      : QStringLiteral("%1 numbers expected, got %2").arg(expectedCount).arg(r.values.size());
        // "3,11" read as two numbers: a decimal comma.
        static const QRegularExpression decimalComma(QStringLiteral("\\d,\\d"));
        if (text.contains(decimalComma)) r.error += QStringLiteral(" (decimal commas? use a decimal point: 3.11, not 3,11)");
        r.values.clear();
    }
    return r;
}

QString answerText(const std::vector<double>& values)
{
    QStringList parts;
    for (double v : values) parts << QString::number(v, 'g', 10);
    switch (values.size()) {
    case 1:
        return parts.value(0);
    case 3:
        return QStringLiteral("(%1)").arg(parts.join(QStringLiteral(", ")));
    case 4:
        return QStringLiteral("[%1]").arg(parts.join(QLatin1Char(' ')));
    case 9:
        return QStringLiteral("%1 %2 %3; %4 %5 %6; %7 %8 %9")
            .arg(parts[0], parts[1], parts[2], parts[3], parts[4], parts[5], parts[6], parts[7], parts[8]);
    default:
        return parts.join(QLatin1Char(' '));
    }
}

} // namespace rbw
