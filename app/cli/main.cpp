// rbw: the headless command line of Rigid Body Workbook. It runs a scene and prints
// the state, the diagnostics and the step trace as JSON (or CSV), for scripts,
// graders and the tests. Exit status: 0 success, 2 bad input, 3 blow-up.
#include "app/cli/check_command.h"
#include "app/cli/command_options.h"
#include "app/cli/contact_study_command.h"
#include "app/cli/diagnose_command.h"
#include "app/cli/probes_command.h"
#include "app/cli/exercise_command.h"
#include "app/cli/output_options.h"
#include "app/cli/standard_output.h"
#include "app/output/atomic_file.h"
#include "app/output/csv_output.h"
#include "app/output/json_output.h"
#include "app/core/lesson_catalogue.h"
#include "app/scene/scene_loader.h"
#include "app/output/study_csv.h"
#include "physics/engine/integrator_registry.h"
#include "physics/workbook/lab/study.h"
#include "physics/engine/quantity_catalogue.h"
#include "physics/engine/world.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

#include <cmath>
#include <cstdio>

namespace {

constexpr int kExitOk = 0;
constexpr int kExitBadInput = 2;
constexpr int kExitBlowUp = 3;

using rbw::cli::out;

QTextStream& err()
{
    static QTextStream s(stderr);
    return s;
}

int badInput(const QString& message)
{
    err() << "rbw: " << message << '\n';
    err().flush();
    return kExitBadInput;
}

enum class TraceMode { None, Last, All };

int runScene(const QCommandLineParser& parser, const QString& sceneFile)
{
    rbw::SceneLoadResult loaded = rbw::loadSceneFile(sceneFile);
    if (!loaded.ok()) {
        for (const QString& e : loaded.errors) err() << "rbw: " << e << '\n';
        err().flush();
        return kExitBadInput;
    }
    rbw::SceneDef scene = std::move(*loaded.scene);

    // Command-line overrides, validated like the file's own values.
    if (parser.isSet("steps")) {
        bool ok = false;
        const long steps = parser.value("steps").toLong(&ok);
        if (!ok || steps < 0) return badInput("--steps: must be a whole number >= 0, got \"" + parser.value("steps") + "\"");
        scene.steps = steps;
    }
    if (parser.isSet("dt")) {
        bool ok = false;
        const double dt = parser.value("dt").toDouble(&ok);
        if (!ok || !std::isfinite(dt) || dt <= 0.0) return badInput("--dt: must be a finite number > 0, got \"" + parser.value("dt") + "\"");
        scene.dt = dt;
    }
    if (parser.isSet("integrator")) {
        const QString name = parser.value("integrator");
        if (!rbw::makeIntegrator(name.toStdString())) {
            return badInput("--integrator: unknown integrator \"" + name + "\"; known: " +
                            QString::fromStdString(rbw::integratorNames()));
        }
        scene.integrator = name.toStdString();
    }
    TraceMode traceMode = TraceMode::Last;
    const QString traceArg = parser.value("trace");
    if (traceArg == "none") traceMode = TraceMode::None;
    else if (traceArg == "all") traceMode = TraceMode::All;
    else if (traceArg != "last") return badInput("--trace: must be none, last or all, got \"" + traceArg + "\"");
    const QString format = parser.value("format");
    if (format != "json" && format != "csv") return badInput("--format: must be json or csv, got \"" + format + "\"");
    if (format == "csv") traceMode = TraceMode::None;   // CSV prints no trace: do not record one
    // The overrides obey the scene's own rules (the steps limit, an end time that does
    // not overflow): validate() again, naming the option.
    for (const rbw::SceneIssue& issue : rbw::validate(scene)) {
        const QString field = QString::fromStdString(issue.path);
        if (field == "steps" && parser.isSet("steps")) return badInput("--steps: " + QString::fromStdString(issue.reason));
        if (field == "dt" && parser.isSet("dt")) return badInput("--dt: " + QString::fromStdString(issue.reason));
        return badInput(QString::fromStdString(issue.path + ": " + issue.reason));
    }

    rbw::World world(std::move(scene));
    const long steps = world.scene().steps;
    // A blow-up: the sentence on stderr; with JSON, the document ends with the blow-up
    // (JsonRunWriter::finishBlowUp) so it stays one valid document.
    auto blewUp = [&sceneFile](const rbw::StepStatus& status) {
        out().flush();
        err() << "rbw: " << sceneFile << ": " << QString::fromStdString(status.message) << '\n';
        err().flush();
        return kExitBlowUp;
    };

    if (format == "csv") {
        // Nothing is printed before the initial state is checked; each row after its check.
        rbw::Diagnostics d = world.diagnostics();
        if (const rbw::StepStatus initial = world.checkOutputs(d); !initial.ok) return blewUp(initial);
        rbw::CsvWriter csv(out());
        csv.writeHeader(world.scene());
        csv.writeRow(world, d);
        for (long k = 0; k < steps; ++k) {
            rbw::StepStatus status = world.step();
            if (status.ok) {
                d = world.diagnostics();
                status = world.checkOutputs(d);
            }
            if (!status.ok) return blewUp(status);
            csv.writeRow(world, d);
            if (rbw::cli::standardOutput().failed()) return kExitBadInput;   // main() reports it
        }
        return kExitOk;
    }

    // JSON, streamed: the header, then each traced step as it is taken (--trace all:
    // memory stays flat with the number of steps), then the result or the blow-up.
    out().flush();
    rbw::cli::StandardOutput& stdoutFile = rbw::cli::standardOutput();
    rbw::JsonRunWriter json(stdoutFile, world, sceneFile);
    json.begin();
    auto jsonBlowUp = [&](const rbw::StepStatus& status) {
        json.finishBlowUp(status);
        return blewUp(status);
    };
    if (const rbw::StepStatus initial = world.checkOutputs(); !initial.ok) return jsonBlowUp(initial);
    rbw::StepTrace current;   // reused from step to step: its capacity is kept
    for (long k = 0; k < steps; ++k) {
        // A traced step checks every number it records; an untraced one only the state,
        // so the rest of what the result prints (diagnostics, P, probes) is checked here.
        rbw::StepStatus status = world.step(traceMode == TraceMode::None ? nullptr : &current);
        if (status.ok && traceMode == TraceMode::None) status = world.checkOutputs();
        if (!status.ok) return jsonBlowUp(status);
        if (traceMode == TraceMode::All) json.addTrace(current);
        if (stdoutFile.failed()) return kExitBadInput;   // main() reports it
    }
    if (traceMode == TraceMode::Last && steps > 0) json.addTrace(current);
    json.finish();
    return kExitOk;
}

// rbw study SCENE [--integrators a,b] [--dt h1,h2] [--t-end T] [--output FILE]:
// every integrator at every h against the scene's exact answer, as CSV
// (physics/workbook/lab/study.h, app/output/study_csv.h). Progress goes to stderr.
int runStudyCommand(const QCommandLineParser& parser, const QString& sceneFile)
{
    rbw::SceneLoadResult loaded = rbw::loadSceneFile(sceneFile);
    if (!loaded.ok()) {
        for (const QString& e : loaded.errors) err() << "rbw: " << e << '\n';
        err().flush();
        return kExitBadInput;
    }
    const rbw::SceneDef scene = std::move(*loaded.scene);
    if (parser.isSet("output")) {
        const QString conflict = rbw::cli::outputConflict({{"--output", parser.value("output")}},
                                                          {{"the scene file (the input)", sceneFile}});
        if (!conflict.isEmpty()) return badInput(conflict);
    }
    auto studyError = [&sceneFile](const QString& field, const QString& reason) {
        return badInput(sceneFile + ": " + field + ": " + reason);
    };

    rbw::lab::StudyConfig config;
    if (parser.isSet("integrators")) {
        for (const QString& name : parser.value("integrators").split(',')) {
            config.integrators.push_back(name.trimmed().toStdString());
        }
    }
    if (parser.isSet("dt")) {
        for (const QString& text : parser.value("dt").split(',')) {
            bool ok = false;
            const double dt = text.trimmed().toDouble(&ok);
            if (!ok) return studyError("dt", "must be a finite number > 0, got \"" + text.trimmed() + "\"");
            config.dts.push_back(dt);
        }
    }
    if (parser.isSet("t-end")) {
        bool ok = false;
        const double T = parser.value("t-end").toDouble(&ok);
        if (!ok) return studyError("t_end", "must be a finite number > 0, got \"" + parser.value("t-end") + "\"");
        config.tEnd = T;
    }
    const std::vector<rbw::SceneIssue> issues = rbw::lab::validateStudy(scene, config);
    if (!issues.empty()) {
        for (const rbw::SceneIssue& i : issues) {
            err() << "rbw: " << sceneFile << ": " << QString::fromStdString(i.path) << ": "
                  << QString::fromStdString(i.reason) << '\n';
        }
        err().flush();
        return kExitBadInput;
    }

    const rbw::lab::StudyResult result = rbw::lab::runStudy(scene, config, [](int done, int total) {
        err() << "rbw: study: " << done << "/" << total << " runs\n";
        err().flush();
    });
    err() << "rbw: study: exact reference: " << QString::fromStdString(result.reference) << ", t_end = "
          << result.tEnd << " s\n";
    err().flush();
    const QString csv = rbw::studyToCsv(result);
    if (!parser.isSet("output")) {
        out() << csv;
        return kExitOk;
    }
    // The file appears complete or not at all (app/output/atomic_file.h).
    QString error;
    if (!rbw::writeFileAtomically(parser.value("output"), csv.toUtf8(), &error)) {
        return badInput(error.replace(QLatin1String(": cannot write:"), QLatin1String(": --output: cannot write:")));
    }
    return kExitOk;
}

int listLessons()
{
    const QList<rbw::Lesson> lessons = rbw::lessonCatalogue();
    if (lessons.isEmpty()) {
        return badInput("no lessons found in " + rbw::lessonsDirectory());
    }
    for (const rbw::Lesson& l : lessons) {
        out() << l.id << "  " << l.title << '\n';
        if (!l.description.isEmpty()) out() << "    " << l.description << '\n';
        out() << "    " << QDir::current().relativeFilePath(l.scenePath) << '\n';
    }
    out().flush();
    return kExitOk;
}

int listIntegrators()
{
    for (const rbw::IntegratorInfo& info : rbw::integratorCatalogue()) {
        out() << info.name << "  " << info.summary << '\n';
    }
    out().flush();
    return kExitOk;
}

// rbw quantities [--format json|csv]: the quantity catalogue, one row per formula.
int listQuantities(const QCommandLineParser& parser)
{
    const QString format = parser.isSet("format") ? parser.value("format") : QStringLiteral("text");
    if (format == "json") {
        QJsonArray rows;
        for (const rbw::QuantityInfo& q : rbw::quantityCatalogue()) {
            rows.append(QJsonObject{
                {"key", q.key},
                {"id", q.id},
                {"stage", rbw::stageName(q.stage)},
                {"index_kind", rbw::indexKindName(q.indexKind)},
                {"symbol", q.symbol},
                {"text", QString::fromUtf8(q.text)},
                {"formula", q.formula},
                {"frame", rbw::frameName(q.frame)},
                {"unit", QString::fromUtf8(q.unit)},
            });
        }
        out() << QJsonDocument(rows).toJson(QJsonDocument::Indented);
    } else if (format == "csv") {
        out() << "key,id,stage,index_kind,frame,unit,formula\n";
        for (const rbw::QuantityInfo& q : rbw::quantityCatalogue()) {
            QString formula = QString::fromUtf8(q.formula);
            formula.replace('"', QStringLiteral("\"\""));
            out() << q.key << ',' << q.id << ',' << rbw::stageName(q.stage) << ',' << rbw::indexKindName(q.indexKind)
                  << ',' << rbw::frameName(q.frame) << ',' << QString::fromUtf8(q.unit) << ",\"" << formula << "\"\n";
        }
    } else if (format == "text") {
        for (const rbw::QuantityInfo& q : rbw::quantityCatalogue()) {
            const QString where = QString::fromLatin1(rbw::stageName(q.stage)) +
                                  (q.indexKind != rbw::IndexKind::None ? QStringLiteral(", per ") +
                                                                             QLatin1String(rbw::indexKindName(q.indexKind))
                                                                       : QString());
            out() << QString::fromLatin1(q.id).leftJustified(28) << ' ' << QString::fromUtf8(q.text).leftJustified(12)
                  << ' ' << QString::fromUtf8(q.unit).leftJustified(10) << ' ' << where;
            if (std::string_view(q.key) != q.id) out() << "  (" << q.key << ')';
            out() << '\n';
        }
    } else {
        return badInput("--format: must be json, csv or text for quantities, got \"" + format + "\"");
    }
    out().flush();
    return kExitOk;
}

int dispatch(QCommandLineParser& parser);

} // namespace

// Every command's standard output is flushed and checked at the end (issue 22): a write
// error is exit status 2 with "cannot write to standard output: REASON".
int main(int argc, char* argv[])
{
    QCoreApplication app(argc, argv);
    QCommandLineParser parser;
    const int status = dispatch(parser);
    return rbw::cli::finishStandardOutput(status);
}

namespace {

int dispatch(QCommandLineParser& parser)
{
    QCoreApplication::setApplicationName("rbw");
    QCoreApplication::setApplicationVersion(QStringLiteral(PROJECT_VERSION_STRING));

    parser.setApplicationDescription(
        "Rigid Body Workbook, headless.\n\n"
        "Commands:\n"
        "  run SCENE.json    run a scene and print its state, diagnostics and step trace\n"
        "  lessons           list the lessons with their one-line descriptions\n"
        "  integrators       list the integrators a scene can choose\n"
        "  quantities        list every traced quantity: id, symbol, unit, stage (--format json|csv)\n"
        "  check SCENE.json ANSWERS.json [MORE.json ...]\n"
        "                    check a student's numbers for one step (--step K, --tolerance REL,\n"
        "                    --format text|json|csv); exit 0 all correct, 1 some not\n"
        "  study SCENE.json  every integrator at every dt against the scene's exact answer (CSV)\n"
        "  contact-study PROBLEM\n"
        "                    resting-box, tower or rain in both contact models: overlap, drift,\n"
        "                    energy gained against ns/step (CSV); --iterations, --dt, --t-end, --boxes\n"
        "  exercise LESSON --seed N\n"
        "                    the lesson's scene with new numbers (docs/exercises.md); --output FILE,\n"
        "                    --worksheet F.html, --answer-key F.html, --answers-key F.json\n"
        "  diagnose --simulator \"CMD\" | --trajectory FILE.csv | DIR\n"
        "                    run your own simulator through the probes (or read its offline answers)\n"
        "                    and name its mistake (docs/simulator-protocol.md); --probes motion|collision|all,\n"
        "                    --timeout S, --format text|json|csv (csv: one row per program and probe,\n"
        "                    for a tutor's several --simulator); exit 0 matches, 1 not\n"
        "  probes --output DIR\n"
        "                    write each probe as protocol commands, DIR/<probe>.commands, for the\n"
        "                    offline mode of diagnose; --probes motion|collision|all\n\n"
        "Exit status: 0 success, 2 bad input (the message names the file, field and reason),\n"
        "3 the simulation blew up (the message names the step, body and quantity).\n\n"
        "Example:\n"
        "  rbw run lessons/01-one-step/scene.json\n"
        "  rbw run lessons/01-one-step/scene.json --steps 100 --dt 0.01 --format csv\n"
        "  rbw study lessons/10-accuracy-lab/scene.json --integrators explicit-euler,rk4 --dt 0.1,0.01");
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument("command", "run, study, check, exercise, contact-study, diagnose, probes, lessons, integrators or quantities");
    parser.addPositionalArgument("scene", "the scene file, for run and study", "[SCENE.json]");
    parser.addOptions({
        {"steps", "Number of steps to take (default: the scene's \"steps\").", "N"},
        {"dt", "Time step h in seconds (default: the scene's \"dt\"). For study: a comma-separated list "
               "(default: 0.1,0.05,0.02,0.01,0.005,0.002,0.001).", "H"},
        {"integrator", "Integrator name (see `rbw integrators`).", "NAME"},
        {"trace", "Which step traces to print: none, last or all.", "none|last|all", "last"},
        {"format", "Output format: json (one document) or csv (one row per step).", "json|csv", "json"},
        {"integrators", "For study: comma-separated integrator names (default: all).", "A,B,..."},
        {"step", "For check: the step K whose numbers are checked (default: the answers file's \"step\", else 0).", "K"},
        {"tolerance", "For check: relative tolerance of a correct answer (default 1e-3: 4 significant figures).", "REL"},
        {"t-end", "For study and contact-study: end time T in seconds, the same for every run (default: steps x dt of the scene).", "T"},
        {"output", "For study, contact-study and exercise: write the CSV or the scene to FILE instead of standard output; "
                   "for probes: the folder DIR of the probe files.", "FILE"},
        {"seed", "For exercise: the seed N of the new numbers (the same seed, the same scene).", "N"},
        {"iterations", "For contact-study: the manifold model's solver iterations (default: 1,2,4,8,16).", "N1,N2,..."},
        {"boxes", "For contact-study rain: the number of boxes (default 100).", "N"},
        {"worksheet", "For exercise: write the HTML worksheet (setup and an empty answer table) to FILE.", "FILE"},
        {"answer-key", "For exercise: write the worksheet filled with the workbook's numbers to FILE.", "FILE"},
        {"answers-key", "For exercise: write the key as an answers file (rbw check accepts it) to FILE.", "FILE"},
        {"simulator", "For diagnose: the command that starts your simulator (docs/simulator-protocol.md).", "CMD"},
        {"timeout", "For diagnose: seconds a probe may take (default 10).", "S"},
        {"trajectory", "For diagnose: your simulator's answers to the probes as CSV (docs/simulator-protocol.md).", "FILE.csv"},
        {"probes", "For diagnose and probes: the probe group, motion, collision or all.", "GROUP"},
    });
    if (!parser.parse(QCoreApplication::arguments())) {
        return badInput(parser.errorText() + " (see rbw --help)");
    }
    // Help and version through the checked standard output (not QCommandLineParser's
    // showHelp/showVersion, which write with stdio and exit without checking).
    if (parser.isSet("help")) {
        out() << parser.helpText();
        return kExitOk;
    }
    if (parser.isSet("version")) {
        out() << QCoreApplication::applicationName() << ' ' << QCoreApplication::applicationVersion() << '\n';
        return kExitOk;
    }
    const QStringList args = parser.positionalArguments();
    if (args.isEmpty()) {
        return badInput("no command given (see rbw --help)");
    }
    const QString command = args.first();
    if (const QString problem = rbw::cli::optionProblem(parser, command); !problem.isEmpty()) return badInput(problem);
    if (command == "run") {
        if (args.size() != 2) return badInput("run takes exactly one scene file (see rbw --help)");
        return runScene(parser, args[1]);
    }
    if (command == "study") {
        if (args.size() != 2) return badInput("study takes exactly one scene file (see rbw --help)");
        return runStudyCommand(parser, args[1]);
    }
    if (command == "lessons" && args.size() == 1) return listLessons();
    if (command == "integrators" && args.size() == 1) return listIntegrators();
    if (command == "quantities" && args.size() == 1) return listQuantities(parser);
    if (command == "check") {
        if (args.size() < 3) return badInput("check takes a scene file and at least one answers file (see rbw --help)");
        return rbw::runCheckCommand(parser, args[1], args.mid(2));
    }
    if (command == "contact-study") {
        if (args.size() != 2) return badInput("contact-study takes exactly one problem: resting-box, tower or rain");
        return rbw::runContactStudyCommand(parser, args[1]);
    }
    if (command == "exercise") {
        if (args.size() != 2) return badInput("exercise takes exactly one lesson, an id or a folder (see rbw --help)");
        return rbw::runExerciseCommand(parser, args[1]);
    }
    if (command == "diagnose") return rbw::runDiagnoseCommand(parser, args.mid(1));
    if (command == "probes") return rbw::runProbesCommand(parser, args.mid(1));
    return badInput("unknown command \"" + args.join(' ') + "\" (see rbw --help)");
}

} // namespace
