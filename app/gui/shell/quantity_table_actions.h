// What the quantities table's rows offer (its context menu and Edit menu): copy the
// selected rows as text or LaTeX, show the physics statement that computed a row in
// the code view, and plot a row's quantity over the recorded history.
#pragma once

#include <QObject>

class QDockWidget;
class QModelIndex;
class QStatusBar;
class QTreeView;

namespace rbw {

class CodeView;
class QuantityPlot;
class QuantityPlotPanel;
class Session;
class TraceModel;

class QuantityTableActions : public QObject {
    Q_OBJECT
public:
    struct Parts {
        QTreeView* table;
        TraceModel* model;
        CodeView* codeView;
        QDockWidget* codeDock;
        QuantityPlotPanel* plots;
        QDockWidget* plotDock;
        QStatusBar* status;
    };
    QuantityTableActions(const Parts& parts, Session* session, QObject* parent);

    void copySelection(bool asLatex);
    // False (with a note in the status bar) for a group row.
    bool showCodeOfCurrentRow();
    bool plotRowOverTime(const QModelIndex& row, bool norm);

private:
    static constexpr int kChartFitRounds = 8;
    static constexpr int kChartFitDelayMs = 60;   // the window lays out the resized docks meanwhile
    // `asked`: the dock area's height asked for in the round before (0: none yet).
    static void growForChart(QDockWidget* dock, QuantityPlot* plot, int rounds, int delayMs, int asked);

    Parts p_;
    Session* session_;
};

} // namespace rbw
