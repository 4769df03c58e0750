#include "physics/workbook/checker/model_inputs.h"

#include "physics/workbook/checker/follow_through.h"
#include "physics/engine/quantities.h"
#include "physics/engine/world.h"

namespace rbw::checking {

BodyStepInputs bodyStepInputs(const World& w, int b)
{
    const SceneDef& scene = w.scene();
    const BodyState& s = w.states()[b];
    BodyStepInputs in;
    in.h = scene.dt;
    in.mass = scene.bodies[b].mass;
    in.size = scene.bodies[b].size;
    in.x_W = s.x_W;
    in.v_W = s.v_W;
    in.q_WB = s.q_WB;
    in.L_W = s.L_W;
    in.convention = w.conventionOf(b);
    if (scene.hasGravity()) in.g_W = scene.g_W;
    const long k = w.stepIndex();
    in.firstStep = k == 0;
    for (const ForceDef& f : scene.forces) {
        if (f.body == b && f.activeIn(k)) in.forces.push_back({f.p_W, f.f_W});
    }
    for (int j = 0; j < static_cast<int>(scene.torques.size()); ++j) {
        const TorqueDef& t = scene.torques[j];
        if (t.body == b && t.activeIn(k) && w.torqueEnabled(j)) in.couple_W += t.q_W;
    }
    for (int i = 0; i < static_cast<int>(scene.probes.size()); ++i) {
        // probe i's index among all probes: body frame offset p_B = R^T (p - x)
        in.probes_B.push_back(scene.probes[i].body == b ? w.worldToBody(b, w.probe(i).p_W) : Vec3::Zero());
    }
    return in;
}

namespace {

// I^-1 of a body in this step's contacts: the one after the integration (positions do
// not change in the contact stages); zero for a fixed body or a particle response.
Mat3 contactInverseInertia(const World& w, const StepTrace& t, int b)
{
    if (w.massProperties()[b].invM == 0.0 || !w.scene().bodies[b].angularResponse) return Mat3::Zero();
    const TraceEntry* e = traceEntryOf(t, AnswerKey{q::inverse_inertia_world.id, b, -1, -1});
    return e != nullptr ? matOf(traceValueComponents(e->value)) : Mat3(Mat3::Zero());
}

// Its body-frame I0^-1 where it turns in the contact (impulse-body-inverse-inertia), else zero.
Mat3 contactBodyInverseInertia(const World& w, int b)
{
    if (w.massProperties()[b].invM == 0.0 || !w.scene().bodies[b].angularResponse) return Mat3::Zero();
    return w.massProperties()[b].I0inv_B;
}

} // namespace

ContactInputs contactStepInputs(const World& w, const StepTrace& t, int k)
{
    ContactInputs in;
    const ContactHeader& h = t.contacts[k];
    auto get = [&](const QuantityInfo& q) -> Values {
        const TraceEntry* e = traceEntryOf(t, AnswerKey{q.id, -1, k, -1});
        return e != nullptr ? traceValueComponents(e->value) : Values{};
    };
    auto vecOr0 = [](const Values& v) { return v.size() == 3 ? vecOf(v) : Vec3(Vec3::Zero()); };
    in.g.p_W = vecOr0(get(q::contact_point));
    in.g.n_W = vecOr0(get(q::contact_normal));
    const Values c = get(q::restitution);
    in.restitution = c.empty() ? w.scene().restitutionFor(h.bodyA, h.bodyB, h.plane) : c[0];
    // Point velocities as recorded (v_A(p) = v_A + omega_A x x_a): enter them as v, no spin.
    in.x_A = in.g.p_W - vecOr0(get(q::x_a));
    in.v_A = vecOr0(get(q::velocity_a));
    in.invM_A = w.massProperties()[h.bodyA].invM;
    in.Iinv_A = contactInverseInertia(w, t, h.bodyA);
    in.I0inv_A = contactBodyInverseInertia(w, h.bodyA);
    if (h.bodyB >= 0) {
        in.x_B = in.g.p_W - vecOr0(get(q::x_b));
        in.invM_B = w.massProperties()[h.bodyB].invM;
        in.Iinv_B = contactInverseInertia(w, t, h.bodyB);
        in.I0inv_B = contactBodyInverseInertia(w, h.bodyB);
    } else {
        in.x_B = in.g.p_W;
    }
    in.v_B = vecOr0(get(q::velocity_b));
    return in;
}

} // namespace rbw::checking
