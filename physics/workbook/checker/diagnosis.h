// Which mistake a wrong answer shows (issue 21 item 2): a model is named with
// confidence only when the student's own answers support it.
//
// The candidates are the mistake models (mistakes.h) whose number the answer is. A
// candidate is
//   dropped    when an answer the student got right, among those this one is computed
//              from (its "through" quantities: omega from I^-1 and L, L from q, ...),
//              would be wrong under it: the file contradicts it;
//   possible   when another candidate gives the same number ("several mistakes give
//              this number"), when it fits only through a quantity it changes that the
//              student did not write, or when it does not give a wrong answer the
//              student wrote among those through quantities;
//   confident  otherwise.
#pragma once

#include "physics/workbook/checker/checker.h"

#include <string_view>
#include <vector>

namespace rbw::checking {

// The quantities `id` is computed from in one explicit Euler step or one contact,
// directly or through others (omega: I^-1, R, r, I0^-1, I0, L, q).
std::vector<std::string_view> throughQuantities(std::string_view id);

struct Diagnosis {
    std::vector<const char*> mistakes;
    std::vector<PossibleMistake> possible;
};

// The diagnosis of answers[which] (verdict wrong) from every answer of the file and its
// verdict.
Diagnosis diagnose(const World& before, const StepTrace& trace, const std::vector<Answer>& answers,
                   const std::vector<Verdict>& verdicts, size_t which, double rel);

} // namespace rbw::checking
