#include "app/gui/shell/scene_files.h"

#include "app/gui/shell/app_settings.h"

#include <QCoreApplication>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QMimeData>
#include <QTreeView>
#include <QUrl>
#include <QWidget>

namespace rbw {

namespace {

const QString kFilter = QStringLiteral("Scene files (*.json);;All files (*)");

// Qt's own dialog: a size where its detail columns (name, size, type, date) fit.
void fitColumns(QFileDialog* dialog)
{
    dialog->resize(900, 540);
    for (QTreeView* view : dialog->findChildren<QTreeView*>()) {
        view->header()->setStretchLastSection(false);
        view->header()->setSectionResizeMode(0, QHeaderView::Stretch);
        for (int c = 1; c < view->header()->count(); ++c) view->header()->setSectionResizeMode(c, QHeaderView::ResizeToContents);
    }
}

} // namespace

SceneFiles::SceneFiles(QWidget* window)
    : QObject(window)
    , window_(window)
{
    settle_.setSingleShot(true);
    settle_.setInterval(150);
    connect(&settle_, &QTimer::timeout, this, &SceneFiles::check);
    connect(&watcher_, &QFileSystemWatcher::fileChanged, this, &SceneFiles::onSomethingChanged);
    connect(&watcher_, &QFileSystemWatcher::directoryChanged, this, &SceneFiles::onSomethingChanged);
    // Drops anywhere in the window, also on widgets that take drops themselves (the
    // derivation's web view would show the file as a page).
    QCoreApplication::instance()->installEventFilter(this);
}

QStringList SceneFiles::recentFiles() const
{
    QStringList existing;
    for (const QString& path : AppSettings::recentFiles()) {
        if (QFileInfo(path).isFile()) existing << path;
    }
    return existing;
}

void SceneFiles::addRecent(const QString& path)
{
    const QString absolute = QFileInfo(path).absoluteFilePath();
    QStringList list = AppSettings::recentFiles();
    list.removeAll(absolute);
    list.prepend(absolute);
    while (list.size() > kMaxRecent) list.removeLast();
    AppSettings::setRecentFiles(list);
    emit recentChanged();
}

void SceneFiles::clearRecent()
{
    AppSettings::setRecentFiles({});
    emit recentChanged();
}

void SceneFiles::watch(const QString& path)
{
    if (!watcher_.files().isEmpty()) watcher_.removePaths(watcher_.files());
    if (!watcher_.directories().isEmpty()) watcher_.removePaths(watcher_.directories());
    settle_.stop();
    watched_ = path.isEmpty() ? QString() : QFileInfo(path).absoluteFilePath();
    lastBytes_.clear();
    if (watched_.isEmpty()) return;
    QFile file(watched_);
    if (file.open(QIODevice::ReadOnly)) lastBytes_ = file.readAll();
    watcher_.addPath(watched_);
    // The folder too: an editor that saves by rename replaces the file, and the folder
    // reports when the new one appears.
    watcher_.addPath(QFileInfo(watched_).absolutePath());
}

void SceneFiles::onSomethingChanged()
{
    if (!watched_.isEmpty()) settle_.start();
}

void SceneFiles::check()
{
    if (watched_.isEmpty() || !QFileInfo(watched_).isFile()) return;   // gone for now: the folder reports its return
    if (!watcher_.files().contains(watched_)) watcher_.addPath(watched_);   // replaced by a rename: watch the new file
    QFile file(watched_);
    if (!file.open(QIODevice::ReadOnly)) return;
    const QByteArray bytes = file.readAll();
    if (bytes == lastBytes_) return;
    lastBytes_ = bytes;
    emit watchedFileChanged(watched_);
}

QFileDialog* SceneFiles::showOpenDialog(const QString& startFolder)
{
    if (openDialog_) {
        openDialog_->raise();
        return openDialog_;
    }
    auto* dialog = new QFileDialog(window_, tr("Open a scene file"), startFolder, kFilter);
    dialog->setObjectName("openSceneDialog");
    dialog->setOption(QFileDialog::DontUseNativeDialog);
    dialog->setAcceptMode(QFileDialog::AcceptOpen);
    dialog->setFileMode(QFileDialog::ExistingFile);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    fitColumns(dialog);
    connect(dialog, &QFileDialog::fileSelected, this, &SceneFiles::openRequested);
    openDialog_ = dialog;
    dialog->open();
    return dialog;
}

QString SceneFiles::askSavePath(const QString& suggested)
{
    QFileDialog dialog(window_, tr("Save the scene as"), suggested, kFilter);
    dialog.setObjectName("saveSceneDialog");
    dialog.setOption(QFileDialog::DontUseNativeDialog);
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    dialog.setDefaultSuffix(QStringLiteral("json"));
    fitColumns(&dialog);
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty()) return {};
    return dialog.selectedFiles().first();
}

QString SceneFiles::sceneFileIn(const QMimeData* mime)
{
    if (mime == nullptr || !mime->hasUrls()) return {};
    for (const QUrl& url : mime->urls()) {
        if (url.isLocalFile() && url.toLocalFile().endsWith(QStringLiteral(".json"), Qt::CaseInsensitive)) {
            return url.toLocalFile();
        }
    }
    return {};
}

bool SceneFiles::eventFilter(QObject* watched, QEvent* event)
{
    const QEvent::Type type = event->type();
    if (type != QEvent::DragEnter && type != QEvent::DragMove && type != QEvent::Drop) return false;
    auto* widget = qobject_cast<QWidget*>(watched);
    if (widget != nullptr && widget->window() == window_) {
        switch (type) {
        case QEvent::DragEnter:
        case QEvent::DragMove: {
            auto* e = static_cast<QDragMoveEvent*>(event);
            if (!sceneFileIn(e->mimeData()).isEmpty()) {
                e->acceptProposedAction();
                return true;
            }
            break;
        }
        case QEvent::Drop: {
            auto* e = static_cast<QDropEvent*>(event);
            const QString path = sceneFileIn(e->mimeData());
            if (!path.isEmpty()) {
                e->acceptProposedAction();
                emit openRequested(path);
                return true;
            }
            break;
        }
        default: break;
        }
    }
    return QObject::eventFilter(watched, event);
}

} // namespace rbw
