// New numbers for practice (docs/exercises.md), for the callers that use all of it
// (rbw exercise, the shell's exercise actions, the tests). One concept per header:
//   exercise_spec.h       a lesson's exercise.json read and checked (ExerciseSpec)
//   scene_path.h          its JSON-path language, "bodies[0].mass"
//   value_grid.h          the number grid and the portable draw from a seed
//   exercise_draw.h       generateExercise(): the scene with drawn values, run and kept
//                         only when it keeps the lesson's point
//   exercise_answers.h    the answer key from the physics' trace
//   exercise_worksheet.h  the worksheet and its answer key as HTML
#pragma once

#include "app/exercise/exercise_answers.h"
#include "app/exercise/exercise_draw.h"
#include "app/exercise/exercise_spec.h"
#include "app/exercise/exercise_worksheet.h"
#include "app/exercise/value_grid.h"
