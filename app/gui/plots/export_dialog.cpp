#include "app/gui/plots/export_dialog.h"

#include <QDir>
#include <QFileDialog>
#include <QMessageBox>
#include <QObject>

namespace rbw {

void exportPlotInteractively(QWidget* parent, PlotExportFormat format, const QString& defaultName,
                             const std::function<bool(const QString&, QString*)>& write)
{
    const bool png = format == PlotExportFormat::Png;
    const QString path = QFileDialog::getSaveFileName(
        parent, png ? QObject::tr("Export plot as PNG") : QObject::tr("Export plot data as CSV"),
        QDir::home().filePath(defaultName), png ? QObject::tr("PNG images (*.png)") : QObject::tr("CSV files (*.csv)"));
    if (path.isEmpty()) return;
    QString error;
    if (!write(path, &error)) {
        QMessageBox::warning(parent, png ? QObject::tr("Export PNG") : QObject::tr("Export CSV"), error);
    }
}

} // namespace rbw
