// rigid-workbook: the desktop app. Opens on lesson 1, or on the lesson named with
// --lesson ID.
#include "app/gui/main_window.h"

#include <QApplication>
#include <QCommandLineParser>

int main(int argc, char* argv[])
{
    QApplication app(argc, argv);
    QApplication::setApplicationName("Rigid Body Workbook");
    QApplication::setOrganizationName("rigid-workbook");

    QCommandLineParser parser;
    parser.setApplicationDescription("Rigid Body Workbook: 3D rigid-body dynamics, step by step.");
    parser.addHelpOption();
    parser.addOption({"lesson", "Open this lesson (folder name, e.g. 01-one-step).", "ID", "01-one-step"});
    parser.process(app);

    rbw::MainWindow window;
    window.show();
    if (!window.openLesson(parser.value("lesson"))) {
        window.openLesson("01-one-step");
    }
    return app.exec();
}
