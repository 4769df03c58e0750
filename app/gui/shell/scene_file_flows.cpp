#include "app/gui/shell/scene_file_flows.h"

#include "app/core/session.h"
#include "app/gui/panels/editor/scene_editor.h"
#include "app/gui/shell/lesson_controller.h"
#include "app/gui/shell/scene_files.h"
#include "app/scene/scene_writer.h"

#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QMainWindow>
#include <QMessageBox>
#include <QRegularExpression>
#include <QStatusBar>

namespace rbw {

SceneFileFlows::SceneFileFlows(const Parts& parts)
    : QObject(parts.window)
    , p_(parts)
{
    p_.window->setAcceptDrops(true);   // a .json dropped anywhere on the window (SceneFiles takes it)
    connect(p_.files, &SceneFiles::openRequested, this, &SceneFileFlows::openAsked);
    connect(p_.editor, &SceneEditor::modifiedChanged, p_.window, &QWidget::setWindowModified);
    // The editor's dock and its tab mark unsaved edits too, as the window's title does
    // (issue 22 item 6, issue 20 item 7).
    connect(p_.editor, &SceneEditor::modifiedChanged, p_.editorDock, [dock = p_.editorDock](bool modified) {
        dock->setWindowTitle(modified ? tr("Scene editor *") : tr("Scene editor"));
    });
    connect(p_.files, &SceneFiles::watchedFileChanged, this, &SceneFileFlows::reloadWatchedFile);
    connect(p_.editor, &SceneEditor::applyRequested, p_.lessons,
            [this](const SceneDef& scene) { p_.lessons->applyEditedScene(scene, p_.editor->filePath()); });
    connect(p_.editor, &SceneEditor::message, p_.window,
            [status = p_.window->statusBar()](const QString& text) { status->showMessage(text, 6000); });
}

SceneFileFlows::Answer SceneFileFlows::ask(const QString& text)
{
    QMessageBox box(QMessageBox::Warning, tr("Unsaved edits"), text,
                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, p_.window);
    box.setObjectName("unsavedDialog");
    box.setDefaultButton(QMessageBox::Save);
    switch (box.exec()) {
    case QMessageBox::Save: return Answer::Save;
    case QMessageBox::Discard: return Answer::Discard;
    default: return Answer::Cancel;
    }
}

bool SceneFileFlows::confirmUnsavedEdits(const QString& action)
{
    if (!p_.editor->isModified()) return true;
    switch (ask(tr("The scene \"%1\" has edits that are not saved. Save them before you %2?")
                    .arg(QString::fromStdString(p_.editor->scene().name), action))) {
    case Answer::Save: return saveScene();
    case Answer::Discard: return true;
    case Answer::Cancel: return false;
    }
    return false;
}

void SceneFileFlows::openAsked(const QString& path)
{
    if (confirmUnsavedEdits(tr("open %1").arg(QFileInfo(path).fileName()))) p_.lessons->openSceneFile(path);
}

void SceneFileFlows::reloadWatchedFile(const QString& path)
{
    if (p_.editor->isModified()) {
        // Save writes the edits over the change on disk; Cancel keeps both as they are.
        switch (ask(tr("%1 changed on disk, and the scene editor has edits that are not saved. Save your edits "
                       "over it, discard them and load the file, or keep them unsaved?")
                        .arg(QFileInfo(path).fileName()))) {
        case Answer::Save: saveScene(); return;
        case Answer::Discard: break;
        case Answer::Cancel:
            p_.window->statusBar()->showMessage(tr("Kept your edits; %1 changed on disk").arg(QFileInfo(path).fileName()), 6000);
            return;
        }
    }
    if (p_.lessons->openSceneFile(path)) {
        p_.window->statusBar()->showMessage(tr("Reloaded %1: it changed on disk").arg(QFileInfo(path).fileName()), 4000);
    }
}

bool SceneFileFlows::saveSceneTo(const QString& path, QString* error)
{
    QString reason;
    if (!p_.editor->issues().isEmpty()) {
        reason = tr("The scene has problems; fix them first:\n%1").arg(p_.editor->issues().join('\n'));
    } else {
        const QString absolute = QFileInfo(path).absoluteFilePath();
        if (p_.files->watchedPath() == absolute) p_.files->noteWritten(writeScene(p_.editor->scene()));   // our own write: no reload
        if (saveSceneFile(p_.editor->scene(), absolute, &reason)) {
            p_.editor->setFilePath(absolute);
            p_.editor->setModified(false);
            if (p_.files->watchedPath() != absolute) p_.files->watch(absolute);
            p_.files->addRecent(absolute);
            p_.lessons->adoptFile(absolute);   // from now on the student's own file, not the lesson's
            p_.window->setWindowTitle(LessonController::windowTitleFor(p_.lessons->current().title, QFileInfo(absolute).fileName()));
            p_.window->statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(absolute)), 4000);
            return true;
        }
    }
    if (error != nullptr) *error = reason;
    QMessageBox::warning(p_.window, tr("Save the scene"), reason);
    return false;
}

bool SceneFileFlows::saveScene()
{
    if (p_.editor->filePath().isEmpty()) return saveSceneAs();
    return saveSceneTo(p_.editor->filePath());
}

bool SceneFileFlows::saveSceneAs()
{
    const QString stem = QString::fromStdString(p_.editor->scene().name).toLower().replace(QRegularExpression("[^a-z0-9]+"), "-");
    const QString folder = p_.editor->filePath().isEmpty() ? QDir::homePath() : QFileInfo(p_.editor->filePath()).absolutePath();
    const QString path = p_.files->askSavePath(QDir(folder).filePath((stem.isEmpty() ? QStringLiteral("scene") : stem) + ".json"));
    return !path.isEmpty() && saveSceneTo(path);
}

void SceneFileFlows::newSceneFromLesson()
{
    if (!p_.session->isLoaded() || !confirmUnsavedEdits(tr("start a new scene"))) return;
    SceneDef scene = p_.session->baseScene();
    scene.name = tr("My %1").arg(p_.lessons->current().title).toStdString();
    p_.editor->setScene(scene, QString());
    p_.editor->setModified(true);
    p_.lessons->applyEditedScene(scene, QString());
    showEditor();
    p_.window->statusBar()->showMessage(tr("A new scene from this lesson: edit it, then File → Save scene as…"), 6000);
}

void SceneFileFlows::showEditor()
{
    p_.editorDock->show();
    p_.editorDock->raise();
}

} // namespace rbw
