#include "app/cli/contact_study_command.h"

#include "app/cli/output_options.h"
#include "app/cli/standard_output.h"
#include "app/exercise/answer_parser.h"
#include "app/output/atomic_file.h"
#include "app/output/study_csv.h"
#include "physics/workbook/lab/contact_study.h"

#include <QTextStream>


namespace rbw {

namespace {

constexpr int kExitOk = 0;
constexpr int kExitBadInput = 2;

QTextStream& err()
{
    static QTextStream s(stderr);
    return s;
}

int fail(const QString& message)
{
    err() << "rbw: contact-study: " << message << '\n';
    err().flush();
    return kExitBadInput;
}

// "1,2,4" -> numbers; false with the offending text if one does not read.
template <class T, class Read>
bool readList(const QString& text, std::vector<T>* out, QString* bad, Read read)
{
    out->clear();
    for (const QString& part : text.split(',')) {
        bool ok = false;
        const T value = read(part.trimmed(), &ok);
        if (!ok) {
            *bad = part.trimmed();
            return false;
        }
        out->push_back(value);
    }
    return true;
}

} // namespace

int runContactStudyCommand(const QCommandLineParser& parser, const QString& problem)
{
    const std::optional<lab::ContactProblem> p = lab::contactProblemFromName(problem.toStdString());
    if (!p) {
        return fail(QStringLiteral("PROBLEM: unknown problem \"%1\" (%2)").arg(problem, lab::contactProblemNames()));
    }
    lab::ContactStudyConfig config;
    config.problem = *p;
    QString bad;
    if (parser.isSet("iterations") &&
        !readList(parser.value("iterations"), &config.iterations, &bad,
                  [](const QString& t, bool* ok) { return t.toInt(ok); })) {
        return fail(QStringLiteral("--iterations: must be whole numbers, got \"%1\"").arg(bad));
    }
    if (parser.isSet("dt") &&
        !readList(parser.value("dt"), &config.dts, &bad, [](const QString& t, bool* ok) {
            // a number or a fraction such as 1/60
            const ParsedAnswer a = parseAnswerText(t, 1);
            *ok = a.ok();
            return a.ok() ? a.values[0] : 0.0;
        })) {
        return fail(QStringLiteral("--dt: must be finite numbers > 0, got \"%1\"").arg(bad));
    }
    if (parser.isSet("t-end")) {
        bool ok = false;
        config.tEnd = parser.value("t-end").toDouble(&ok);
        if (!ok) return fail(QStringLiteral("--t-end: must be a finite number > 0, got \"%1\"").arg(parser.value("t-end")));
    }
    if (parser.isSet("boxes")) {
        if (config.problem != lab::ContactProblem::Rain) {
            return fail(QStringLiteral("--boxes: only rain has a number of boxes, not %1").arg(problem));
        }
        bool ok = false;
        config.rainBoxes = parser.value("boxes").toInt(&ok);
        if (!ok) return fail(QStringLiteral("--boxes: must be a whole number, got \"%1\"").arg(parser.value("boxes")));
    }
    if (parser.isSet("output")) {
        if (const QString conflict = cli::outputConflict({{QStringLiteral("--output"), parser.value("output")}}, {});
            !conflict.isEmpty()) {
            return fail(conflict);
        }
    }
    const std::vector<SceneIssue> issues = lab::validateContactStudy(config);
    if (!issues.empty()) {
        for (const SceneIssue& i : issues) {
            err() << "rbw: contact-study: --" << QString::fromStdString(i.path).replace('_', '-') << ": "
                  << QString::fromStdString(i.reason) << '\n';
        }
        err().flush();
        return kExitBadInput;
    }
    const lab::ContactStudyResult result = lab::runContactStudy(config, [](int done, int total) {
        err() << "rbw: contact-study: " << done << "/" << total << " runs\n";
        err().flush();
    });
    const QByteArray csv = contactStudyToCsv(result).toUtf8();
    if (!parser.isSet("output")) {
        cli::standardOutput().write(csv);   // checked by main() (cli::finishStandardOutput)
        return kExitOk;
    }
    QString error;
    if (!writeFileAtomically(parser.value("output"), csv, &error)) {
        return fail(error.replace(QLatin1String(": cannot write:"), QLatin1String(": --output: cannot write:")));
    }
    return kExitOk;
}

} // namespace rbw
