// The Export PNG… / Export CSV… of the plots: a save dialog that starts at
// ~/DEFAULT_NAME, then the plot's own writer (atomic, docs/architecture.md); a write
// that fails is reported in a message box naming the file and the reason. And the PNG
// writer the energy plot and Plot over time share.
#pragma once

#include <QString>

#include <functional>

class QChart;
class QWidget;

namespace rbw {

enum class PlotExportFormat { Png, Csv };

// write(path, &error) returns false and sets error when the file could not be written.
void exportPlotInteractively(QWidget* parent, PlotExportFormat format, const QString& defaultName,
                             const std::function<bool(const QString&, QString*)>& write);

// The chart as a PNG at twice its size on white, written atomically. A chart never laid
// out on screen (`onScreen` false: a closed dock) is given 800 x 500 first; the posted
// layout is done first, so the axes are as they are now. False, with the file and the
// reason in `error`, when the chart has no size or the file cannot be written.
// `title` (what the plot shows, "Energy", "R₂₂ (racket)") is drawn above the plot in
// the image, so a PNG on its own says what it is; the chart on screen keeps its own.
bool writeChartPng(QChart* chart, bool onScreen, const QString& path, QString* error, const QString& title = {});

} // namespace rbw
