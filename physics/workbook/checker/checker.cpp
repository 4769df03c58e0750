#include "physics/workbook/checker/checker.h"

#include "physics/engine/integrators/explicit_euler.h"
#include "physics/engine/quantities.h"
#include "physics/engine/world.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <tuple>

namespace rbw {

const char* verdictName(Verdict v)
{
    switch (v) {
    case Verdict::Correct: return "correct";
    case Verdict::Wrong: return "wrong";
    case Verdict::FollowsFromEarlier: return "follows-from-earlier";
    }
    return "?";
}

namespace {

using Values = std::vector<double>;

Vec3 vec(const Values& v) { return Vec3(v[0], v[1], v[2]); }
Mat3 mat(const Values& v)
{
    Mat3 m;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m(i, j) = v[3 * i + j];
    return m;
}
Values flatVec(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

double maxAbs(const Values& v)
{
    double m = 0.0;
    for (double x : v) m = std::max(m, std::abs(x));
    return m;
}

// |given_i - ref_i| <= rel * max|ref| + extra_i for every i (a quaternion also as -ref).
bool matches(const Values& given, const Values& ref, double rel, const Values& extra = {})
{
    if (given.size() != ref.size()) return false;
    auto within = [&](double sign) {
        const double tol = rel * maxAbs(ref);
        for (size_t i = 0; i < ref.size(); ++i) {
            const double allowed = tol + (extra.empty() ? 0.0 : extra[i]);
            if (!(std::abs(given[i] - sign * ref[i]) <= allowed)) return false;
        }
        return true;
    };
    return within(1.0) || (ref.size() == 4 && within(-1.0));
}

// The trace entry an answer is about.
const TraceEntry* entryFor(const StepTrace& trace, const std::string& id, int body, int contact, int index)
{
    for (const TraceEntry& e : trace.entries) {
        if (id != e.info->id) continue;
        if (contact >= 0) {
            if (e.info->indexKind == IndexKind::Contact && e.index == contact) return &e;
            continue;
        }
        if (e.body == body && e.index == index) return &e;
    }
    return nullptr;
}

// A value the recomputation reads: the student's (with its rounding) or the workbook's.
struct Val {
    Values v;
    Values err;              // rounding carried in, per component
    bool student = false;    // some student answer went into it
    bool studentWrong = false;
    bool ok = false;
};

struct Key {
    std::string id;
    int body, contact, index;
    bool operator<(const Key& o) const
    {
        return std::tie(id, body, contact, index) < std::tie(o.id, o.body, o.contact, o.index);
    }
};

struct Given {
    Values value;
    bool correct;
};

// A recomputation rule: the quantity `id` from `inputs` (same body or contact).
struct Rule {
    const char* id;
    std::vector<std::pair<const char*, int>> inputs;   // (id, index; -2: the answer's own index)
    std::function<Values(const std::vector<Values>&)> f;
};

class Checker {
public:
    Checker(const World& before, const StepTrace& trace, double rel) : w_(before), t_(trace), rel_(rel) {}

    AnswerResult check(const Answer& a)
    {
        AnswerResult r;
        const TraceEntry* e = entryFor(t_, a.quantity, a.body, a.contact, a.index);
        r.expected = traceValueComponents(e->value);
        const Key key{a.quantity, a.contact >= 0 ? -1 : a.body, a.contact, a.index};
        if (matches(a.value, r.expected, rel_)) {
            r.verdict = Verdict::Correct;
            r.explanation = "Right.";
        } else {
            // Recomputed from the student's own earlier answers.
            const Val re = recompute(key, 0);
            if (re.ok && re.student && matches(a.value, re.v, rel_, re.err)) {
                r.verdict = re.studentWrong ? Verdict::FollowsFromEarlier : Verdict::Correct;
                r.explanation = re.studentWrong
                                    ? "Not the workbook's number, but it is what your earlier wrong answers give: "
                                      "correct those and this one follows."
                                    : "Right, up to the rounding of your earlier answers.";
            } else {
                r.verdict = Verdict::Wrong;
                r.mistakes = mistakesMatching(a);
                if (!r.mistakes.empty()) {
                    r.explanation = findMistake(r.mistakes.front())->explanation;
                } else {
                    r.explanation = "This is not the workbook's number, and none of the common mistakes gives it.";
                }
            }
        }
        given_[key] = Given{a.value, r.verdict == Verdict::Correct};
        return r;
    }

private:
    // --- recomputation from earlier answers ---
    const std::vector<Rule>& rules() const
    {
        static const std::vector<Rule> all = [] {
            std::vector<Rule> r;
            // omega = I^-1 L
            r.push_back({q::angular_velocity.id,
                         {{q::inverse_inertia_world.id, -1}, {q::angular_momentum.id, -1}},
                         [](const std::vector<Values>& in) { return flatVec(mat(in[0]) * vec(in[1])); }});
            // v_p = v + omega x (p - x)
            r.push_back({q::point_velocity.id,
                         {{q::linear_velocity.id, -1}, {q::angular_velocity.id, -1}, {q::probe_position.id, -2},
                          {q::position.id, -1}},
                         [](const std::vector<Values>& in) {
                             return flatVec(vec(in[0]) + vec(in[1]).cross(vec(in[2]) - vec(in[3])));
                         }});
            // v_rel = v_A(p) - v_B(p)
            r.push_back({q::relative_velocity.id,
                         {{q::velocity_a.id, -1}, {q::velocity_b.id, -1}},
                         [](const std::vector<Values>& in) { return flatVec(vec(in[0]) - vec(in[1])); }});
            // v_rel . n
            r.push_back({q::normal_velocity.id,
                         {{q::relative_velocity.id, -1}, {q::contact_normal.id, -1}},
                         [](const std::vector<Values>& in) { return Values{vec(in[0]).dot(vec(in[1]))}; }});
            // -(1 + c) v_rel . n
            r.push_back({q::numerator.id,
                         {{q::restitution.id, -1}, {q::normal_velocity.id, -1}},
                         [](const std::vector<Values>& in) { return Values{-(1.0 + in[0][0]) * in[1][0]}; }});
            // 1/M_A + 1/M_B + [.]_A + [.]_B
            r.push_back({q::denominator.id,
                         {{q::inv_mass_a.id, -1}, {q::inv_mass_b.id, -1}, {q::rotational_a.id, -1},
                          {q::rotational_b.id, -1}},
                         [](const std::vector<Values>& in) {
                             return Values{in[0][0] + in[1][0] + in[2][0] + in[3][0]};
                         }});
            // J = numerator / denominator
            r.push_back({q::impulse.id,
                         {{q::numerator.id, -1}, {q::denominator.id, -1}},
                         [](const std::vector<Values>& in) { return Values{in[0][0] / in[1][0]}; }});
            return r;
        }();
        return all;
    }

    // The value of `key` as the student's answers (given earlier) make it.
    Val recompute(const Key& key, int depth)
    {
        Val out;
        if (depth > 8) return out;
        const Rule* rule = nullptr;
        for (const Rule& r : rules()) {
            if (key.id == r.id) rule = &r;
        }
        if (rule == nullptr) return out;
        std::vector<Val> ins;
        for (const auto& [id, idx] : rule->inputs) {
            const Key k{id, key.body, key.contact, idx == -2 ? key.index : idx};
            Val v = valueOf(k, depth + 1);
            if (!v.ok) return out;
            ins.push_back(v);
        }
        std::vector<Values> args;
        for (const Val& v : ins) args.push_back(v.v);
        out.v = rule->f(args);
        out.err.assign(out.v.size(), 0.0);
        // First-order propagation of the inputs' rounding.
        for (size_t i = 0; i < ins.size(); ++i) {
            for (size_t j = 0; j < ins[i].err.size(); ++j) {
                if (ins[i].err[j] == 0.0) continue;
                std::vector<Values> moved = args;
                moved[i][j] += ins[i].err[j];
                const Values f2 = rule->f(moved);
                for (size_t c = 0; c < out.v.size(); ++c) out.err[c] += std::abs(f2[c] - out.v[c]);
            }
            out.student = out.student || ins[i].student;
            out.studentWrong = out.studentWrong || ins[i].studentWrong;
        }
        out.ok = true;
        return out;
    }

    Val valueOf(const Key& k, int depth)
    {
        Val v;
        const auto g = given_.find(k);
        if (g != given_.end()) {
            v.v = g->second.value;
            v.err.assign(v.v.size(), rel_ * maxAbs(v.v));   // the student's rounding
            v.student = true;
            v.studentWrong = !g->second.correct;
            v.ok = true;
            return v;
        }
        Val re = recompute(k, depth);
        if (re.ok && re.student) return re;
        const TraceEntry* e = entryFor(t_, k.id, k.body, k.contact, k.index);
        if (e == nullptr) return v;
        v.v = traceValueComponents(e->value);
        v.err.assign(v.v.size(), 0.0);
        v.ok = true;
        return v;
    }

    // --- mistake models ---
    std::vector<const char*> mistakesMatching(const Answer& a) const
    {
        std::vector<const char*> out;
        if (a.contact >= 0) {
            const ContactInputs in = contactInputs(a.contact);
            for (const MistakeInfo& m : mistakeCatalogue()) {
                TraceValue v;
                if (handImpulse(in, m.mistake).value(a.quantity, v) && matches(a.value, traceValueComponents(v), rel_)) {
                    out.push_back(m.id);
                }
            }
            return out;
        }
        if (a.body < 0 || std::string_view(w_.integratorOf(a.body).name()) != ExplicitEuler::kName) {
            return out;   // the models are hand calculations of the explicit Euler step
        }
        const BodyStepInputs in = bodyInputs(a.body);
        for (const MistakeInfo& m : mistakeCatalogue()) {
            TraceValue v;
            if (handEulerStep(in, m.mistake).value(a.quantity, a.index, v) && matches(a.value, traceValueComponents(v), rel_)) {
                out.push_back(m.id);
            }
        }
        return out;
    }

    BodyStepInputs bodyInputs(int b) const
    {
        const SceneDef& scene = w_.scene();
        const BodyState& s = w_.states()[b];
        BodyStepInputs in;
        in.h = scene.dt;
        in.mass = scene.bodies[b].mass;
        in.size = scene.bodies[b].size;
        in.x_W = s.x_W;
        in.v_W = s.v_W;
        in.q_WB = s.q_WB;
        in.L_W = s.L_W;
        in.convention = w_.conventionOf(b);
        if (scene.hasGravity()) in.g_W = scene.g_W;
        const long k = w_.stepIndex();
        for (const ForceDef& f : scene.forces) {
            if (f.body == b && f.activeIn(k)) in.forces.push_back({f.p_W, f.f_W});
        }
        for (int j = 0; j < static_cast<int>(scene.torques.size()); ++j) {
            const TorqueDef& t = scene.torques[j];
            if (t.body == b && t.activeIn(k) && w_.torqueEnabled(j)) in.couple_W += t.q_W;
        }
        for (int i = 0; i < static_cast<int>(scene.probes.size()); ++i) {
            // probe i's index among all probes: body frame offset p_B = R^T (p - x)
            in.probes_B.push_back(scene.probes[i].body == b ? w_.worldToBody(b, w_.probe(i).p_W) : Vec3::Zero());
        }
        return in;
    }

    ContactInputs contactInputs(int k) const
    {
        ContactInputs in;
        const ContactHeader& h = t_.contacts[k];
        auto get = [&](const QuantityInfo& q) -> Values {
            const TraceEntry* e = entryFor(t_, q.id, -1, k, -1);
            return e != nullptr ? traceValueComponents(e->value) : Values{};
        };
        auto vecOr0 = [](const Values& v) { return v.size() == 3 ? vec(v) : Vec3(Vec3::Zero()); };
        in.g.p_W = vecOr0(get(q::contact_point));
        in.g.n_W = vecOr0(get(q::contact_normal));
        const Values c = get(q::restitution);
        in.restitution = c.empty() ? w_.scene().restitutionFor(h.bodyA, h.bodyB, h.plane) : c[0];
        // Point velocities as recorded (v_A(p) = v_A + omega_A x x_a): enter them as v, no spin.
        in.x_A = in.g.p_W - vecOr0(get(q::x_a));
        in.v_A = vecOr0(get(q::velocity_a));
        in.invM_A = w_.massProperties()[h.bodyA].invM;
        in.Iinv_A = inverseInertiaOf(h.bodyA);
        if (h.bodyB >= 0) {
            in.x_B = in.g.p_W - vecOr0(get(q::x_b));
            in.invM_B = w_.massProperties()[h.bodyB].invM;
            in.Iinv_B = inverseInertiaOf(h.bodyB);
        } else {
            in.x_B = in.g.p_W;
        }
        in.v_B = vecOr0(get(q::velocity_b));
        return in;
    }

    // I^-1 of a body in this step's contacts: the one after the integration (positions do
    // not change in the contact stages); zero for a fixed body or a particle response.
    Mat3 inverseInertiaOf(int b) const
    {
        if (w_.massProperties()[b].invM == 0.0 || !w_.scene().bodies[b].angularResponse) return Mat3::Zero();
        const TraceEntry* e = entryFor(t_, q::inverse_inertia_world.id, b, -1, -1);
        return e != nullptr ? mat(traceValueComponents(e->value)) : Mat3(Mat3::Zero());
    }

    const World& w_;
    const StepTrace& t_;
    double rel_;
    std::map<Key, Given> given_;
};

} // namespace

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
    const TraceEntry* e = entryFor(trace, a.quantity, a.body, a.contact, a.index);
    if (e == nullptr) {
        return "the workbook has no " + a.quantity + (a.index >= 0 ? " " + std::to_string(a.index) : std::string()) +
               " for this " + (a.contact >= 0 ? "contact" : "body") + " in step " + std::to_string(trace.step);
    }
    const size_t n = traceValueComponents(e->value).size();
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
    Checker checker(before, trace, relTol);
    std::vector<AnswerResult> out;
    out.reserve(answers.size());
    for (const Answer& a : answers) out.push_back(checker.check(a));
    return out;
}

} // namespace rbw
