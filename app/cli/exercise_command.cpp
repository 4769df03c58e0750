#include "app/cli/exercise_command.h"

#include "app/output/atomic_file.h"
#include "app/exercise/exercise.h"

#include <QFile>
#include <QTextStream>

#include <cstdio>

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
    if (!parser.isSet("output")) {
        QFile out;
        if (!out.open(stdout, QIODevice::WriteOnly) || out.write(g.sceneJson) != g.sceneJson.size()) {
            return fail({"exercise: cannot write to standard output"});
        }
        out.flush();
    }
    return kExitOk;
}

} // namespace rbw
