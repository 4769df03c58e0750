// The docks around the 3D view and the panels in them, built and placed once: the
// lesson list and text on the left; the quantities of the step (table and formula),
// Check my numbers, the scene editor, the derivation and the accuracy studies on the
// right; the plots and the code view at the bottom. Each dock has an objectName, so
// QMainWindow::saveState can store the layout (AppSettings seals it).
#pragma once

#include "app/core/lesson_catalogue.h"

#include <QList>

class QDockWidget;
class QListWidget;
class QMainWindow;
class QTextBrowser;
class QTreeView;

namespace rbw {

class AccuracyPanel;
class BodyColourDelegate;
class BodyPlotPanel;
class CheckPanel;
class CodeView;
class DerivationView;
class FormulaPane;
class PlotPanel;
class QuantityPlotPanel;
class SceneEditor;
class TraceModel;

struct ShellDocks {
    QListWidget* lessonList = nullptr;
    QTextBrowser* lessonText = nullptr;
    QTreeView* traceView = nullptr;
    FormulaPane* formulaPane = nullptr;
    BodyColourDelegate* bodySwatches = nullptr;   // the table's body rows in the bodies' colours
    DerivationView* derivationView = nullptr;
    PlotPanel* plotPanel = nullptr;
    BodyPlotPanel* bodyPlotPanel = nullptr;
    CodeView* codeView = nullptr;
    QuantityPlotPanel* quantityPlots = nullptr;
    AccuracyPanel* accuracyPanel = nullptr;
    CheckPanel* checkPanel = nullptr;
    SceneEditor* sceneEditor = nullptr;

    QDockWidget* derivationDock = nullptr;
    QDockWidget* codeDock = nullptr;
    QDockWidget* quantityPlotDock = nullptr;
    QDockWidget* checkDock = nullptr;
    QDockWidget* editorDock = nullptr;
};

// Creates the panels and their docks in `window`: the list shows `lessons`, the
// table `traceModel`.
ShellDocks buildDocks(QMainWindow* window, const QList<Lesson>& lessons, TraceModel* traceModel);

// The first start (no saved layout): once the window has its size, the quantities
// table gets room for all its columns and the lessons theirs.
void fitDocksToWindow(QMainWindow* window);

} // namespace rbw
