// The lessons: one folder each under lessons/, holding scene.json (whose "name" and
// "description" give the title and the one-line summary) and lesson.md (what to
// compute by hand and what to notice). Any other scene file in the folder is a
// variant of the lesson, listed after it with the id "folder/file" (no ".json"), except
// exercise.json (docs/exercises.md). Folders are listed in name order, so the
// number prefix ("01-one-step") fixes the order.
#pragma once

#include <QString>
#include <QList>

namespace rbw {

struct Lesson {
    QString id;            // folder name, e.g. "01-one-step"
    QString title;         // scene "name"
    QString description;   // scene "description"
    QString scenePath;
    QString textPath;      // lesson.md (a variant: NAME.md beside NAME.json if there is one), may not exist
    bool variant = false;  // another scene file of the lesson's folder; id "folder/file"
};

// $RBW_LESSONS_DIR if set; else lessons/ beside or above the executable; else the
// installed package's lessons (<exe>/../share/rigid-body-workbook/lessons, see
// installedDataDirectory() in source_root.h); else the source tree's lessons/ (a build
// tree). A folder counts if it holds 01-one-step/scene.json.
QString lessonsDirectory();

QList<Lesson> lessonCatalogue(const QString& directory = lessonsDirectory());

// What `rigid-workbook --lesson ARG` or `rigid-workbook FILE` names: a lesson by its id
// ("01-one-step", "07-bounce/impulses"), or a scene file by its path (a lesson's own
// file counts as that lesson). `error` says why it names neither: an unknown id (with
// the ids there are), or a path that is not a file.
struct LessonArgument {
    QString lessonId;   // a lesson of the catalogue
    QString file;       // else a scene file (absolute path), not yet loaded
    QString error;      // else why not

    bool ok() const { return error.isEmpty(); }
};
LessonArgument resolveLessonArgument(const QString& argument, const QList<Lesson>& lessons);

} // namespace rbw
