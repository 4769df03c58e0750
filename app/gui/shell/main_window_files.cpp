// MainWindow: the student's own scene files and the scene editor. File → Open,
// the recent files, drops and the file watch live in SceneFiles, the editor in
// app/gui/panels/editor/; this file wires them to the window. A scene that does not load never
// replaces the running one: the error (file, JSON path, reason) is shown and the
// running scene keeps its name.
#include "app/scene/scene_loader.h"
#include "app/scene/scene_writer.h"
#include "app/gui/panels/accuracy/accuracy_panel.h"
#include "app/gui/panels/editor/scene_editor.h"
#include "app/gui/shell/main_window.h"
#include "app/gui/shell/scene_files.h"
#include "app/gui/panels/view/scene_view.h"

#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QLabel>
#include <QRegularExpression>
#include <QListWidget>
#include <QMenu>
#include <QMessageBox>
#include <QSignalBlocker>
#include <QStatusBar>
#include <QTextBrowser>
#include <QTimer>
#include <QToolBar>
#include <QTreeView>

namespace rbw {

void MainWindow::createEditorDock()
{
    sceneFiles_ = new SceneFiles(this);
    setAcceptDrops(true);   // a .json dropped anywhere on the window (SceneFiles takes it)
    connect(sceneFiles_, &SceneFiles::openRequested, this, [this](const QString& path) { openSceneFile(path); });
    connect(sceneFiles_, &SceneFiles::watchedFileChanged, this, &MainWindow::reloadWatchedFile);

    sceneEditor_ = new SceneEditor;
    sceneEditor_->setObjectName("sceneEditor");
    editorDock_ = new QDockWidget(tr("Scene editor"), this);
    editorDock_->setObjectName("sceneEditorDock");
    editorDock_->setWidget(sceneEditor_);
    addDockWidget(Qt::RightDockWidgetArea, editorDock_);
    // A tab beside the quantities of the step, where a key and its value fit side by side.
    if (auto* traceDock = findChild<QDockWidget*>("traceDock")) {
        tabifyDockWidget(traceDock, editorDock_);
        traceDock->raise();
    }
    connect(sceneEditor_, &SceneEditor::applyRequested, this, &MainWindow::applyEditedScene);
    connect(sceneEditor_, &SceneEditor::message, this, [this](const QString& text) {
        statusBar()->showMessage(text, 6000);
    });
}

void MainWindow::createFileActions(QMenu* fileMenu)
{
    auto* open = addShortcutAction(tr("&Open scene…"), "actionOpenScene", {QKeySequence::Open});
    connect(open, &QAction::triggered, this, [this] {
        const QString current = currentLesson_.scenePath;
        sceneFiles_->showOpenDialog(current.isEmpty() ? QDir::homePath() : QFileInfo(current).absolutePath());
    });
    recentMenu_ = new QMenu(tr("Open &recent"), this);
    recentMenu_->setObjectName("recentMenu");
    connect(sceneFiles_, &SceneFiles::recentChanged, this, &MainWindow::updateRecentMenu);
    auto* save = addShortcutAction(tr("&Save scene"), "actionSaveScene", {QKeySequence::Save});
    connect(save, &QAction::triggered, this, &MainWindow::saveScene);
    auto* saveAs = addShortcutAction(tr("Save scene &as…"), "actionSaveSceneAs", {QKeySequence::SaveAs});
    connect(saveAs, &QAction::triggered, this, &MainWindow::saveSceneAs);
    auto* fromLesson = addShortcutAction(tr("&New scene from this lesson"), "actionNewSceneFromLesson", {QKeySequence::New});
    connect(fromLesson, &QAction::triggered, this, &MainWindow::newSceneFromLesson);
    auto* editor = addShortcutAction(tr("&Edit the scene"), "actionEditScene",
                                     {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E)});
    connect(editor, &QAction::triggered, this, [this] {
        editorDock_->show();
        editorDock_->raise();
        sceneEditor_->view()->setFocus();
    });

    fileMenu->addAction(open);
    fileMenu->addMenu(recentMenu_);
    fileMenu->addSeparator();
    fileMenu->addActions({fromLesson, editor, save, saveAs});
    fileMenu->addSeparator();
    sceneEditor_->toolBar()->addActions({save, saveAs});
    updateRecentMenu();
}

void MainWindow::updateRecentMenu()
{
    recentMenu_->clear();
    const QStringList files = sceneFiles_->recentFiles();
    for (int i = 0; i < files.size(); ++i) {
        auto* a = recentMenu_->addAction(QStringLiteral("&%1  %2").arg(i + 1).arg(QDir::toNativeSeparators(files[i])));
        const QString path = files[i];
        connect(a, &QAction::triggered, this, [this, path] { openSceneFile(path); });
    }
    if (files.isEmpty()) recentMenu_->addAction(tr("(none yet)"))->setEnabled(false);
    recentMenu_->addSeparator();
    auto* clear = recentMenu_->addAction(tr("Clear the list"));
    clear->setEnabled(!files.isEmpty());
    connect(clear, &QAction::triggered, sceneFiles_, &SceneFiles::clearRecent);
}

void MainWindow::showSceneErrors(const QString& what, const QStringList& errors)
{
    const QString running = session_.isLoaded() ? currentLesson_.title : tr("nothing");
    alertLabel_->setText(tr("%1 cannot be loaded; still running \"%2\".\n%3")
                             .arg(what, running, errors.mid(0, 6).join('\n')));
    alertLabel_->show();
    statusBar()->showMessage(errors.value(0), 10000);
    updateStatus();
}

void MainWindow::sceneStarted(const SceneDef& scene, const QString& userFile)
{
    sceneEditor_->setScene(scene, userFile);
    sceneFiles_->watch(userFile);
    if (!userFile.isEmpty()) sceneFiles_->addRecent(userFile);
}

bool MainWindow::openSceneFile(const QString& path, QString* error)
{
    const QFileInfo info(path);
    // A lesson's own file opens the lesson, with its text and list entry.
    for (const Lesson& l : lessons_) {
        if (info.exists() && QFileInfo(l.scenePath).canonicalFilePath() == info.canonicalFilePath()) {
            if (openLesson(l.id)) return true;
            if (error != nullptr) *error = alertLabel_->text();
            return false;
        }
    }
    const SceneLoadResult loaded = loadSceneFile(path);
    if (!loaded.ok()) {
        showSceneErrors(QDir::toNativeSeparators(path), loaded.errors);
        if (error != nullptr) *error = loaded.errors.join('\n');
        return false;
    }
    setPlaying(false);
    alertLabel_->hide();
    focusBody_ = -1;
    const QString absolute = info.absoluteFilePath();
    const QString name = QString::fromStdString(loaded.scene->name);
    currentLesson_ = Lesson{QString(), name.isEmpty() ? info.completeBaseName() : name,
                            QString::fromStdString(loaded.scene->description), absolute, QString(), false};
    {
        const QSignalBlocker block(lessonList_);   // not a lesson: no row is current
        lessonList_->setCurrentRow(-1);
        lessonList_->clearSelection();
    }
    lessonText_->setMarkdown(tr("# %1\n\n%2\n\nYour own scene, from `%3`. Saving the file in an editor reloads it "
                                "here; the **Scene editor** tab (Ctrl+Shift+E) changes its numbers.")
                                 .arg(currentLesson_.title, currentLesson_.description, QDir::toNativeSeparators(absolute)));
    session_.load(*loaded.scene);   // -> onSessionReset, onStateChanged
    accuracyPanel_->setScene(*loaded.scene, currentLesson_.title);
    sceneView_->resetView();
    setWindowTitle(tr("%1 (%2) — Rigid Body Workbook").arg(currentLesson_.title, info.fileName()));
    sceneStarted(*loaded.scene, absolute);
    statusBar()->showMessage(tr("Opened %1").arg(QDir::toNativeSeparators(absolute)), 4000);
    updateStatus();
    return true;
}

void MainWindow::reloadWatchedFile(const QString& path)
{
    const SceneLoadResult loaded = loadSceneFile(path);
    if (!loaded.ok()) {
        showSceneErrors(QDir::toNativeSeparators(path), loaded.errors);
        return;
    }
    if (openSceneFile(path)) statusBar()->showMessage(tr("Reloaded %1: it changed on disk").arg(QFileInfo(path).fileName()), 4000);
}

void MainWindow::applyEditedScene(const SceneDef& scene)
{
    setPlaying(false);
    alertLabel_->hide();
    focusBody_ = -1;
    if (!scene.name.empty()) currentLesson_.title = QString::fromStdString(scene.name);
    session_.load(scene);   // -> onSessionReset, onStateChanged: the next step uses these numbers
    accuracyPanel_->setScene(scene, currentLesson_.title);
    const QString file = sceneEditor_->filePath().isEmpty() ? QString() : QFileInfo(sceneEditor_->filePath()).fileName();
    setWindowTitle(file.isEmpty() ? tr("%1 — Rigid Body Workbook").arg(currentLesson_.title)
                                  : tr("%1 (%2) — Rigid Body Workbook").arg(currentLesson_.title, file));
    updateStatus();
}

bool MainWindow::saveSceneTo(const QString& path, QString* error)
{
    QString reason;
    if (!sceneEditor_->issues().isEmpty()) {
        reason = tr("The scene has problems; fix them first:\n%1").arg(sceneEditor_->issues().join('\n'));
    } else {
        const QByteArray text = writeScene(sceneEditor_->scene());
        const QString absolute = QFileInfo(path).absoluteFilePath();
        if (sceneFiles_->watchedPath() == absolute) sceneFiles_->noteWritten(text);   // our own write: no reload
        if (saveSceneFile(sceneEditor_->scene(), absolute, &reason)) {
            sceneEditor_->setFilePath(absolute);
            sceneEditor_->setModified(false);
            if (sceneFiles_->watchedPath() != absolute) sceneFiles_->watch(absolute);
            sceneFiles_->addRecent(absolute);
            // From now on this is the student's own file, not the lesson it came from.
            currentLesson_.id.clear();
            currentLesson_.scenePath = absolute;
            currentLesson_.textPath.clear();
            setWindowTitle(tr("%1 (%2) — Rigid Body Workbook").arg(currentLesson_.title, QFileInfo(absolute).fileName()));
            statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(absolute)), 4000);
            return true;
        }
    }
    if (error != nullptr) *error = reason;
    QMessageBox::warning(this, tr("Save the scene"), reason);
    return false;
}

bool MainWindow::saveScene()
{
    // A lesson's file is not overwritten: it is saved as the student's own.
    if (sceneEditor_->filePath().isEmpty()) return saveSceneAs();
    return saveSceneTo(sceneEditor_->filePath());
}

bool MainWindow::saveSceneAs()
{
    const QString stem = QString::fromStdString(sceneEditor_->scene().name).toLower().replace(QRegularExpression("[^a-z0-9]+"), "-");
    const QString folder = sceneEditor_->filePath().isEmpty() ? QDir::homePath() : QFileInfo(sceneEditor_->filePath()).absolutePath();
    const QString path = sceneFiles_->askSavePath(QDir(folder).filePath((stem.isEmpty() ? QStringLiteral("scene") : stem) + ".json"));
    return !path.isEmpty() && saveSceneTo(path);
}

void MainWindow::newSceneFromLesson()
{
    if (!session_.isLoaded()) return;
    SceneDef scene = session_.baseScene();
    scene.name = tr("My %1").arg(currentLesson_.title).toStdString();
    sceneEditor_->setScene(scene, QString());
    sceneEditor_->setModified(true);
    applyEditedScene(scene);
    editorDock_->show();
    editorDock_->raise();
    statusBar()->showMessage(tr("A new scene from this lesson: edit it, then File → Save scene as…"), 6000);
}

} // namespace rbw
