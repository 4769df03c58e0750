#include "app/cli/check_command.h"

#include "app/cli/standard_output.h"
#include "app/exercise/answers_file.h"
#include "app/exercise/answers_input.h"
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
    QString error;        // a file that could not be checked: why (it still gets a row)
    int errorStatus = 0;  // kBadInput or kBlowUp
    QString stepHint;     // "steps count from 0: did you mean step 0?"
    std::vector<Answer> answers;
    std::vector<AnswerResult> results;
    std::vector<QString> hints;   // per answer: an input slip (slipHint), or empty
};

// The score of one file: how many answers got each verdict.
struct Score {
    int correct = 0, imprecise = 0, follows = 0, wrong = 0;
    QString text() const
    {
        return QStringLiteral("%1 correct, %2 imprecise, %3 follows, %4 wrong").arg(correct).arg(imprecise).arg(follows).arg(wrong);
    }
    QJsonObject json() const
    {
        return QJsonObject{{"correct", correct}, {"imprecise", imprecise}, {"follows", follows}, {"wrong", wrong}};
    }
};

Score scoreOf(const FileResult& f)
{
    Score s;
    for (const AnswerResult& r : f.results) {
        switch (r.verdict) {
        case Verdict::Correct: ++s.correct; break;
        case Verdict::Imprecise: ++s.imprecise; break;
        case Verdict::FollowsFromEarlier: ++s.follows; break;
        case Verdict::Wrong: ++s.wrong; break;
        }
    }
    return s;
}

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
    QByteArray sceneBytes;
    QString readError;
    if (!readInputFile(scenePath, &sceneBytes, &readError)) return fail(kBadInput, readError);
    const SceneLoadResult loaded = parseScene(sceneBytes, scenePath);
    if (!loaded.ok()) return fail(kBadInput, loaded.errors.join("\nrbw: "));
    const SceneDef& scene = *loaded.scene;

    // A marking sheet never loses a student: a file that cannot be read or checked gets
    // a row with its error, and the others go on (exit 2 at the end).
    std::vector<FileResult> files;
    std::vector<AnswersInput> inputs;
    std::vector<long> steps;
    for (const QString& path : answerPaths) {
        FileResult fr;
        fr.file = path;
        AnswersInput in;
        QByteArray bytes;
        if (!readInputFile(path, &bytes, &readError)) {
            in.errors << readError;
        } else {
            in = readAnswersInput(bytes, path, scene, stepOption);
        }
        fr.step = in.step;
        if (!in.ok()) {
            fr.error = in.errors.join(QLatin1Char('\n'));
            fr.errorStatus = kBadInput;
        } else {
            steps.push_back(in.step);
            if (in.step > 0) steps.push_back(in.step - 1);   // for the "steps count from 0" hint
        }
        files.push_back(std::move(fr));
        inputs.push_back(std::move(in));
    }
    // Each scene simulated once for the whole sheet, as far as the largest asked step.
    StepStates states(scene);
    QString blowUp;
    states.prepare(steps, &blowUp);
    for (size_t n = 0; n < files.size(); ++n) {
        FileResult& fr = files[n];
        const AnswersInput& in = inputs[n];
        if (fr.errorStatus != 0) continue;
        if (!states.has(fr.step)) {
            // Which file blew up: the scene's, as rbw run names it (issue 22).
            fr.error = QStringLiteral("%1: step %2 cannot be checked: %3: %4").arg(fr.file).arg(fr.step).arg(scenePath, blowUp);
            fr.errorStatus = kBlowUp;
            continue;
        }
        const QStringList problems = answersProblems(in, states.trace(fr.step), scene, fr.file);
        if (!problems.isEmpty()) {
            fr.error = problems.join(QLatin1Char('\n'));
            fr.errorStatus = kBadInput;
            continue;
        }
        fr.answers = in.file.answers;
        fr.results = checkAnswers(*states.worldBefore(fr.step), states.trace(fr.step), fr.answers, tolerance);
        for (size_t i = 0; i < fr.answers.size(); ++i) fr.hints.push_back(slipHint(fr.answers[i], fr.results[i], tolerance));
        // Not all right here, every answer right one step earlier: steps counted from 1.
        fr.stepHint = stepSlipHint(fr.answers, fr.results, fr.step, states, tolerance);
    }
    int errorStatus = 0;
    for (const FileResult& f : files) {
        if (f.errorStatus == 0) continue;
        fail(f.errorStatus, f.error);
        if (errorStatus != kBadInput) errorStatus = f.errorStatus;
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
    if (format == "csv") out << "file,step,quantity,body,contact,index,verdict,expected,given,mistakes,score,error\n";
    for (const FileResult& f : files) {
        QJsonArray results;
        if (f.errorStatus != 0) {
            // The row of a file that could not be checked: its error, first line in text.
            if (format == "text") {
                out << QFileInfo(f.file).fileName() << ": NOT CHECKED: " << f.error.section(QLatin1Char('\n'), 0, 0)
                    << '\n';
            } else if (format == "csv") {
                out << csvField(f.file) << ",,,,,,error,,,,," << csvField(f.error) << '\n';
            } else {
                jsonFiles.append(QJsonObject{{"file", f.file}, {"scene", scenePath}, {"error", f.error}});
            }
            continue;
        }
        const Score score = scoreOf(f);
        if (format == "text") out << QFileInfo(f.file).fileName() << ", step " << f.step << ":\n";
        if (format == "text" && !f.stepHint.isEmpty()) out << "  hint: " << f.stepHint << '\n';
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
                    if (!f.hints[i].isEmpty()) out << "\n          hint: " << f.hints[i];
                }
                out << '\n';
            } else if (format == "csv") {
                out << csvField(f.file) << ',' << f.step << ',' << QString::fromStdString(a.quantity) << ','
                    << (a.contact >= 0 ? QString() : csvField(QString::fromStdString(scene.bodies[a.body].name))) << ','
                    << (a.contact >= 0 ? QString::number(a.contact) : QString()) << ','
                    << (a.index >= 0 ? QString::number(a.index) : QString()) << ',' << verdictName(r.verdict) << ','
                    << csvField(numbers(r.expected)) << ',' << csvField(numbers(a.value)) << ','
                    << csvField(mistakes.join(' ')) << ',' << csvField(score.text()) << ",\n";
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
                if (!f.hints[i].isEmpty()) o.insert("hint", f.hints[i]);
                results.append(o);
            }
        }
        if (format == "text") out << "  score: " << score.text() << '\n';
        QJsonObject fileJson{{"file", f.file},
                             {"scene", scenePath},
                             {"step", static_cast<qint64>(f.step)},
                             {"tolerance", tolerance},
                             {"score", score.json()},
                             {"results", results}};
        if (!f.stepHint.isEmpty()) fileJson.insert("hint", f.stepHint);
        jsonFiles.append(fileJson);
    }
    if (format == "json") {
        out << QJsonDocument(jsonFiles.size() == 1 ? QJsonDocument(jsonFiles.first().toObject())
                                                   : QJsonDocument(jsonFiles))
                   .toJson(QJsonDocument::Indented);
    }
    out.flush();
    if (errorStatus != 0) return errorStatus;
    return allCorrect ? kAllCorrect : kSomeWrong;
}

} // namespace rbw
