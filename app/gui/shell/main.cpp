// rigid-workbook: the desktop app. Opens the scene file given as FILE.json, or the
// lesson (or scene file) named with --lesson ID|PATH; else the lesson open when it was
// last closed, else (the first time) lesson 1. A lesson or file that was asked for and
// cannot be opened is an error: its messages (file, JSON path, reason) go to standard
// error and the exit status is 2, before any window opens; only the remembered lesson
// falls back to lesson 1.
// --version and --help print and exit before any window exists, so they need no display.
#include "app/core/lesson_catalogue.h"
#include "app/core/step_run.h"
#include "app/scene/scene_loader.h"
#include "app/gui/shell/app_settings.h"
#include "app/gui/shell/main_window.h"
#include "app/gui/shell/performance_probe.h"
#include "app/gui/panels/view/scene_view.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QSurfaceFormat>

#include <cstdio>
#include <cstdlib>

namespace {

void addOptions(QCommandLineParser& parser)
{
    parser.setApplicationDescription("Rigid Body Workbook: 3D rigid-body dynamics, step by step.");
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addOption({"lesson",
                      "Open this lesson (its id, e.g. 01-one-step or 07-bounce/impulses) or this scene file (a path).",
                      "ID|PATH"});
    parser.addPositionalArgument("file", "A scene file to open (docs/scene-format.md).", "[FILE.json]");
    parser.addOption({"measure",
                      "Measure start-up, frame rate (playing for SECONDS) and memory; print JSON and quit.",
                      "SECONDS"});
}

// --version and --help, answered from argv alone: a QApplication would need a display.
// Qt's own options (-platform xcb, ...) are not known here, so a failed parse is not an
// error yet; QApplication removes them and parser.process() below reports the rest.
bool answeredWithoutWindow(int argc, char* argv[], int* exitCode)
{
    QStringList arguments;
    for (int i = 0; i < argc; ++i) arguments.append(QString::fromLocal8Bit(argv[i]));
    QCommandLineParser parser;
    addOptions(parser);
    parser.parse(arguments);
    if (parser.isSet("version")) {
        std::printf("rigid-workbook %s\n", PROJECT_VERSION_STRING);
        *exitCode = 0;
        return true;
    }
    if (parser.isSet("help")) {
        // Without a QCoreApplication, helpText() cannot name the program.
        QString help = parser.helpText();
        help.replace(QStringLiteral("<executable_name>"), QStringLiteral("rigid-workbook"));
        std::fputs(help.toLocal8Bit().constData(), stdout);
        *exitCode = 0;
        return true;
    }
    return false;
}

// Each line to standard error as "rigid-workbook: LINE"; the exit status for bad input.
int refuse(const QStringList& lines)
{
    for (const QString& line : lines) std::fprintf(stderr, "rigid-workbook: %s\n", line.toLocal8Bit().constData());
    return 2;
}

} // namespace

int main(int argc, char* argv[])
{
    int exitCode = 0;
    if (answeredWithoutWindow(argc, argv, &exitCode)) {
        return exitCode;
    }

    // QtWebEngine (the derivation) and the OpenGL view share contexts; both must be
    // set before the QApplication exists.
    QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QSurfaceFormat::setDefaultFormat(rbw::SceneView::requestedFormat());
    QApplication app(argc, argv);
    QApplication::setApplicationName("Rigid Body Workbook");
    QApplication::setOrganizationName("rigid-workbook");
    QApplication::setApplicationVersion(QStringLiteral(PROJECT_VERSION_STRING));
    // The installed RBW_APP_ID.desktop (packaging/): Wayland's app id, so the desktop
    // shows the window with that file's name and icon.
    QGuiApplication::setDesktopFileName(QStringLiteral(RBW_APP_ID));

    QCommandLineParser parser;
    addOptions(parser);
    parser.process(app);

    // What was asked for is checked before a window exists: a wrong id or a broken file
    // is reported and the app does not start on something else.
    const QStringList files = parser.positionalArguments();
    if (files.size() > 1) return refuse({QStringLiteral("give at most one scene file, got %1").arg(files.size())});
    if (files.size() == 1 && parser.isSet("lesson")) {
        return refuse({QStringLiteral("give either --lesson or a scene file, not both")});
    }
    rbw::LessonArgument asked;
    if (parser.isSet("lesson") || !files.isEmpty()) {
        const QList<rbw::Lesson> lessons = rbw::lessonCatalogue();
        asked = rbw::resolveLessonArgument(files.isEmpty() ? parser.value("lesson") : files.first(), lessons);
        if (!asked.ok()) return refuse({asked.error});
        QString scenePath = asked.file;
        for (const rbw::Lesson& l : lessons) {
            if (l.id == asked.lessonId) scenePath = l.scenePath;
        }
        const rbw::SceneLoadResult loaded = rbw::loadSceneFile(scenePath);
        if (!loaded.ok()) return refuse(loaded.errors);
    }

    rbw::MainWindow window;
    window.show();
    QString error;
    if (!asked.lessonId.isEmpty() && !window.openLesson(asked.lessonId)) {
        return refuse({QStringLiteral("lesson %1 cannot be loaded").arg(asked.lessonId)});   // its scene is broken
    }
    if (!asked.file.isEmpty() && !window.openSceneFile(asked.file, &error)) return refuse(error.split('\n'));
    if (asked.lessonId.isEmpty() && asked.file.isEmpty() &&
        !window.openLesson(rbw::AppSettings::lastLesson())) {
        window.openLesson("01-one-step");
    }
    if (parser.isSet("measure")) {
        auto* probe = new rbw::PerformanceProbe(&window, parser.value("measure").toDouble(), &window);
        probe->start();
    }
    const int status = app.exec();
    if (rbw::StepRun::running() > 0) {
        // Quit while a step was being computed (cancelled at close): its thread cannot be
        // stopped inside the step, so leave without waiting for it (Quit always quits).
        // The settings are written already (each QSettings syncs when it goes).
        std::fflush(stdout);
        std::fflush(stderr);
        std::_Exit(status);
    }
    return status;
}
