#include "app/gui/shell/help_dialogs.h"

#include "app/core/source_root.h"

#include <QCoreApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileInfo>
#include <QMessageBox>
#include <QTextBrowser>
#include <QUrl>
#include <QVBoxLayout>
#include <QtGlobal>

#ifndef RBW_VERSION
#define RBW_VERSION "unknown"
#endif

namespace rbw {

namespace {

// The repository states no licence yet (no LICENSE file): About says so rather
// than guessing one. Change this line when a licence is chosen.
const char* const kLicenceLine = "Licence: none stated yet in this copy (no LICENSE file).";

} // namespace

void showUserGuide(QWidget* parent)
{
    if (auto* open = parent->findChild<QDialog*>(QStringLiteral("userGuideWindow"))) {
        open->raise();
        open->activateWindow();
        return;
    }
    auto* window = new QDialog(parent);
    window->setObjectName("userGuideWindow");
    window->setWindowTitle(QObject::tr("User guide"));
    window->setAttribute(Qt::WA_DeleteOnClose);
    window->setModal(false);
    auto* browser = new QTextBrowser(window);
    browser->setObjectName("userGuideBrowser");
    browser->setOpenExternalLinks(true);
    const QString path = userGuidePath();
    if (path.isEmpty()) {
        browser->setHtml(QObject::tr("<h2>The user guide was not found</h2><p>Looked for "
                                     "<code>docs/user-guide.md</code> in <code>%1</code> (the installed copy) and in "
                                     "the source tree (set <code>RBW_SOURCE_ROOT</code> to a copy of the "
                                     "repository).</p>")
                             .arg(QDir::toNativeSeparators(installedDataDirectory()).toHtmlEscaped()));
    } else {
        // A .md source is read as Markdown; its images resolve beside it (docs/images/).
        browser->setSearchPaths({QFileInfo(path).absolutePath()});
        browser->setSource(QUrl::fromLocalFile(path), QTextDocument::MarkdownResource);
    }
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, window);
    QObject::connect(buttons, &QDialogButtonBox::rejected, window, &QDialog::close);
    auto* layout = new QVBoxLayout(window);
    layout->addWidget(browser);
    layout->addWidget(buttons);
    window->resize(900, 700);
    window->show();
}

QString aboutText()
{
    const QString version = QCoreApplication::applicationVersion().isEmpty()
                                ? QStringLiteral(RBW_VERSION)
                                : QCoreApplication::applicationVersion();
    return QObject::tr("<h3>Rigid Body Workbook %1</h3>"
                       "<p>A workbook for the dynamics of rigid bodies: each lesson's step computed, traced "
                       "and derived, next to your own numbers.</p>"
                       "<p>Qt %2 (built with Qt %3)</p>"
                       "<p>%4</p>")
        .arg(version.toHtmlEscaped(), QString::fromLatin1(qVersion()), QStringLiteral(QT_VERSION_STR),
             QObject::tr(kLicenceLine).toHtmlEscaped());
}

void showAbout(QWidget* parent)
{
    auto* box = new QMessageBox(QMessageBox::Information, QObject::tr("About Rigid Body Workbook"), aboutText(),
                                QMessageBox::Ok, parent);
    box->setObjectName("aboutDialog");
    box->setTextFormat(Qt::RichText);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setModal(false);
    box->show();
}

} // namespace rbw
