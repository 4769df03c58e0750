// Which mistakes an exercise can show (issue 21 items 9 and 10), measured, not claimed.
//
// For every draw of the given seeds, every mistake model of the checker's catalogue
// (physics/workbook/checker/mistakes.h, iterated, so a model added there is measured
// here without a change) recomputes the exercise's answer step from the same inputs the
// checker uses (model_inputs.h), and each answer of the key is compared with the right
// number at the checker's tolerance (tolerance.h):
//   shown    the model gives another number for that answer;
//   hidden   it gives the right number.
// Per lesson, a model shows in a quantity (an id and its body, or its contact's pair)
// when it is shown there in every draw; a quantity where it is shown in some draws and
// hidden in others is a failure: the generator drew values that make the mistake
// invisible (h = 1 for `missing-time-step`). Two models that give the same numbers in
// every answer of a draw cannot be told apart there; when they can in other draws, that
// is a failure too (c = 0.5, where 1 - c = c). Nothing is computed here: the numbers are
// the physics' models and trace.
#pragma once

#include "app/exercise/exercise_spec.h"

#include <QString>
#include <QStringList>

#include <cstdint>
#include <vector>

namespace rbw {

struct ModelVisibility {
    QString model;             // "missing-time-step", "inertia-axes-swapped (variant 1)"
    QStringList shownIn;       // "angular_momentum", "impulse (A–B)": shown in every draw
    QStringList sameAs;        // models with the same numbers in every answer of every draw
    QStringList hiddenAt;      // failures: "seed 3: angular_momentum of box is right under it"
    QStringList coincidences;  // failures: "seed 5: the same numbers as restitution-one-minus"
};

struct ExerciseMistakeReport {
    QString lessonId;
    std::vector<std::uint64_t> seeds;
    std::vector<ModelVisibility> models;   // in the catalogue's order
    QStringList errors;                    // a seed that made no exercise
    QStringList failures() const;          // every hiddenAt and coincidences, and the errors
    // The lesson's section of docs/checker.md: a heading and a table.
    QString markdown() const;
};

ExerciseMistakeReport measureExerciseMistakes(const ExerciseSpec& spec, const std::vector<std::uint64_t>& seeds);

} // namespace rbw
