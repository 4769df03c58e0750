#include "physics/workbook/checker/checker.h"

#include "physics/workbook/checker/diagnosis.h"
#include "physics/workbook/checker/follow_through.h"
#include "physics/workbook/checker/tolerance.h"
#include "physics/engine/quantities.h"
#include "physics/engine/world.h"

namespace rbw {

const char* verdictName(Verdict v)
{
    switch (v) {
    case Verdict::Correct: return "correct";
    case Verdict::Wrong: return "wrong";
    case Verdict::FollowsFromEarlier: return "follows-from-earlier";
    case Verdict::Imprecise: return "imprecise";
    }
    return "?";
}

bool countsAsCorrect(Verdict v)
{
    return v == Verdict::Correct || v == Verdict::Imprecise;
}

namespace {

using checking::AnswerKey;
using checking::Values;

AnswerKey keyOf(const Answer& a)
{
    return AnswerKey{a.quantity, a.contact >= 0 ? -1 : a.body, a.contact, a.index};
}

// J of a separating contact (v_rel . n > 0): no impulse, which the trace does not record.
bool separatingImpulse(const StepTrace& t, const Answer& a)
{
    return a.quantity == q::impulse.id && a.contact >= 0 && a.contact < static_cast<int>(t.contacts.size()) &&
           t.contacts[a.contact].separating;
}

// "torque", "torque and angular_momentum", "torque, I0 and r"
std::string listed(const std::vector<std::string>& names)
{
    std::string s;
    for (size_t i = 0; i < names.size(); ++i) {
        s += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    }
    return s;
}

std::string followsText(const std::vector<AnswerKey>& from)
{
    std::vector<std::string> names;
    for (const AnswerKey& k : from) names.push_back(k.name());
    const bool one = names.size() == 1;
    return "Not the workbook's number, but it follows from your earlier " + listed(names) + ": it is what " +
           (one ? "that answer gives" : "those answers give") + ". Correct " + (one ? "that one" : "those") +
           " and this one follows.";
}

// The explanation of a named mistake for the answer's body (its inertia convention).
std::string explanationOf(const char* id, const World& w, const Answer& a)
{
    const InertiaConvention c = a.contact < 0 && a.body >= 0 ? w.conventionOf(a.body) : InertiaConvention::Standard;
    return mistakeExplanation(*findMistake(id), c);
}

std::string wrongText(const AnswerResult& r, const World& w, const Answer& a)
{
    if (r.mistakes.size() > 1) {
        std::string s = "Two mistakes together give this number (no one of them alone does):";
        for (const char* id : r.mistakes) s += std::string(" ") + id + ": " + explanationOf(id, w, a);
        return s;
    }
    if (!r.mistakes.empty()) return explanationOf(r.mistakes.front(), w, a);
    // One pair, only possible: each id "only together with" the other, then why (diagnosis.cpp).
    if (r.possibleMistakes.size() == 2) {
        const PossibleMistake& p = r.possibleMistakes[0];
        const std::string head = std::string("only together with ") + r.possibleMistakes[1].id + "; ";
        if (p.reason.rfind(head, 0) == 0 && p.reason.find("several mistakes") == std::string::npos) {
            return std::string("It may be two mistakes together, ") + p.id + " and " + r.possibleMistakes[1].id +
                   ", but " + p.reason.substr(head.size()) + ": " + explanationOf(p.id, w, a) + " " +
                   explanationOf(r.possibleMistakes[1].id, w, a);
        }
    }
    if (r.possibleMistakes.size() > 1) {
        std::vector<std::string> ids;
        for (const PossibleMistake& p : r.possibleMistakes) ids.push_back(p.id);
        return "Several mistakes give this number: " + listed(ids) + ". Your other answers do not tell which.";
    }
    if (r.possibleMistakes.size() == 1) {
        const PossibleMistake& p = r.possibleMistakes.front();
        return std::string("It may be ") + p.id + ", but " + p.reason + ": " + explanationOf(p.id, w, a);
    }
    return "This is not the workbook's number, and none of the common mistakes gives it.";
}

} // namespace

std::vector<double> expectedValue(const StepTrace& trace, const Answer& a)
{
    const TraceEntry* e = checking::traceEntryOf(trace, keyOf(a));
    if (e != nullptr) return traceValueComponents(e->value);
    return separatingImpulse(trace, a) ? Values{0.0} : Values{};
}

std::string answerProblem(const StepTrace& trace, const Answer& a)
{
    const QuantityInfo* info = findQuantity(a.quantity);
    if (info == nullptr) return "unknown quantity \"" + a.quantity + "\" (rbw quantities lists them)";
    if (info->indexKind == IndexKind::Contact && a.contact < 0) return "a contact quantity needs \"contact\"";
    if (info->indexKind != IndexKind::Contact && a.contact >= 0) return "\"" + a.quantity + "\" is not a contact quantity";
    if (a.contact >= 0 && a.contact >= static_cast<int>(trace.contacts.size())) {
        return "no contact " + std::to_string(a.contact) + " in step " + std::to_string(trace.step) + " (it has " +
               std::to_string(trace.contacts.size()) + ")";
    }
    const Values expected = expectedValue(trace, a);
    if (expected.empty()) {
        return "the workbook has no " + a.quantity + (a.index >= 0 ? " " + std::to_string(a.index) : std::string()) +
               " for this " + (a.contact >= 0 ? "contact" : "body") + " in step " + std::to_string(trace.step);
    }
    const size_t n = expected.size();
    if (a.value.size() != n) {
        const char* shape = n == 1 ? "a number" : n == 3 ? "a vector of 3 numbers" : n == 4 ? "a quaternion [w, x, y, z]"
                                                                                           : "a 3x3 matrix (3 rows of 3)";
        return "\"" + a.quantity + "\" is " + shape + ", got " + std::to_string(a.value.size()) + " numbers";
    }
    return {};
}

std::vector<AnswerResult> checkAnswers(const World& before, const StepTrace& trace, const std::vector<Answer>& answers,
                                       double relTol)
{
    checking::FollowThrough follow(before, trace);
    std::vector<AnswerResult> out;
    std::vector<Verdict> verdicts;
    out.reserve(answers.size());
    // In the file's order: the answers above one are its earlier answers.
    for (const Answer& a : answers) {
        AnswerResult r;
        r.expected = expectedValue(trace, a);
        const AnswerKey key = keyOf(a);
        checking::GivenAnswer given{a.value, Values(a.value.size(), relTol * checking::maxAbs(a.value)), false, {}};
        const bool right = checking::matches(a.value, r.expected, relTol);
        const checking::Recomputed re = right ? checking::Recomputed{} : follow.recompute(key);
        if (right) {
            r.verdict = Verdict::Correct;
            r.explanation = "Right.";
        } else if (re.ok && re.student && checking::matches(a.value, re.v, relTol, re.err)) {
            // Recomputed from the student's own earlier answers.
            if (re.wrongFrom.empty()) {
                r.verdict = Verdict::Correct;
                r.explanation = "Right, up to the rounding of your earlier answers.";
            } else {
                r.verdict = Verdict::FollowsFromEarlier;
                r.explanation = followsText(re.wrongFrom);
                given.wrongFrom = re.wrongFrom;
            }
        } else if (checking::rightToThreeFigures(a.value, r.expected)) {
            r.verdict = Verdict::Imprecise;
            r.explanation = "Right to 3 significant figures; write 4 for the check.";
            given.rounding.assign(a.value.size(), checking::threeFigureHalfUnit(r.expected));
        } else {
            r.verdict = Verdict::Wrong;
            given.wrongFrom = {key};
        }
        given.right = countsAsCorrect(r.verdict);
        follow.give(key, std::move(given));
        verdicts.push_back(r.verdict);
        out.push_back(std::move(r));
    }
    // Which mistake a wrong answer shows, with every answer of the file known.
    for (size_t i = 0; i < out.size(); ++i) {
        if (out[i].verdict != Verdict::Wrong) continue;
        checking::Diagnosis d = checking::diagnose(before, trace, answers, verdicts, i, relTol);
        out[i].mistakes = std::move(d.mistakes);
        out[i].possibleMistakes = std::move(d.possible);
        out[i].explanation = wrongText(out[i], before, answers[i]);
    }
    return out;
}

} // namespace rbw
