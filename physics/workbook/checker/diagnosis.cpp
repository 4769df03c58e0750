#include "physics/workbook/checker/diagnosis.h"

#include "physics/workbook/checker/follow_through.h"
#include "physics/workbook/checker/model_inputs.h"
#include "physics/workbook/checker/tolerance.h"
#include "physics/engine/integrators/explicit_euler.h"
#include "physics/engine/quantities.h"
#include "physics/engine/world.h"

#include <algorithm>
#include <functional>
#include <optional>
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
using ModelValue = std::function<bool(const MistakeSet&, const std::string& id, int index, Values& out)>;

struct Candidate {
    std::vector<const MistakeInfo*> infos;   // one model, or a pair
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

std::string reasonOf(const Candidate& c, const MistakeInfo& self, bool several)
{
    std::vector<std::string> parts;
    for (const MistakeInfo* other : c.infos) {
        if (other != &self) parts.push_back(std::string("only together with ") + other->id);
    }
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

namespace {

// Everything diagnose() needs to judge one candidate against the student's file.
struct Judge {
    const ModelValue& value;
    const std::vector<Answer>& answers;
    const std::vector<Verdict>& verdicts;
    size_t which;
    double rel;
    const StepTrace& t;
    std::vector<std::string_view> through;

    bool sameSubject(const Answer& g) const
    {
        const Answer& a = answers[which];
        return a.contact >= 0 ? g.contact == a.contact : (g.contact < 0 && g.body == a.body);
    }
    bool isThrough(const std::string& id) const
    {
        return std::find(through.begin(), through.end(), id) != through.end();
    }
    // The model's value of `id` differs from the right one.
    bool changes(const MistakeSet& ms, const std::string& id, int index) const
    {
        Values wrong, right;
        if (!value(ms, id, index, wrong) || !value(MistakeSet{}, id, index, right)) return false;
        return !matches(wrong, right, rel);
    }

    // The candidate `ms` if it gives the answer and the file does not contradict it.
    std::optional<Candidate> judge(const MistakeSet& ms, std::vector<const MistakeInfo*> infos) const
    {
        const Answer& a = answers[which];
        Values mine;
        if (!value(ms, a.quantity, a.index, mine) || !matches(a.value, mine, rel)) return std::nullopt;
        Candidate c{std::move(infos), {}, {}};
        // The student's answers this one is computed from.
        for (size_t i = 0; i < answers.size(); ++i) {
            const Answer& g = answers[i];
            if (i == which || !sameSubject(g) || !isThrough(g.quantity)) continue;
            const bool right = verdicts[i] == Verdict::Correct || verdicts[i] == Verdict::Imprecise;
            Values theirs;
            if (!value(ms, g.quantity, g.index, theirs)) continue;
            if (right && changes(ms, g.quantity, g.index)) return std::nullopt;   // "your q is right": contradicted
            if (!right && !matches(g.value, theirs, rel)) addOnce(c.notGiven, g.quantity);
        }
        // What it changes on the way that the student did not write.
        for (std::string_view q : through) {
            const std::string id(q);
            const int index = id == q::probe_position.id ? a.index : -1;
            // only what the workbook traces for this body or contact (one of I^-1's two rows)
            const AnswerKey key{id, a.contact >= 0 ? -1 : a.body, a.contact, index};
            if (traceEntryOf(t, key) == nullptr) continue;
            const bool written = std::any_of(answers.begin(), answers.end(),
                                             [&](const Answer& g) { return sameSubject(g) && g.quantity == id; });
            if (!written && changes(ms, id, index)) addOnce(c.unwritten, id);
        }
        return c;
    }
};

// The models a one-step check can name (oneStep), each in every variant.
std::vector<std::pair<const MistakeInfo*, int>> oneStepModels()
{
    std::vector<std::pair<const MistakeInfo*, int>> all;
    for (const MistakeInfo& m : mistakeCatalogue()) {
        if (!m.oneStep) continue;
        for (int v = 0; v < m.variants; ++v) all.push_back({&m, v});
    }
    return all;
}

// Single models (a model with variants is a candidate through any one of them).
std::vector<Candidate> singleCandidates(const Judge& j)
{
    std::vector<Candidate> out;
    for (const auto& [m, variant] : oneStepModels()) {
        const bool seen = std::any_of(out.begin(), out.end(), [&](const Candidate& o) { return o.infos[0] == m; });
        if (seen) continue;
        if (std::optional<Candidate> c = j.judge(MistakeSet{m->mistake, Mistake::None, variant}, {m})) {
            out.push_back(std::move(*c));
        }
    }
    return out;
}

// Pairs of two different models (issue 21 item 1: mistakes combine); a pair that gives the
// same number as a model of it alone is that model's business (never reached: pairs are
// tried only when no single model gives the number).
std::vector<Candidate> pairCandidates(const Judge& j)
{
    std::vector<Candidate> out;
    const std::vector<std::pair<const MistakeInfo*, int>> models = oneStepModels();
    for (size_t i = 0; i < models.size(); ++i) {
        for (size_t k = i + 1; k < models.size(); ++k) {
            const auto& [a, va] = models[i];
            const auto& [b, vb] = models[k];
            if (a == b || (va > 0 && vb > 0)) continue;
            const bool seen = std::any_of(out.begin(), out.end(),
                                          [&](const Candidate& o) { return o.infos[0] == a && o.infos[1] == b; });
            if (seen) continue;
            if (std::optional<Candidate> c = j.judge(MistakeSet{a->mistake, b->mistake, std::max(va, vb)}, {a, b})) {
                out.push_back(std::move(*c));
            }
        }
    }
    return out;
}

} // namespace

Diagnosis diagnose(const World& w, const StepTrace& t, const std::vector<Answer>& answers,
                   const std::vector<Verdict>& verdicts, size_t which, double rel)
{
    Diagnosis d;
    const Answer& a = answers[which];
    ModelValue value;
    if (a.contact >= 0) {
        const ContactInputs in = contactStepInputs(w, t, a.contact);
        value = [in](const MistakeSet& ms, const std::string& id, int, Values& out) {
            TraceValue v;
            if (!handImpulse(in, ms).value(id, v)) return false;
            out = traceValueComponents(v);
            return true;
        };
    } else if (a.body >= 0 && std::string_view(w.integratorOf(a.body).name()) == ExplicitEuler::kName) {
        // the body models are hand calculations of the explicit Euler step
        const BodyStepInputs in = bodyStepInputs(w, a.body);
        value = [in](const MistakeSet& ms, const std::string& id, int index, Values& out) {
            TraceValue v;
            if (!handEulerStep(in, ms).value(id, index, v)) return false;
            out = traceValueComponents(v);
            return true;
        };
    } else {
        return d;
    }
    const Judge judge{value, answers, verdicts, which, rel, t, throughQuantities(a.quantity)};
    std::vector<Candidate> candidates = singleCandidates(judge);
    // A pair is considered only when no single model gives the number.
    if (candidates.empty()) candidates = pairCandidates(judge);
    if (candidates.size() == 1 && candidates.front().notGiven.empty() && candidates.front().unwritten.empty()) {
        for (const MistakeInfo* m : candidates.front().infos) d.mistakes.push_back(m->id);
        return d;
    }
    const bool several = candidates.size() > 1;
    for (const Candidate& c : candidates) {
        for (const MistakeInfo* m : c.infos) {
            const bool seen = std::any_of(d.possible.begin(), d.possible.end(),
                                          [&](const PossibleMistake& p) { return std::string_view(p.id) == m->id; });
            if (!seen) d.possible.push_back(PossibleMistake{m->id, reasonOf(c, *m, several)});
        }
    }
    return d;
}

} // namespace rbw::checking
