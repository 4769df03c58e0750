// A lesson's exercise.json (docs/exercises.md), read and checked: which values of its
// scene.json may vary (scene paths, scene_path.h), their ranges and rounding steps,
// what must stay true (the lesson's point, e.g. "A and B still collide"), which step's
// numbers the worksheet asks for and which trace ids. Every error names the file, the
// JSON path in it and the reason.
#pragma once

#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace rbw {

struct ExerciseVary {
    QString jsonPath;            // "vary[2]": where this rule is in exercise.json
    QStringList paths;           // scene paths that receive the one drawn value, "bodies[0].mass"
    std::vector<double> lo, hi;  // one range per component; a scalar has one
    bool vector = false;         // the scene value is an array (range was a list of ranges)
    double step = 0.1;           // values are lo + k step, k = 0, 1, ...
    int decimals = 1;            // decimals of step: the values are rounded to these
    bool nonzero = false;        // redraw an all-zero value
    std::vector<double> avoid;   // a number's values that are redrawn (they hide a mistake)
};

struct ExerciseRequire {
    QString jsonPath;            // "require[0]"
    QString a, b;                // a body name and a body or plane name
    int points = -1;             // the contacts of the pair in its first contact step; -1: any
};

struct ExerciseSpec {
    QString file;                // .../exercise.json
    QString lessonId;            // the folder name, "01-one-step"; a lesson's further exercise
                                 // (a folder inside the lesson's): "06-box-on-plane/separating"
    QString scenePath;           // the base scene
    QJsonObject scene;           // the base scene's document
    std::vector<ExerciseVary> vary;
    std::vector<ExerciseRequire> require;
    bool answerAtFirstContact = false;  // "step": "first-contact"
    bool answerAtFirstSeparating = false;  // "step": "first-separating": the first step with a
                                           // separating contact (v_rel . n > 0: no impulse)
    long answerStep = 0;                // else the step k whose numbers the worksheet asks for
    QStringList quantities;             // trace ids for the answer table, in trace order
    QString task;                       // one sentence for the worksheet
    QString description;                // the new scenes' "description", if given
    int attempts = 50;                  // sub-seeds tried before giving up
};

struct ExerciseLoadResult {
    std::optional<ExerciseSpec> spec;
    QStringList errors;          // "file: json path: reason"
    bool ok() const { return spec.has_value(); }
};

// LESSON is a lesson id ("01-one-step", looked up in lessonsDirectory()), a lesson's
// further exercise ("06-box-on-plane/separating": a folder inside the lesson's, whose
// exercise.json names the lesson's scene as "../scene.json") or a folder path. Reads and
// checks LESSON/exercise.json and its scene.
ExerciseLoadResult loadExercise(const QString& lesson);

} // namespace rbw
