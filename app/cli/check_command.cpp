#include "app/cli/check_command.h"

#include "app/cli/standard_output.h"
#include "app/exercise/answers_file.h"
#include "app/scene/scene_loader.h"
#include "physics/workbook/checker/checker.h"
#include "physics/engine/world.h"

#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

#include <algorithm>
#include <cmath>
#include <memory>

namespace rbw {

namespace {

constexpr int kAllCorrect = 0;
constexpr int kSomeWrong = 1;
constexpr int kBadInput = 2;
constexpr int kBlowUp = 3;

int fail(int status, const QString& message)
{
    QTextStream err(stderr);
    err << "rbw: " << message << '\n';
    return status;
}

QString numbers(const std::vector<double>& v)
{
    // Rounding noise of a computed matrix (1e-15 beside 4.8) is written as 0.
    double scale = 0.0;
    for (double x : v) scale = std::max(scale, std::abs(x));
    QStringList parts;
    for (double x : v) parts << QString::number(std::abs(x) < 1e-12 * scale ? 0.0 : x, 'g', 7);
    if (v.size() == 1) return parts.first();
    if (v.size() == 9) {
        return QStringLiteral("[[%1], [%2], [%3]]")
            .arg(parts.mid(0, 3).join(", "), parts.mid(3, 3).join(", "), parts.mid(6, 3).join(", "));
    }
    return QLatin1Char('(') + parts.join(", ") + QLatin1Char(')');
}

QJsonValue jsonNumbers(const std::vector<double>& v)
{
    if (v.size() == 1) return v[0];
    QJsonArray a;
    if (v.size() == 9) {
        for (int i = 0; i < 3; ++i) a.append(QJsonArray{v[3 * i], v[3 * i + 1], v[3 * i + 2]});
        return a;
    }
    for (double x : v) a.append(x);
    return a;
}

// RFC 4180: a field with a comma, a quote or a line break is quoted, quotes doubled
// (a body or file name may hold any of them).
QString csvField(QString s)
{
    if (s.contains(QLatin1Char(',')) || s.contains(QLatin1Char('"')) || s.contains(QLatin1Char('\n')) ||
        s.contains(QLatin1Char('\r'))) {
        s.replace(QLatin1Char('"'), QStringLiteral("\"\""));
        return QLatin1Char('"') + s + QLatin1Char('"');
    }
    return s;
}

struct FileResult {
    QString file;
    long step = 0;
    std::vector<Answer> answers;
    std::vector<AnswerResult> results;
};

} // namespace

int runCheckCommand(const QCommandLineParser& parser, const QString& scenePath, const QStringList& answerPaths)
{
    const QString format = parser.isSet("format") ? parser.value("format") : QStringLiteral("text");
    if (format != "text" && format != "json" && format != "csv") {
        return fail(kBadInput, "--format: must be text, json or csv for check, got \"" + format + "\"");
    }
    double tolerance = 1e-3;
    if (parser.isSet("tolerance")) {
        bool ok = false;
        tolerance = parser.value("tolerance").toDouble(&ok);
        if (!ok || !std::isfinite(tolerance) || tolerance <= 0.0 || tolerance >= 1.0) {
            return fail(kBadInput, "--tolerance: must be a number between 0 and 1 (relative), got \"" +
                                       parser.value("tolerance") + "\"");
        }
    }
    std::optional<long> stepOption;
    if (parser.isSet("step")) {
        bool ok = false;
        const long k = parser.value("step").toLong(&ok);
        if (!ok || k < 0 || k > 1000000000L) {
            return fail(kBadInput, "--step: must be a whole number from 0 to 10^9, got \"" + parser.value("step") + "\"");
        }
        stepOption = k;
    }
    const SceneLoadResult loaded = loadSceneFile(scenePath);
    if (!loaded.ok()) return fail(kBadInput, loaded.errors.join("\nrbw: "));
    const SceneDef& scene = *loaded.scene;

    std::vector<FileResult> files;
    for (const QString& path : answerPaths) {
        const AnswersFile af = loadAnswersFile(path, scene);
        if (!af.ok()) return fail(kBadInput, af.errors.join("\nrbw: "));
        FileResult fr;
        fr.file = path;
        fr.step = stepOption.value_or(af.step.value_or(0));
        // The world at the start of step k, and the trace of that step.
        World world(scene);
        for (long k = 0; k < fr.step; ++k) {
            const StepStatus st = world.step();
            if (!st.ok) return fail(kBlowUp, QString::fromStdString(st.message));
        }
        const WorldSnapshot before = world.snapshot();
        StepTrace trace;
        const StepStatus st = world.step(&trace);
        if (!st.ok) return fail(kBlowUp, QString::fromStdString(st.message));
        world.restore(before);
        for (size_t i = 0; i < af.answers.size(); ++i) {
            const std::string problem = answerProblem(trace, af.answers[i]);
            if (!problem.empty()) {
                return fail(kBadInput, QStringLiteral("%1: %2: %3").arg(path, af.paths[i], QString::fromStdString(problem)));
            }
        }
        fr.answers = af.answers;
        fr.results = checkAnswers(world, trace, af.answers, tolerance);
        files.push_back(std::move(fr));
    }

    bool allCorrect = true;
    QTextStream& out = cli::out();   // checked by main() (cli::finishStandardOutput)
    auto who = [&](const Answer& a) {
        QString s = a.contact >= 0 ? QStringLiteral("contact %1").arg(a.contact)
                                   : QString::fromStdString(scene.bodies[a.body].name);
        if (a.index >= 0) s += QStringLiteral(" #%1").arg(a.index);
        return s;
    };
    QJsonArray jsonFiles;
    if (format == "csv") out << "file,step,quantity,body,contact,index,verdict,expected,given,mistakes\n";
    for (const FileResult& f : files) {
        QJsonArray results;
        if (format == "text") out << QFileInfo(f.file).fileName() << ", step " << f.step << ":\n";
        for (size_t i = 0; i < f.answers.size(); ++i) {
            const Answer& a = f.answers[i];
            const AnswerResult& r = f.results[i];
            allCorrect = allCorrect && countsAsCorrect(r.verdict);
            QStringList mistakes;
            for (const char* m : r.mistakes) mistakes << QString::fromLatin1(m);
            QStringList possible;
            QJsonArray possibleJson;
            for (const PossibleMistake& p : r.possibleMistakes) {
                possible << QStringLiteral("%1 (%2)").arg(QString::fromLatin1(p.id), QString::fromStdString(p.reason));
                possibleJson.append(QJsonObject{{"id", QString::fromLatin1(p.id)}, {"reason", QString::fromStdString(p.reason)}});
            }
            if (format == "text") {
                const char* mark = countsAsCorrect(r.verdict) ? "  ok    " : r.verdict == Verdict::Wrong ? "  WRONG " : "  CARRIED ";
                out << mark << QString::fromStdString(a.quantity) << " (" << who(a) << "): " << verdictName(r.verdict);
                if (r.verdict != Verdict::Correct) {
                    out << "\n          expected " << numbers(r.expected) << ", given " << numbers(a.value);
                    if (!mistakes.isEmpty()) out << "\n          mistake: " << mistakes.join(", ");
                    if (!possible.isEmpty()) out << "\n          possible mistakes: " << possible.join("; ");
                    out << "\n          " << QString::fromStdString(r.explanation);
                }
                out << '\n';
            } else if (format == "csv") {
                out << csvField(f.file) << ',' << f.step << ',' << QString::fromStdString(a.quantity) << ','
                    << (a.contact >= 0 ? QString() : csvField(QString::fromStdString(scene.bodies[a.body].name))) << ','
                    << (a.contact >= 0 ? QString::number(a.contact) : QString()) << ','
                    << (a.index >= 0 ? QString::number(a.index) : QString()) << ',' << verdictName(r.verdict) << ','
                    << csvField(numbers(r.expected)) << ',' << csvField(numbers(a.value)) << ','
                    << csvField(mistakes.join(' ')) << '\n';
            } else {
                QJsonObject o{{"quantity", QString::fromStdString(a.quantity)},
                              {"verdict", verdictName(r.verdict)},
                              {"expected", jsonNumbers(r.expected)},
                              {"given", jsonNumbers(a.value)},
                              {"mistakes", QJsonArray::fromStringList(mistakes)},
                              {"possible_mistakes", possibleJson},
                              {"explanation", QString::fromStdString(r.explanation)}};
                if (a.contact >= 0) o.insert("contact", a.contact);
                else o.insert("body", QString::fromStdString(scene.bodies[a.body].name));
                if (a.index >= 0) o.insert("index", a.index);
                results.append(o);
            }
        }
        jsonFiles.append(QJsonObject{{"file", f.file},
                                     {"scene", scenePath},
                                     {"step", static_cast<qint64>(f.step)},
                                     {"tolerance", tolerance},
                                     {"results", results}});
    }
    if (format == "json") {
        out << QJsonDocument(jsonFiles.size() == 1 ? QJsonDocument(jsonFiles.first().toObject())
                                                   : QJsonDocument(jsonFiles))
                   .toJson(QJsonDocument::Indented);
    }
    out.flush();
    return allCorrect ? kAllCorrect : kSomeWrong;
}

} // namespace rbw
