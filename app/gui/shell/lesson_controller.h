// The one way a scene starts in the window (issue 18). A lesson from the list, a
// scene file (File → Open, a drop, the command line, the file watch), new numbers
// for a seed and the scene editor's Apply all end in start(): the running lesson's
// record is replaced, the session loads the scene, and started() tells the window
// what to show (one slot, MainWindow::onSceneStarted, updates every panel). Before,
// the sequence was written four times and the copies disagreed (the accuracy panel
// got the lesson's id from two of them and its title from the others).
//
// A scene that does not load never replaces the running one: loadFailed() carries
// what was asked for and the messages (file, JSON path, reason).
#pragma once

#include "app/core/lesson_catalogue.h"
#include "physics/engine/scene.h"

#include <QObject>
#include <QStringList>

#include <optional>

namespace rbw {

class Session;

// Where a scene came from; the window shows it accordingly.
enum class SceneOrigin { Lesson, File, NewNumbers, Editor, Probe };

// What the window shows for a started scene.
struct StartedScene {
    SceneOrigin origin = SceneOrigin::Lesson;
    QString title;           // the lesson's or scene's title: window, status line, accuracy panel
    QString userFile;        // the student's own file (absolute), or empty
    QString windowTitle;
    QString lessonMarkdown;  // the Lesson dock's new text, filled from the scene; empty: it stays (own file, editor)
    QString statusMessage;   // a note for the status bar, or empty
    std::optional<quint64> seed;   // new numbers: the seed they were drawn from
};

class LessonController : public QObject {
    Q_OBJECT
public:
    LessonController(Session* session, QObject* parent = nullptr);

    const QList<Lesson>& lessons() const { return lessons_; }
    // The running scene's record: a lesson, or (id empty) the student's own scene.
    const Lesson& current() const { return current_; }
    int lessonRow(const QString& id) const;   // -1 if no such lesson

    // Each loads, and starts the scene only if it loads; false (and loadFailed) if not.
    bool openLesson(int row, QStringList* errors = nullptr);
    // A lesson's own file opens that lesson.
    bool openSceneFile(const QString& path, QString* error = nullptr);
    bool openNewNumbers(quint64 seed, QString* error = nullptr);
    // The editor's scene; editorFile is the file the editor shows (may be empty).
    void applyEditedScene(const SceneDef& scene, const QString& editorFile);
    // A probe of Compare with my simulator as a scene (physics' probeScene()), with its
    // title and the Lesson dock's text; the Yours column and the slider's mark follow it
    // (ProbeInWindow).
    void openProbe(const SceneDef& scene, const QString& title, const QString& markdown);
    // The scene was saved to this file: from now on it is the student's own.
    void adoptFile(const QString& absolutePath);

    static QString windowTitleFor(const QString& title, const QString& fileName);
    // The lesson's text (markdown, or its textPath if empty) with its setup filled from the scene
    // (app/derivation/lesson_text.h); new numbers and edits are marked as not the published scene.
    static QString lessonTextFor(const Lesson& lesson, const SceneDef& scene, SceneOrigin origin, QString markdown);

signals:
    // Before the session loads the new scene: the window stops playing, clears alerts.
    void aboutToStart();
    void started(const SceneDef& scene, const StartedScene& info);
    void loadFailed(const QString& what, const QStringList& errors);

private:
    // THE sequence: every scene starts here.
    void start(const SceneDef& scene, const Lesson& record, StartedScene info);

    Session* session_;
    QList<Lesson> lessons_;
    Lesson current_;
};

} // namespace rbw
