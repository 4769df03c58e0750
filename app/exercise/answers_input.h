// What `rbw check` and the app's check panel accept as a student's answers file, in one
// code path (issue 22 item 5): both call readAnswersInput() and answersProblems(), so
// the panel refuses exactly what `rbw check` refuses, with the same message.
//   - every input file is read up to kMaxInputFileBytes (1 MiB), no more;
//   - the file's form (answers_file.h), duplicate keys with their JSON path, and at
//     least one answer;
//   - the step: below the scene's "steps" (the limit is in the message), refused before
//     anything is simulated;
//   - each answer against the trace of its step (answerProblem), with a hint for the
//     slips students make: a probe index missing or counted per body.
// StepStates simulates a scene once for a whole marking sheet: the world before each
// asked step and that step's trace. slipHint() and stepSlipHint() name the input slips
// checked answers show (a quaternion written [x, y, z, w], steps counted from 1).
#pragma once

#include "app/exercise/answers_file.h"
#include "physics/engine/world.h"
#include "physics/workbook/checker/checker.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace rbw {

// The most bytes read from any input file of `rbw check` or the check panel.
constexpr qint64 kMaxInputFileBytes = qint64(1) << 20;

// Reads a regular file of at most `limit` bytes (a larger file, /dev/zero, a FIFO that
// never ends: refused after reading limit + 1 bytes). False with "path: reason".
bool readInputFile(const QString& path, QByteArray* out, QString* error, qint64 limit = kMaxInputFileBytes);

// A text from the input, safe in a message: control characters as \n, \t or \xNN, at
// most `max` characters (then "…").
QString shownText(const QString& s, int max = 80);

struct AnswersInput {
    AnswersFile file;
    long step = 0;        // the option's step, else the file's, else 0
    QStringList errors;   // "label: path: reason"
    bool ok() const { return errors.isEmpty(); }
};

// Form, duplicate keys, no answers, the step's limit. Nothing is simulated.
AnswersInput readAnswersInput(const QByteArray& json, const QString& label, const SceneDef& scene,
                              std::optional<long> stepOption = std::nullopt);

// Each answer against its step's trace: "label: answers[i]: problem (hint)".
QStringList answersProblems(const AnswersInput& in, const StepTrace& trace, const SceneDef& scene, const QString& label);

// The world before each asked step and the step's trace, from one simulation.
class StepStates {
public:
    explicit StepStates(const SceneDef& scene) : scene_(scene) {}
    // Simulates from t = 0 to the largest asked step, once. False with the blow-up
    // message (the step it stopped in).
    bool prepare(std::vector<long> steps, QString* error);
    bool has(long step) const { return states_.count(step) != 0; }
    const StepTrace& trace(long step) const { return states_.at(step).trace; }
    // A world standing before `step` (a fresh world restored from the snapshot).
    std::unique_ptr<World> worldBefore(long step) const;
    // How many runs from t = 0 prepare() has made (one per call that needed a new step):
    // what a marking sheet costs (tst_step_states).
    int simulations() const { return simulations_; }

private:
    struct State {
        WorldSnapshot before;
        StepTrace trace;
    };
    SceneDef scene_;
    std::map<long, State> states_;
    int simulations_ = 0;
};

// A hint for a checked answer that shows an input slip, or empty: a wrong quaternion
// that is right as [x, y, z, w] ("quaternions are [w, x, y, z]").
QString slipHint(const Answer& a, const AnswerResult& r, double tolerance);

// Steps counted from 1: not every answer right in `step`, but every one right in step
// k - 1 ("steps count from 0: did you mean step 0? (every answer is right for step 0)"),
// or empty. `states` must hold step k - 1 (StepStates::prepare); without it, empty.
// rbw check and the check panel both call it.
QString stepSlipHint(const std::vector<Answer>& answers, const std::vector<AnswerResult>& results, long step,
                     const StepStates& states, double tolerance);

} // namespace rbw
