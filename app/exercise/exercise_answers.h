// The answer key of a drawn exercise as answers (docs/checker.md): the entries of the
// physics' trace of the lesson's step that the exercise asks for, each with its body,
// index or contact; `rbw check` accepts the key with exit 0.
#pragma once

#include "app/exercise/exercise_draw.h"
#include "physics/workbook/checker/checker.h"

#include <QByteArray>

#include <vector>

namespace rbw {

std::vector<Answer> exerciseAnswers(const GeneratedExercise& g);

// The key as an answers file (answers_file.h).
QByteArray exerciseAnswersJson(const GeneratedExercise& g);

} // namespace rbw
