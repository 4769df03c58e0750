// The worksheet of a drawn exercise as one HTML page (`rbw exercise --worksheet`, the
// app's worksheet export): the lesson and seed, the scene's setup as tables, the task
// and an answer table of the asked-for trace entries, empty or (withAnswers, the answer
// key) filled with the physics' numbers through value_format.
//
// It stays in app/exercise rather than beside the derivation's HTML (app/derivation):
// it reads ExerciseSpec and GeneratedExercise, and app/derivation may not include
// app/exercise, nor app/exercise app/derivation (tests/architecture/rooms.cmake); it
// shares nothing with the derivation page (no KaTeX, no template).
#pragma once

#include "app/exercise/exercise_draw.h"
#include "app/exercise/exercise_spec.h"

#include <QString>

namespace rbw {

QString exerciseWorksheetHtml(const ExerciseSpec& spec, const GeneratedExercise& g, bool withAnswers);

} // namespace rbw
