#include "physics/workbook/checker/follow_through.h"

#include "physics/engine/integrators/explicit_euler.h"
#include "physics/engine/quantities.h"
#include "physics/engine/world.h"

#include <algorithm>
#include <cmath>

namespace rbw::checking {

std::string AnswerKey::name() const
{
    return index >= 0 ? id + " #" + std::to_string(index) : id;
}

const TraceEntry* traceEntryOf(const StepTrace& trace, const AnswerKey& k)
{
    for (const TraceEntry& e : trace.entries) {
        if (k.id != e.info->id) continue;
        if (k.contact >= 0) {
            if (e.info->indexKind == IndexKind::Contact && e.index == k.contact) return &e;
            continue;
        }
        if (e.body == k.body && e.index == k.index) return &e;
    }
    return nullptr;
}

namespace {

struct Rule;

// What a rule may read besides its inputs: the workbook's numbers of the same body or
// contact, the scene (h, masses) and the rule itself.
struct RuleContext {
    const World& w;
    const StepTrace& t;
    const AnswerKey& key;
    const Rule& rule;

    Values traced(const char* id) const
    {
        const TraceEntry* e = traceEntryOf(t, AnswerKey{id, key.body, key.contact, -1});
        return e != nullptr ? traceValueComponents(e->value) : Values{};
    }
    int side(bool a) const
    {
        if (key.contact < 0 || key.contact >= static_cast<int>(t.contacts.size())) return -1;
        return a ? t.contacts[key.contact].bodyA : t.contacts[key.contact].bodyB;
    }
    // The body's I^-1 after the integration (the contact stages do not move bodies).
    Values inverseInertiaOf(int body) const
    {
        for (const QuantityInfo* q : {&q::inverse_inertia_world, &q::inverse_inertia_world_template}) {
            const TraceEntry* e = traceEntryOf(t, AnswerKey{q->id, body, -1, -1});
            if (e != nullptr) return traceValueComponents(e->value);
        }
        return {};
    }
};

using In = std::vector<Values>;

struct RuleInput {
    const char* id;
    int index = -1;          // -2: the answer's own index (a probe)
    bool optional = false;   // zero when neither written nor traced (no friction)
};

struct Rule {
    const char* id;
    std::vector<RuleInput> inputs;
    bool explicitEulerOnly;
    Values (*f)(const In&, const RuleContext&);   // empty: cannot be recomputed
};

// --- the rules, one equation each ---

// L' = L_n + h q: the workbook's L' moved by h times the student's change of q
Values angularMomentum(const In& in, const RuleContext& c)
{
    const Values L = c.traced(q::angular_momentum.id), q0 = c.traced(c.rule.inputs[0].id);
    if (L.size() != 3 || q0.size() != 3) return {};
    return flatVec(vecOf(L) + c.w.scene().dt * (vecOf(in[0]) - vecOf(q0)));
}

// v' = v_n + h F/M: likewise with F
Values linearVelocity(const In& in, const RuleContext& c)
{
    const Values v = c.traced(q::linear_velocity.id), F0 = c.traced(c.rule.inputs[0].id);
    if (v.size() != 3 || F0.size() != 3) return {};
    const double invM = c.w.massProperties()[c.key.body].invM;
    return flatVec(vecOf(v) + c.w.scene().dt * invM * (vecOf(in[0]) - vecOf(F0)));
}

// I0^-1 = (I0)^-1
Values inverseInertiaBody(const In& in, const RuleContext&)
{
    const Mat3 I0 = matOf(in[0]);
    if (!(std::abs(I0.determinant()) > 0.0)) return {};
    return flatMat(I0.inverse());
}

// R = R(r), r = [w, x, y, z] normalised
Values rotationMatrix(const In& in, const RuleContext&)
{
    Quat r(in[0][0], in[0][1], in[0][2], in[0][3]);
    if (!(r.norm() > 0.0)) return {};
    r.normalize();
    return flatMat(r.toRotationMatrix());
}

// I^-1 = R I0^-1 R^T (the template convention: R^T I0^-1 R)
Values inverseInertiaWorld(const In& in, const RuleContext& c)
{
    const Mat3 R = matOf(in[0]), I0inv = matOf(in[1]);
    if (c.w.conventionOf(c.key.body) == InertiaConvention::CourseTemplate) {
        return flatMat(R.transpose() * I0inv * R);
    }
    return flatMat(R * I0inv * R.transpose());
}

// omega = I^-1 L
Values angularVelocity(const In& in, const RuleContext&) { return flatVec(matOf(in[0]) * vecOf(in[1])); }

// v_p = v + omega x (p - x)
Values pointVelocity(const In& in, const RuleContext&)
{
    return flatVec(vecOf(in[0]) + vecOf(in[1]).cross(vecOf(in[2]) - vecOf(in[3])));
}

// v_rel = v_A(p) - v_B(p)
Values relativeVelocity(const In& in, const RuleContext&) { return flatVec(vecOf(in[0]) - vecOf(in[1])); }
// v_rel . n
Values normalVelocity(const In& in, const RuleContext&) { return {vecOf(in[0]).dot(vecOf(in[1]))}; }
// -(1 + c) v_rel . n
Values numerator(const In& in, const RuleContext&) { return {-(1.0 + in[0][0]) * in[1][0]}; }
// 1/M_A + 1/M_B + [.]_A + [.]_B
Values denominator(const In& in, const RuleContext&) { return {in[0][0] + in[1][0] + in[2][0] + in[3][0]}; }
// J = numerator / denominator
Values impulse(const In& in, const RuleContext&)
{
    if (in[1][0] == 0.0) return {};
    return {in[0][0] / in[1][0]};
}

// P = J n + J_t t: the impulse on A (inputs: J, n, J_t t)
Vec3 impulseVector(const In& in) { return in[0][0] * vecOf(in[1]) + vecOf(in[2]); }

// dv_A = P / M_A,  dv_B = -P / M_B
Values deltaVA(const In& in, const RuleContext&) { return flatVec(in[3][0] * impulseVector(in)); }
Values deltaVB(const In& in, const RuleContext&) { return flatVec(-in[3][0] * impulseVector(in)); }

// dL_A = x_a x P,  dL_B = x_b x (-P); zero for a side without angular response
Values deltaL(const In& in, const RuleContext& c, bool a)
{
    const int b = c.side(a);
    if (b < 0 || !c.w.scene().bodies[b].angularResponse) return {0.0, 0.0, 0.0};
    const Vec3 P = (a ? 1.0 : -1.0) * impulseVector(in);
    return flatVec(vecOf(in[3]).cross(P));
}
Values deltaLA(const In& in, const RuleContext& c) { return deltaL(in, c, true); }
Values deltaLB(const In& in, const RuleContext& c) { return deltaL(in, c, false); }

// v' = v + dv (v: the workbook's v' less its dv), and L' = L + dL likewise
Values plusDelta(const In& in, const RuleContext& c)
{
    const Values after = c.traced(c.rule.id), delta = c.traced(c.rule.inputs[0].id);
    if (after.size() != 3 || delta.size() != 3) return {};
    return flatVec(vecOf(after) - vecOf(delta) + vecOf(in[0]));
}

// omega' = I^-1 L' of the side
Values omegaAfter(const In& in, const RuleContext& c, bool a)
{
    const int b = c.side(a);
    if (b < 0) return {};
    const Values Iinv = c.inverseInertiaOf(b);
    if (Iinv.size() != 9) return {};
    return flatVec(matOf(Iinv) * vecOf(in[0]));
}
Values omegaAfterA(const In& in, const RuleContext& c) { return omegaAfter(in, c, true); }
Values omegaAfterB(const In& in, const RuleContext& c) { return omegaAfter(in, c, false); }

const std::vector<Rule>& rules()
{
    static const std::vector<Rule> all = {
        {q::angular_momentum.id, {{q::torque.id}}, true, angularMomentum},
        {q::angular_momentum.id, {{q::torque_with_couples.id}}, true, angularMomentum},
        {q::linear_velocity.id, {{q::force.id}}, true, linearVelocity},
        {q::linear_velocity.id, {{q::force_with_gravity.id}}, true, linearVelocity},
        {q::inverse_inertia_body.id, {{q::inertia_body.id}}, false, inverseInertiaBody},
        {q::rotation_matrix.id, {{q::orientation.id}}, false, rotationMatrix},
        {q::inverse_inertia_world.id, {{q::rotation_matrix.id}, {q::inverse_inertia_body.id}}, false,
         inverseInertiaWorld},
        {q::inverse_inertia_world_template.id, {{q::rotation_matrix.id}, {q::inverse_inertia_body.id}}, false,
         inverseInertiaWorld},
        {q::angular_velocity.id, {{q::inverse_inertia_world.id}, {q::angular_momentum.id}}, false, angularVelocity},
        {q::angular_velocity.id, {{q::inverse_inertia_world_template.id}, {q::angular_momentum.id}}, false,
         angularVelocity},
        {q::point_velocity.id,
         {{q::linear_velocity.id}, {q::angular_velocity.id}, {q::probe_position.id, -2}, {q::position.id}},
         false, pointVelocity},
        {q::relative_velocity.id, {{q::velocity_a.id}, {q::velocity_b.id}}, false, relativeVelocity},
        {q::normal_velocity.id, {{q::relative_velocity.id}, {q::contact_normal.id}}, false, normalVelocity},
        {q::numerator.id, {{q::restitution.id}, {q::normal_velocity.id}}, false, numerator},
        {q::denominator.id,
         {{q::inv_mass_a.id}, {q::inv_mass_b.id}, {q::rotational_a.id}, {q::rotational_b.id}}, false, denominator},
        {q::impulse.id, {{q::numerator.id}, {q::denominator.id}}, false, impulse},
        {q::delta_v_a.id,
         {{q::impulse.id}, {q::contact_normal.id}, {q::friction_impulse.id, -1, true}, {q::inv_mass_a.id}}, false,
         deltaVA},
        {q::delta_v_b.id,
         {{q::impulse.id}, {q::contact_normal.id}, {q::friction_impulse.id, -1, true}, {q::inv_mass_b.id}}, false,
         deltaVB},
        {q::delta_L_a.id, {{q::impulse.id}, {q::contact_normal.id}, {q::friction_impulse.id, -1, true}, {q::x_a.id}},
         false, deltaLA},
        {q::delta_L_b.id, {{q::impulse.id}, {q::contact_normal.id}, {q::friction_impulse.id, -1, true}, {q::x_b.id}},
         false, deltaLB},
        {q::linear_velocity_a.id, {{q::delta_v_a.id}}, false, plusDelta},
        {q::linear_velocity_b.id, {{q::delta_v_b.id}}, false, plusDelta},
        {q::angular_momentum_a.id, {{q::delta_L_a.id}}, false, plusDelta},
        {q::angular_momentum_b.id, {{q::delta_L_b.id}}, false, plusDelta},
        {q::angular_velocity_a.id, {{q::angular_momentum_a.id}}, false, omegaAfterA},
        {q::angular_velocity_b.id, {{q::angular_momentum_b.id}}, false, omegaAfterB},
    };
    return all;
}

void addSources(std::vector<AnswerKey>& to, const std::vector<AnswerKey>& from)
{
    for (const AnswerKey& k : from) {
        if (std::find(to.begin(), to.end(), k) == to.end()) to.push_back(k);
    }
}

} // namespace

Recomputed FollowThrough::recompute(const AnswerKey& key, int depth) const
{
    if (depth > 8) return {};
    const bool euler = key.body >= 0 && key.contact < 0 &&
                       std::string_view(w_.integratorOf(key.body).name()) == ExplicitEuler::kName;
    for (const Rule& rule : rules()) {
        if (key.id != rule.id || (rule.explicitEulerOnly && !euler)) continue;
        std::vector<Recomputed> ins;
        for (const RuleInput& input : rule.inputs) {
            const AnswerKey k{input.id, key.body, key.contact, input.index == -2 ? key.index : input.index};
            Recomputed v = valueOf(k, depth + 1);
            if (!v.ok && input.optional) {
                v.ok = true;
                v.v = v.err = Values{0.0, 0.0, 0.0};
            }
            if (!v.ok) break;
            ins.push_back(std::move(v));
        }
        if (ins.size() != rule.inputs.size()) continue;   // an input is missing: the next rule
        In args;
        for (const Recomputed& v : ins) args.push_back(v.v);
        const RuleContext ctx{w_, t_, key, rule};
        Recomputed out;
        out.v = rule.f(args, ctx);
        if (out.v.empty()) continue;
        out.err.assign(out.v.size(), 0.0);
        // First-order propagation of the inputs' rounding: each input component moved by
        // its rounding, the absolute changes summed.
        for (size_t i = 0; i < ins.size(); ++i) {
            for (size_t j = 0; j < ins[i].err.size(); ++j) {
                if (ins[i].err[j] == 0.0) continue;
                In moved = args;
                moved[i][j] += ins[i].err[j];
                const Values f2 = rule.f(moved, ctx);
                if (f2.size() != out.v.size()) continue;
                for (size_t c = 0; c < out.v.size(); ++c) out.err[c] += std::abs(f2[c] - out.v[c]);
            }
            out.student = out.student || ins[i].student;
            addSources(out.wrongFrom, ins[i].wrongFrom);
        }
        out.ok = true;
        return out;
    }
    return {};
}

Recomputed FollowThrough::valueOf(const AnswerKey& k, int depth) const
{
    Recomputed v;
    const auto g = given_.find(k);
    if (g != given_.end()) {
        v.v = g->second.value;
        v.err = g->second.rounding;
        v.student = true;
        v.wrongFrom = g->second.wrongFrom;
        v.ok = true;
        return v;
    }
    Recomputed re = recompute(k, depth);
    if (re.ok && re.student) return re;
    const TraceEntry* e = traceEntryOf(t_, k);
    if (e == nullptr) return v;
    v.v = traceValueComponents(e->value);
    v.err.assign(v.v.size(), 0.0);
    v.ok = true;
    return v;
}

} // namespace rbw::checking
