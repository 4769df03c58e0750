// A student's answers for one step (rbw check, the app's "Check my numbers"):
//   { "step": 0,
//     "answers": [
//       { "quantity": "angular_velocity", "body": "box", "value": [-2.4, 4.918, -1.765] },
//       { "quantity": "point_velocity", "body": "box", "index": 1, "value": [3.11, 1.07, -2.68] },
//       { "quantity": "impulse", "contact": 0, "value": 2.37 } ] }
// Values are a number, a vector [x, y, z], a quaternion [w, x, y, z] or a 3x3 matrix as
// three rows. Quantity ids are the trace's (rbw quantities). Reading checks the file's
// form and resolves body names; whether an answer fits the step (the quantity exists
// there, the shape) is checked against the step's trace by answerProblem().
#pragma once

#include "physics/workbook/checker/checker.h"
#include "physics/engine/scene.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace rbw {

struct AnswersFile {
    std::optional<long> step;        // "step", if the file gives one
    std::vector<Answer> answers;
    std::vector<QString> paths;      // per answer: its JSON path, "answers[2]"
    QStringList errors;              // "file: path: reason"; empty on success
    bool ok() const { return errors.isEmpty(); }
};

AnswersFile loadAnswersFile(const QString& filePath, const SceneDef& scene);
AnswersFile parseAnswers(const QByteArray& json, const QString& fileLabel, const SceneDef& scene);

// The answers as a file again (the app saves what a student typed).
QByteArray answersToJson(const std::vector<Answer>& answers, long step, const SceneDef& scene);

} // namespace rbw
