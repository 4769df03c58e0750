#include "app/cli/command_options.h"

#include <QMap>

#include <algorithm>
#include <vector>

namespace rbw::cli {

namespace {

// The table: command -> its options (main.cpp's parser declares them all).
const QMap<QString, QStringList>& table()
{
    static const QMap<QString, QStringList> t{
        {QStringLiteral("run"), {"steps", "dt", "integrator", "trace", "format"}},
        {QStringLiteral("study"), {"integrators", "dt", "t-end", "output"}},
        {QStringLiteral("check"), {"step", "tolerance", "format"}},
        {QStringLiteral("contact-study"), {"iterations", "dt", "t-end", "boxes", "output"}},
        {QStringLiteral("exercise"), {"seed", "output", "worksheet", "answer-key", "answers-key"}},
        {QStringLiteral("diagnose"), {"simulator", "trajectory", "probes", "timeout", "format"}},
        {QStringLiteral("probes"), {"output", "probes"}},
        {QStringLiteral("quantities"), {"format"}},
        {QStringLiteral("lessons"), {}},
        {QStringLiteral("integrators"), {}},
    };
    return t;
}

// Help and version belong to every command.
bool isGlobal(const QString& name)
{
    static const QStringList g{"h", "?", "help", "help-all", "v", "version"};
    return g.contains(name);
}

int editDistance(const QString& a, const QString& b)
{
    std::vector<int> row(static_cast<size_t>(b.size()) + 1);
    for (size_t j = 0; j < row.size(); ++j) row[j] = static_cast<int>(j);
    for (qsizetype i = 1; i <= a.size(); ++i) {
        int diagonal = row[0];
        row[0] = static_cast<int>(i);
        for (qsizetype j = 1; j <= b.size(); ++j) {
            const int up = row[static_cast<size_t>(j)];
            row[static_cast<size_t>(j)] = std::min({up + 1, row[static_cast<size_t>(j - 1)] + 1,
                                                    diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = up;
        }
    }
    return row.back();
}

QString suggestion(const QString& name, const QStringList& own)
{
    QString best;
    int bestDistance = 3;   // at most two edits away
    for (const QString& o : own) {
        const int d = editDistance(name, o);
        if (d < bestDistance) {
            bestDistance = d;
            best = o;
        }
    }
    return best;
}

} // namespace

QStringList commandOptions(const QString& command)
{
    return table().value(command);
}

QString optionProblem(const QCommandLineParser& parser, const QString& command)
{
    if (!table().contains(command)) return {};
    const QStringList own = commandOptions(command);
    QStringList seen;
    for (const QString& name : parser.optionNames()) {
        if (isGlobal(name)) continue;
        if (!own.contains(name)) {
            QString message = QStringLiteral("%1: --%2 is not an option of %1").arg(command, name);
            if (const QString s = suggestion(name, own); !s.isEmpty()) message += QStringLiteral("; did you mean --%1?").arg(s);
            else if (own.isEmpty()) message += QStringLiteral(" (%1 takes no options)").arg(command);
            else message += QStringLiteral(" (its options: --%1)").arg(own.join(QStringLiteral(", --")));
            return message + QStringLiteral(" (see rbw --help)");
        }
        // --simulator of diagnose may be given once per program (--format csv)
        const bool repeatable = command == QLatin1String("diagnose") && name == QLatin1String("simulator");
        if (seen.contains(name) && !repeatable) {
            const QStringList values = parser.values(name);
            return QStringLiteral("%1: --%2 is given %3 times (\"%4\"); give it once")
                .arg(command, name)
                .arg(values.size())
                .arg(values.join(QStringLiteral("\", \"")));
        }
        seen << name;
    }
    return {};
}

} // namespace rbw::cli
