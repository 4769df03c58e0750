#include "app/gui/shell/lesson_controller.h"

#include "app/core/session.h"
#include "app/derivation/lesson_text.h"
#include "app/exercise/exercise.h"
#include "app/gui/shell/app_settings.h"
#include "app/scene/scene_loader.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

namespace rbw {

LessonController::LessonController(Session* session, QObject* parent)
    : QObject(parent)
    , session_(session)
    , lessons_(lessonCatalogue())
{
}

int LessonController::lessonRow(const QString& id) const
{
    for (int row = 0; row < lessons_.size(); ++row) {
        if (lessons_[row].id == id) return row;
    }
    return -1;
}

QString LessonController::windowTitleFor(const QString& title, const QString& fileName)
{
    // [*]: Qt shows "*" there while the window is modified (unsaved edits in the editor).
    return fileName.isEmpty() ? tr("%1[*] — Rigid Body Workbook").arg(title)
                              : tr("%1 (%2)[*] — Rigid Body Workbook").arg(title, fileName);
}

QString LessonController::lessonTextFor(const Lesson& lesson, const SceneDef& scene, SceneOrigin origin, QString markdown)
{
    QFile text(lesson.textPath);
    if (markdown.isEmpty() && !lesson.textPath.isEmpty() && text.open(QIODevice::ReadOnly)) markdown = QString::fromUtf8(text.readAll());
    const bool published = origin == SceneOrigin::Lesson || origin == SceneOrigin::File;
    return markdown.isEmpty() ? markdown : fillLessonText(markdown, scene, published).markdown;
}

void LessonController::start(const SceneDef& scene, const Lesson& record, StartedScene info)
{
    emit aboutToStart();
    current_ = record;
    // The lesson text's setup numbers follow the scene (issue 20): new numbers and edits re-read and refill it.
    // (A probe's text is its own, with no published numbers to compare with.)
    if (info.origin != SceneOrigin::Probe) info.lessonMarkdown = lessonTextFor(current_, scene, info.origin, info.lessonMarkdown);
    info.title = current_.title;
    info.windowTitle = windowTitleFor(current_.title, QFileInfo(info.userFile).fileName());
    if (info.origin == SceneOrigin::Lesson) AppSettings::setLastLesson(current_.id);
    session_->load(scene);   // -> the window's onSessionReset, onStateChanged
    emit started(scene, info);
}

bool LessonController::openLesson(int row, QStringList* errors)
{
    if (row < 0 || row >= lessons_.size()) return false;
    const Lesson lesson = lessons_[row];
    const SceneLoadResult loaded = loadSceneFile(lesson.scenePath);
    if (!loaded.ok()) {
        if (errors != nullptr) *errors = loaded.errors;
        emit loadFailed(tr("Lesson \"%1\"").arg(lesson.title), loaded.errors);
        return false;
    }
    StartedScene info;
    info.origin = SceneOrigin::Lesson;
    QFile text(lesson.textPath);
    info.lessonMarkdown = text.open(QIODevice::ReadOnly) ? QString::fromUtf8(text.readAll()) : lesson.description;
    start(*loaded.scene, lesson, info);
    return true;
}

bool LessonController::openSceneFile(const QString& path, QString* error)
{
    const QFileInfo file(path);
    // A lesson's own file opens the lesson, with its text and list entry.
    for (int row = 0; row < lessons_.size(); ++row) {
        if (file.exists() && QFileInfo(lessons_[row].scenePath).canonicalFilePath() == file.canonicalFilePath()) {
            QStringList errors;
            if (openLesson(row, &errors)) return true;
            if (error != nullptr) *error = errors.join('\n');
            return false;
        }
    }
    const SceneLoadResult loaded = loadSceneFile(path);
    if (!loaded.ok()) {
        emit loadFailed(QDir::toNativeSeparators(path), loaded.errors);
        if (error != nullptr) *error = loaded.errors.join('\n');
        return false;
    }
    const QString absolute = file.absoluteFilePath();
    const QString name = QString::fromStdString(loaded.scene->name);
    const Lesson own{QString(), name.isEmpty() ? file.completeBaseName() : name,
                     QString::fromStdString(loaded.scene->description), absolute, QString(), false};
    StartedScene info;
    info.origin = SceneOrigin::File;
    info.userFile = absolute;
    info.lessonMarkdown = tr("# %1\n\n%2\n\nYour own scene, from `%3`. Saving the file in an editor reloads it "
                             "here; the **Scene editor** tab (Ctrl+Shift+E) changes its numbers.")
                              .arg(own.title, own.description, QDir::toNativeSeparators(absolute));
    info.statusMessage = tr("Opened %1").arg(QDir::toNativeSeparators(absolute));
    start(*loaded.scene, own, info);
    return true;
}

bool LessonController::openNewNumbers(quint64 seed, QString* error)
{
    const QString lessonId = current_.variant ? current_.id.section('/', 0, 0) : current_.id;
    const ExerciseLoadResult spec = loadExercise(QFileInfo(current_.scenePath).absolutePath());
    GeneratedExercise generated;
    if (spec.ok()) generated = generateExercise(*spec.spec, seed);
    if (!spec.ok() || !generated.ok()) {
        if (error != nullptr) {
            *error = spec.ok() ? generated.errors.join('\n')
                               : tr("This lesson has no new numbers.\n\n%1").arg(spec.errors.join('\n'));
        }
        return false;
    }
    Lesson record = current_;
    record.title = tr("Lesson %1, new numbers (seed %2)").arg(lessonId.section('-', 0, 0).toInt()).arg(seed);
    StartedScene info;
    info.origin = SceneOrigin::NewNumbers;
    info.statusMessage = tr("New numbers: seed %1").arg(seed);
    info.seed = seed;
    start(*generated.scene, record, info);
    return true;
}

void LessonController::applyEditedScene(const SceneDef& scene, const QString& editorFile)
{
    Lesson record = current_;
    if (!scene.name.empty()) record.title = QString::fromStdString(scene.name);
    StartedScene info;
    info.origin = SceneOrigin::Editor;
    info.userFile = editorFile;
    start(scene, record, info);
}

void LessonController::openProbe(const SceneDef& scene, const QString& title, const QString& markdown)
{
    const Lesson probe{QString(), title, QString::fromStdString(scene.description), QString(), QString(), false};
    StartedScene info;
    info.origin = SceneOrigin::Probe;
    info.lessonMarkdown = markdown;
    info.statusMessage = tr("Opened %1").arg(title);
    start(scene, probe, info);
}

void LessonController::adoptFile(const QString& absolutePath)
{
    current_.id.clear();
    current_.scenePath = absolutePath;
    current_.textPath.clear();
}

} // namespace rbw
