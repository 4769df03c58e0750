// New numbers for practice (docs/exercises.md): a lesson's exercise.json names the
// values of its scene.json that may vary, their ranges and rounding steps, and what
// must stay true (the lesson's point, e.g. "A and B still collide"). generateExercise()
// draws the values from std::mt19937_64 with a mapping written here (not a standard
// distribution, whose results differ between standard libraries), so a seed gives the
// same scene, byte for byte, everywhere. Each candidate scene is validated by the
// scene loader (parseScene) and run by the physics; one that fails is replaced by the
// next sub-seed's, a bounded number of times. The answer key is the physics' own trace
// of the lesson's step: nothing here recomputes a physical quantity.
#pragma once

#include "physics/workbook/checker/checker.h"
#include "physics/engine/scene.h"
#include "physics/engine/trace.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <optional>
#include <random>
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
};

struct ExerciseRequire {
    QString jsonPath;            // "require[0]"
    QString a, b;                // a body name and a body or plane name
    int points = -1;             // the contacts of the pair in its first contact step; -1: any
};

struct ExerciseSpec {
    QString file;                // .../exercise.json
    QString lessonId;            // the folder name, "01-one-step"
    QString scenePath;           // the base scene
    QJsonObject scene;           // the base scene's document
    std::vector<ExerciseVary> vary;
    std::vector<ExerciseRequire> require;
    bool answerAtFirstContact = false;  // "step": "first-contact"
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

// LESSON is a lesson id ("01-one-step", looked up in lessonsDirectory()) or a lesson
// folder path. Reads and checks LESSON/exercise.json and its scene.
ExerciseLoadResult loadExercise(const QString& lesson);

struct GeneratedExercise {
    QByteArray sceneJson;        // the new scene file, indented JSON
    std::optional<SceneDef> scene;
    std::uint64_t seed = 0;
    int attempt = 0;             // which sub-seed gave it (0: the seed itself)
    long answerStep = 0;
    StepTrace answerTrace;       // the physics' trace of that step
    std::vector<TraceEntry> key; // the answer-table entries of that trace, in trace order
    QStringList errors;          // why no scene could be made; empty on success
    bool ok() const { return errors.isEmpty() && scene.has_value(); }
};

GeneratedExercise generateExercise(const ExerciseSpec& spec, std::uint64_t seed);

// An integer uniform in [0, n], from the engine's raw 64-bit outputs by rejection
// (portable: the same numbers with every standard library).
std::uint64_t uniformIndex(std::mt19937_64& engine, std::uint64_t n);

// The key as answers (docs/checker.md): rbw check accepts it with exit 0.
std::vector<Answer> exerciseAnswers(const GeneratedExercise& g);
QByteArray exerciseAnswersJson(const GeneratedExercise& g);

// The worksheet: the setup and an answer table, empty or (withAnswers) filled.
QString exerciseWorksheetHtml(const ExerciseSpec& spec, const GeneratedExercise& g, bool withAnswers);

} // namespace rbw
