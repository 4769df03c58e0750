#include "physics/workbook/checker/diagnosis.h"

#include "physics/workbook/checker/follow_through.h"
#include "physics/workbook/checker/model_inputs.h"
#include "physics/workbook/checker/tolerance.h"
#include "physics/engine/integrators/explicit_euler.h"
#include "physics/engine/quantities.h"
#include "physics/engine/world.h"

#include <algorithm>
#include <functional>
#include <utility>

namespace rbw::checking {

namespace {

// What each quantity of the hand calculations is computed from, directly.
const std::vector<std::pair<std::string_view, std::vector<std::string_view>>>& directInputs()
{
    static const std::vector<std::pair<std::string_view, std::vector<std::string_view>>> all = {
        {q::inverse_inertia_body.id, {q::inertia_body.id}},
        {q::linear_velocity.id, {q::force.id}},
        {q::angular_momentum.id, {q::torque.id}},
        {q::rotation_matrix.id, {q::orientation.id}},
        {q::inverse_inertia_world.id, {q::rotation_matrix.id, q::inverse_inertia_body.id}},
        {q::inverse_inertia_world_template.id, {q::rotation_matrix.id, q::inverse_inertia_body.id}},
        {q::angular_velocity.id,
         {q::inverse_inertia_world.id, q::inverse_inertia_world_template.id, q::angular_momentum.id}},
        {q::probe_position.id, {q::position.id, q::rotation_matrix.id}},
        {q::point_velocity.id, {q::linear_velocity.id, q::angular_velocity.id, q::probe_position.id, q::position.id}},
        {q::velocity_a.id, {q::x_a.id}},
        {q::velocity_b.id, {q::x_b.id}},
        {q::relative_velocity.id, {q::velocity_a.id, q::velocity_b.id}},
        {q::normal_velocity.id, {q::relative_velocity.id}},
        {q::numerator.id, {q::normal_velocity.id}},
        {q::rotational_a.id, {q::x_a.id}},
        {q::rotational_b.id, {q::x_b.id}},
        {q::denominator.id, {q::rotational_a.id, q::rotational_b.id}},
        {q::impulse.id, {q::numerator.id, q::denominator.id}},
    };
    return all;
}

// A model's value of a quantity (false: the model does not compute it).
using ModelValue = std::function<bool(Mistake, int variant, const std::string& id, int index, Values& out)>;

struct Candidate {
    const MistakeInfo* info;
    std::vector<std::string> notGiven;    // wrong answers of the student it does not give
    std::vector<std::string> unwritten;   // quantities it changes that the student did not write
};

void addOnce(std::vector<std::string>& list, const std::string& s)
{
    if (std::find(list.begin(), list.end(), s) == list.end()) list.push_back(s);
}

// "a", "a and b", "a, b and c"
std::string listed(const std::vector<std::string>& names)
{
    std::string s;
    for (size_t i = 0; i < names.size(); ++i) {
        s += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    }
    return s;
}

std::string reasonOf(const Candidate& c, bool several)
{
    std::vector<std::string> parts;
    if (several) parts.push_back("several mistakes give this number");
    if (!c.notGiven.empty()) parts.push_back("it does not give your " + listed(c.notGiven));
    if (!c.unwritten.empty()) {
        parts.push_back("it fits only through " + listed(c.unwritten) + ", which you did not write");
    }
    std::string s;
    for (const std::string& p : parts) s += (s.empty() ? "" : "; ") + p;
    return s;
}

} // namespace

std::vector<std::string_view> throughQuantities(std::string_view id)
{
    std::vector<std::string_view> out;
    std::vector<std::string_view> todo{id};
    while (!todo.empty()) {
        const std::string_view q = todo.back();
        todo.pop_back();
        for (const auto& [of, inputs] : directInputs()) {
            if (of != q) continue;
            for (std::string_view in : inputs) {
                if (std::find(out.begin(), out.end(), in) == out.end()) {
                    out.push_back(in);
                    todo.push_back(in);
                }
            }
        }
    }
    return out;
}

Diagnosis diagnose(const World& w, const StepTrace& t, const std::vector<Answer>& answers,
                   const std::vector<Verdict>& verdicts, size_t which, double rel)
{
    Diagnosis d;
    const Answer& a = answers[which];
    ModelValue value;
    if (a.contact >= 0) {
        const ContactInputs in = contactStepInputs(w, t, a.contact);
        value = [in](Mistake m, int, const std::string& id, int, Values& out) {
            TraceValue v;
            if (!handImpulse(in, m).value(id, v)) return false;
            out = traceValueComponents(v);
            return true;
        };
    } else if (a.body >= 0 && std::string_view(w.integratorOf(a.body).name()) == ExplicitEuler::kName) {
        // the body models are hand calculations of the explicit Euler step
        const BodyStepInputs in = bodyStepInputs(w, a.body);
        value = [in](Mistake m, int variant, const std::string& id, int index, Values& out) {
            TraceValue v;
            if (!handEulerStep(in, m, variant).value(id, index, v)) return false;
            out = traceValueComponents(v);
            return true;
        };
    } else {
        return d;
    }
    const auto sameSubject = [&](const Answer& g) {
        return a.contact >= 0 ? g.contact == a.contact : (g.contact < 0 && g.body == a.body);
    };
    const std::vector<std::string_view> through = throughQuantities(a.quantity);
    const auto isThrough = [&](const std::string& id) {
        return std::find(through.begin(), through.end(), id) != through.end();
    };

    std::vector<Candidate> candidates;
    for (const MistakeInfo& m : mistakeCatalogue()) {
        // A model with variants (which two axes are swapped) is a candidate through any.
        for (int variant = 0; variant < m.variants; ++variant) {
            Values mine;
            if (!value(m.mistake, variant, a.quantity, a.index, mine) || !matches(a.value, mine, rel)) continue;
            Candidate c{&m, {}, {}};
            bool contradicted = false;
            const auto changes = [&](const std::string& id, int index) {
                Values wrong, right;
                if (!value(m.mistake, variant, id, index, wrong) || !value(Mistake::None, 0, id, index, right)) {
                    return false;
                }
                return !matches(wrong, right, rel);
            };
            // The student's answers this one is computed from.
            for (size_t i = 0; i < answers.size(); ++i) {
                const Answer& g = answers[i];
                if (i == which || !sameSubject(g) || !isThrough(g.quantity)) continue;
                const bool right = verdicts[i] == Verdict::Correct || verdicts[i] == Verdict::Imprecise;
                Values theirs;
                if (!value(m.mistake, variant, g.quantity, g.index, theirs)) continue;
                if (right && changes(g.quantity, g.index)) {
                    contradicted = true;   // "your q is right": the file contradicts the model
                } else if (!right && !matches(g.value, theirs, rel)) {
                    addOnce(c.notGiven, g.quantity);
                }
            }
            if (contradicted) continue;
            // What it changes on the way that the student did not write.
            for (std::string_view q : through) {
                const std::string id(q);
                const int index = id == q::probe_position.id ? a.index : -1;
                // only what the workbook traces for this body or contact (one of I^-1's two rows)
                const AnswerKey key{id, a.contact >= 0 ? -1 : a.body, a.contact, index};
                if (traceEntryOf(t, key) == nullptr) continue;
                const bool written = std::any_of(answers.begin(), answers.end(), [&](const Answer& g) {
                    return sameSubject(g) && g.quantity == id;
                });
                if (!written && changes(id, index)) {
                    addOnce(c.unwritten, id);
                }
            }
            const bool seen = std::any_of(candidates.begin(), candidates.end(),
                                          [&](const Candidate& o) { return o.info == &m; });
            if (!seen) candidates.push_back(std::move(c));
            break;
        }
    }
    if (candidates.size() == 1 && candidates.front().notGiven.empty() && candidates.front().unwritten.empty()) {
        d.mistakes.push_back(candidates.front().info->id);
        return d;
    }
    for (const Candidate& c : candidates) d.possible.push_back(PossibleMistake{c.info->id, reasonOf(c, candidates.size() > 1)});
    return d;
}

} // namespace rbw::checking
