// Checking a student's numbers for one step (issue 10). The workbook's own numbers are
// the trace of that step; an answer is
//   correct              within the tolerance of the workbook's number, or of the number
//                        recomputed from the student's own earlier (correct but rounded)
//                        answers, with their rounding carried into the tolerance;
//   follows-from-earlier wrong, but what the student's own earlier wrong answers give
//                        (error carried forward: a marker's follow-through mark);
//   wrong                neither.
// A wrong answer lists every mistake model (mistakes.h) whose value it matches.
//
// Tolerances: an answer v matches a reference e when |v_i - e_i| <= tol for every
// component, tol = rel * max_j |e_j| + (the rounding carried in). The rounding of a
// student's input u is rel * max_j |u_j| per component; what a recomputation inherits
// from it is propagated to first order, by perturbing each input component by its
// rounding and summing the absolute changes.
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

enum class Verdict { Correct, Wrong, FollowsFromEarlier };
const char* verdictName(Verdict v);   // "correct", "wrong", "follows-from-earlier"

struct AnswerResult {
    Verdict verdict = Verdict::Wrong;
    std::vector<double> expected;         // the workbook's number (flattened)
    std::vector<const char*> mistakes;    // ids of the mistake models the answer matches
    std::string explanation;              // one or two sentences for the student
};

// The problems of an answer that cannot be checked at all (unknown quantity, no such
// body or contact in this step, wrong number of components); empty when it can.
std::string answerProblem(const StepTrace& trace, const Answer& a);

// Checks the answers against the step whose trace is given; `before` is the world as it
// was at the start of that step (its state, scene and forces). Answers that have a
// problem (answerProblem) must be rejected before.
std::vector<AnswerResult> checkAnswers(const World& before, const StepTrace& trace, const std::vector<Answer>& answers,
                                       double relTol = 1e-3);

} // namespace rbw
