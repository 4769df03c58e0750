#include "app/gui/shell/worksheet_export.h"

#include "app/output/atomic_file.h"
#include "app/exercise/exercise.h"

#include <QBuffer>
#include <QDir>
#include <QFileInfo>
#include <QPageLayout>
#include <QPageSize>
#include <QPdfWriter>
#include <QTextDocument>

namespace rbw {

namespace {

QByteArray render(const QString& html, const QString& title, bool pdf)
{
    return pdf ? htmlToPdf(html, title) : html.toUtf8();
}

} // namespace

QByteArray htmlToPdf(const QString& html, const QString& title)
{
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    {
        QPdfWriter writer(&buffer);
        writer.setTitle(title);
        writer.setCreator(QStringLiteral("Rigid Body Workbook"));
        writer.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Portrait, QMarginsF(15, 15, 15, 15),
                                         QPageLayout::Millimeter));
        writer.setResolution(300);
        QTextDocument document;
        document.setHtml(html);
        document.print(&writer);
    }
    buffer.close();
    return bytes;
}

bool exportWorksheet(const ExerciseSpec& spec, const GeneratedExercise& g, const QString& path,
                     WorksheetFiles* written, QString* error)
{
    const QFileInfo info(path);
    const bool pdf = info.suffix().compare(QLatin1String("pdf"), Qt::CaseInsensitive) == 0;
    const QString suffix = info.suffix().isEmpty() ? QStringLiteral("html") : info.suffix();
    const QString keyPath = info.dir().filePath(info.completeBaseName() + QStringLiteral("-key.") + suffix);
    const QString sheet = exerciseWorksheetHtml(spec, g, false);
    const QString key = exerciseWorksheetHtml(spec, g, true);
    const QByteArray sheetBytes = render(sheet, info.completeBaseName(), pdf);
    const QByteArray keyBytes = render(key, info.completeBaseName() + QStringLiteral(" (answer key)"), pdf);
    if (sheetBytes.isEmpty() || keyBytes.isEmpty()) {
        if (error != nullptr) *error = QStringLiteral("%1: the PDF could not be laid out").arg(path);
        return false;
    }
    if (!writeFileAtomically(path, sheetBytes, error) || !writeFileAtomically(keyPath, keyBytes, error)) return false;
    if (written != nullptr) *written = WorksheetFiles{path, keyPath};
    return true;
}

} // namespace rbw
