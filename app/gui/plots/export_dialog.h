// The Export PNG… / Export CSV… of every plot: a save dialog that starts at
// ~/DEFAULT_NAME, then the plot's own writer (atomic, docs/architecture.md); a write
// that fails is reported in a message box naming the file and the reason.
#pragma once

#include <QString>

#include <functional>

class QWidget;

namespace rbw {

enum class PlotExportFormat { Png, Csv };

// write(path, &error) returns false and sets error when the file could not be written.
void exportPlotInteractively(QWidget* parent, PlotExportFormat format, const QString& defaultName,
                             const std::function<bool(const QString&, QString*)>& write);

} // namespace rbw
