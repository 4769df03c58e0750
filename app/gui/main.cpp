// rigid-workbook: the desktop app. Opens on the lesson named with --lesson ID, else on
// the lesson open when it was last closed, else (the first time) on lesson 1.
// --version and --help print and exit before any window exists, so they need no display.
#include "app/gui/main_window.h"
#include "app/gui/performance_probe.h"
#include "app/gui/view/scene_view.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QSettings>
#include <QSurfaceFormat>

#include <cstdio>

namespace {

void addOptions(QCommandLineParser& parser)
{
    parser.setApplicationDescription("Rigid Body Workbook: 3D rigid-body dynamics, step by step.");
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addOption({"lesson", "Open this lesson (folder name, e.g. 01-one-step).", "ID"});
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

    rbw::MainWindow window;
    window.show();
    const QString wanted = parser.isSet("lesson") ? parser.value("lesson")
                                                  : QSettings().value("lesson/last", "01-one-step").toString();
    if (!window.openLesson(wanted)) {
        window.openLesson("01-one-step");
    }
    if (parser.isSet("measure")) {
        auto* probe = new rbw::PerformanceProbe(&window, parser.value("measure").toDouble(), &window);
        probe->start();
    }
    return app.exec();
}
