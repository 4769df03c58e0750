#include "app/cli/exercise_command.h"

#include "app/cli/output_options.h"
#include "app/cli/standard_output.h"
#include "app/output/atomic_file.h"
#include "app/exercise/exercise.h"

#include <QFileInfo>
#include <QTextStream>


namespace rbw {

namespace {

constexpr int kExitOk = 0;
constexpr int kExitBadInput = 2;

int fail(const QStringList& messages)
{
    QTextStream err(stderr);
    for (const QString& m : messages) err << "rbw: " << m << '\n';
    err.flush();
    return kExitBadInput;
}

} // namespace

int runExerciseCommand(const QCommandLineParser& parser, const QString& lesson)
{
    if (!parser.isSet("seed")) return fail({"exercise: --seed N is required (a whole number from 0 to 18446744073709551615)"});
    bool ok = false;
    const QString seedText = parser.value("seed");
    const quint64 seed = seedText.toULongLong(&ok, 10);
    if (!ok || seedText.startsWith('+') || seedText.trimmed() != seedText) {
        return fail({"--seed: must be a whole number from 0 to 18446744073709551615, got \"" + seedText + "\""});
    }
    const ExerciseLoadResult loaded = loadExercise(lesson);
    if (!loaded.ok()) return fail(loaded.errors);
    const ExerciseSpec& spec = *loaded.spec;
    // Before anything is drawn or written: each output its own file, none of them one
    // of the lesson's files (--output exercise.json would destroy the lesson).
    static const char* const kOutputs[] = {"output", "worksheet", "answer-key", "answers-key"};
    std::vector<cli::NamedFile> outputs;
    for (const char* option : kOutputs) {
        if (parser.isSet(option)) outputs.push_back({QStringLiteral("--") + QLatin1String(option), parser.value(option)});
    }
    std::vector<cli::NamedFile> lessonOwn = cli::lessonFiles(QFileInfo(spec.file).path());
    lessonOwn.push_back({QStringLiteral("the lesson's exercise.json"), spec.file});
    lessonOwn.push_back({QStringLiteral("the lesson's scene"), spec.scenePath});
    if (const QString conflict = cli::outputConflict(outputs, lessonOwn); !conflict.isEmpty()) return fail({conflict});
    const GeneratedExercise g = generateExercise(spec, seed);
    if (!g.ok()) return fail(g.errors);

    QStringList errors;
    auto write = [&](const char* option, const QByteArray& bytes) {
        if (!parser.isSet(option)) return;
        // The file appears complete or not at all.
        QString e;
        if (!writeFileAtomically(parser.value(option), bytes, &e)) {
            errors << e.replace(QLatin1String(": cannot write:"), QStringLiteral(": --%1: cannot write:").arg(option));
        }
    };
    write("output", g.sceneJson);
    write("worksheet", exerciseWorksheetHtml(spec, g, false).toUtf8());
    write("answer-key", exerciseWorksheetHtml(spec, g, true).toUtf8());
    write("answers-key", exerciseAnswersJson(g));
    if (!errors.isEmpty()) return fail(errors);
    // Checked by main() (cli::finishStandardOutput).
    if (!parser.isSet("output")) cli::standardOutput().write(g.sceneJson);
    return kExitOk;
}

} // namespace rbw
