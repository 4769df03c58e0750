#include "app/gui/panels/plots/export_dialog.h"

#include "app/output/atomic_file.h"

#include <QBuffer>
#include <QChart>
#include <QCoreApplication>
#include <QDir>
#include <QFileDialog>
#include <QGraphicsLayout>
#include <QGraphicsScene>
#include <QImage>
#include <QMessageBox>
#include <QObject>
#include <QPainter>

#include <algorithm>

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

bool writeChartPng(QChart* chart, bool onScreen, const QString& path, QString* error, const QString& title)
{
    // The title for the image only: set now, the chart's own back on return.
    struct TitleForImage {
        QChart* chart;
        QString saved;
        QFont savedFont;
        ~TitleForImage()
        {
            chart->setTitle(saved);
            chart->setTitleFont(savedFont);
        }
    } restore{chart, chart->title(), chart->titleFont()};
    if (!title.isEmpty()) {
        QFont bold = chart->titleFont();
        bold.setBold(true);
        bold.setPointSizeF(std::max(bold.pointSizeF(), 11.0));
        chart->setTitleFont(bold);
        chart->setTitle(title);
    }
    constexpr qreal kPixelRatio = 2.0;
    auto fail = [error](const QString& text) {
        if (error != nullptr) *error = text;
        return false;
    };
    if (!onScreen) chart->resize(QSizeF(800, 500));
    // Axis ticks and labels are laid out on a posted LayoutRequest: do it now, so
    // the image shows the axes as they are, not as they were one event ago.
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    chart->layout()->activate();
    const QSize logical = chart->size().toSize();
    if (logical.width() < 10 || logical.height() < 10) {
        return fail(QStringLiteral("cannot export %1: the chart has no size yet").arg(path));
    }
    QImage image(logical * kPixelRatio, QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(kPixelRatio);
    image.fill(Qt::white);
    {
        QPainter painter(&image);
        painter.setRenderHint(QPainter::Antialiasing);
        painter.setRenderHint(QPainter::TextAntialiasing);
        const QRectF source = chart->mapRectToScene(QRectF(QPointF(0, 0), chart->size()));
        chart->scene()->render(&painter, QRectF(QPointF(0, 0), QSizeF(logical)), source);
    }
    QByteArray bytes;
    {
        QBuffer buffer(&bytes);
        buffer.open(QIODevice::WriteOnly);
        if (!image.save(&buffer, "PNG")) return fail(QStringLiteral("cannot encode %1 as PNG").arg(path));
    }
    return writeFileAtomically(path, bytes, error);
}

} // namespace rbw
