// rigid-workbook: the desktop app. Opens on the lesson named with --lesson ID, else on
// the lesson open when it was last closed, else (the first time) on lesson 1.
#include "app/gui/main_window.h"
#include "app/gui/performance_probe.h"
#include "app/gui/view/scene_view.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QSettings>
#include <QSurfaceFormat>

int main(int argc, char* argv[])
{
    // QtWebEngine (the derivation) and the OpenGL view share contexts; both must be
    // set before the QApplication exists.
    QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QSurfaceFormat::setDefaultFormat(rbw::SceneView::requestedFormat());
    QApplication app(argc, argv);
    QApplication::setApplicationName("Rigid Body Workbook");
    QApplication::setOrganizationName("rigid-workbook");

    QCommandLineParser parser;
    parser.setApplicationDescription("Rigid Body Workbook: 3D rigid-body dynamics, step by step.");
    parser.addHelpOption();
    parser.addOption({"lesson", "Open this lesson (folder name, e.g. 01-one-step).", "ID"});
    parser.addOption({"measure",
                      "Measure start-up, frame rate (playing for SECONDS) and memory; print JSON and quit.",
                      "SECONDS"});
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
