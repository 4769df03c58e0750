// The student's own scene files in the window: Save, Save as, New scene from this
// lesson, the reload when the open file changes on disk, and the editor's Apply.
// File → Open, recent files, drops and the watch itself are SceneFiles; every scene
// starts through the LessonController. A save goes through the atomic writer
// (saveSceneFile); a refused save is a warning dialog and leaves the file as it was.
//
// Unsaved edits are never discarded silently (issue 22): New, Open (the dialog, a
// drop, a recent file, another lesson), Quit and the reload of a file changed on disk
// first ask Save / Discard / Cancel while the editor holds edits; the window's title
// carries the edit mark (Qt's [*]).
#pragma once

#include <QObject>
#include <QString>

class QDockWidget;
class QMainWindow;

namespace rbw {

class LessonController;
class SceneEditor;
class SceneFiles;
class Session;

class SceneFileFlows : public QObject {
    Q_OBJECT
public:
    struct Parts {
        QMainWindow* window;
        SceneEditor* editor;
        QDockWidget* editorDock;
        SceneFiles* files;
        LessonController* lessons;
        Session* session;
    };
    explicit SceneFileFlows(const Parts& parts);

    // Writes the editor's scene (it must pass validate()) to `path`; it then becomes
    // the open, watched file. False with the reason (also shown in a dialog).
    bool saveSceneTo(const QString& path, QString* error = nullptr);
    bool saveScene();     // a lesson's own file is not overwritten: Save as
    bool saveSceneAs();
    void newSceneFromLesson();
    void showEditor();
    // Opens a file the student asked for (File → Open, a drop, a recent file), after
    // asking about unsaved edits.
    void openAsked(const QString& path);
    // No unsaved edits, or the student saved or discarded them: true to go on;
    // false if cancelled (or the save failed). The question names `action`.
    bool confirmUnsavedEdits(const QString& action);

private:
    enum class Answer { Save, Discard, Cancel };
    // The question (objectName "unsavedDialog").
    Answer ask(const QString& text);
    void reloadWatchedFile(const QString& path);

    Parts p_;
};

} // namespace rbw
