// Checking a student's numbers for one step (issues 10 and 21). The workbook's own
// numbers are the trace of that step; an answer is
//   correct              within the tolerance of the workbook's number, or of the number
//                        recomputed from the student's own earlier (correct but rounded)
//                        answers, with their rounding carried into the tolerance;
//   imprecise            right to 3 significant figures but not within the tolerance:
//                        precision is not a mistake, and it counts as correct;
//   follows-from-earlier wrong, but what the student's own earlier wrong answers give
//                        (error carried forward: a marker's follow-through mark), by the
//                        rules of follow_through.h;
//   wrong                neither.
// A wrong answer names a mistake model (mistakes.h) in `mistakes` only when the
// student's own answers support it; models that only may explain it are in
// `possibleMistakes`, each with its reason (diagnosis.h).
//
// Tolerances (tolerance.h): an answer v matches a reference e when |v_i - e_i| <= tol for
// every component, tol = rel * max_j |e_j| + (the rounding carried in). The rounding of a
// student's input u is rel * max_j |u_j| per component (half a unit of its third figure
// for an imprecise one); what a recomputation inherits from it is propagated to first
// order, by perturbing each input component by its rounding and summing the changes.
//
// A separating contact (v_rel . n > 0) has no impulse: its J is checked against 0.
#pragma once

#include "physics/workbook/checker/mistakes.h"
#include "physics/engine/trace.h"

#include <string>
#include <vector>

namespace rbw {

class World;

struct Answer {
    std::string quantity;   // a trace id, e.g. "angular_velocity"
    int body = -1;          // for body quantities
    int contact = -1;       // for contact quantities
    int index = -1;         // which force / probe (point_velocity 1 ...)
    std::vector<double> value;   // flattened: 1, 3, 4 ([w, x, y, z]) or 9 (row by row) numbers
};

enum class Verdict { Correct, Wrong, FollowsFromEarlier, Imprecise };
const char* verdictName(Verdict v);   // "correct", "wrong", "follows-from-earlier", "imprecise"
// Correct and imprecise: the exit status and the marks treat both as right.
bool countsAsCorrect(Verdict v);

// A mistake that may give the number, and why it is not named with confidence.
struct PossibleMistake {
    const char* id;
    std::string reason;   // "several mistakes give this number", "it fits only through ..."
};

struct AnswerResult {
    Verdict verdict = Verdict::Wrong;
    std::vector<double> expected;         // the workbook's number (flattened)
    std::vector<const char*> mistakes;    // mistakes the student's answers support (confident)
    std::vector<PossibleMistake> possibleMistakes;
    std::string explanation;              // one or two sentences for the student
};

// The workbook's number for an answer (flattened): its trace entry's value, or J = 0 for
// the impulse of a separating contact (v_rel . n > 0: no impulse, which the trace does not
// record); empty when the step has no such number. What every answer is checked against,
// and what an exercise's key writes for a separating contact (app/exercise/exercise_draw.h).
std::vector<double> expectedValue(const StepTrace& trace, const Answer& a);

// The problems of an answer that cannot be checked at all (unknown quantity, no such
// body or contact in this step, wrong number of components); empty when it can.
std::string answerProblem(const StepTrace& trace, const Answer& a);

// Checks the answers against the step whose trace is given; `before` is the world as it
// was at the start of that step (its state, scene and forces). Answers that have a
// problem (answerProblem) must be rejected before.
std::vector<AnswerResult> checkAnswers(const World& before, const StepTrace& trace, const std::vector<Answer>& answers,
                                       double relTol = 1e-3);

} // namespace rbw
