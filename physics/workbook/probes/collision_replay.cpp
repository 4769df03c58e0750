#include "physics/workbook/probes/collision_replay.h"

#include "physics/engine/course/box_box_sat.h"
#include "physics/workbook/checker/mistakes.h"
#include "physics/workbook/probes/probe_models.h"
#include "physics/workbook/probes/simulator_state.h"

#include <algorithm>
#include <cstddef>
#include <utility>

namespace rbw::probes {

namespace {

// The impulse between A = bodies[i] and B = bodies[j], if they touch.
void collide(SimBody& A, SimBody& B, double c, const MistakeSet& m)
{
    const BoxPose boxA{A.x_W, A.r_WB.toRotationMatrix(), 0.5 * A.size};
    const BoxPose boxB{B.x_W, B.r_WB.toRotationMatrix(), 0.5 * B.size};
    const std::optional<ContactGeometry> contact = collideBoxBoxSAT(boxA, boxB);
    if (!contact) return;
    ContactInputs in;
    in.g = *contact;
    in.restitution = c;
    in.x_A = A.x_W;
    in.v_A = A.v_W;
    in.omega_A = A.omega_W;
    in.Iinv_A = A.Iinv_W;
    in.I0inv_A = A.I0inv_B;
    in.invM_A = 1.0 / A.mass;
    in.x_B = B.x_W;
    in.v_B = B.v_W;
    in.omega_B = B.omega_W;
    in.Iinv_B = B.Iinv_W;
    in.I0inv_B = B.I0inv_B;
    in.invM_B = 1.0 / B.mass;
    const HandImpulse k = handImpulse(in, m);
    // the simulator's own separating test on its own v_rel.n
    if (k.v_rel_n > 0.0 && !m.has(Mistake::NoSeparatingCheck)) return;
    const double J = k.numerator / k.denominator;
    const Vec3 Jn_W = J * contact->n_W;
    A.v_W += Jn_W / A.mass;
    B.v_W -= Jn_W / B.mass;
    A.L_W += k.x_a.cross(Jn_W);
    B.L_W -= k.x_b.cross(Jn_W);
    A.omega_W = A.Iinv_W * A.L_W;
    B.omega_W = B.Iinv_W * B.L_W;
}

} // namespace

std::vector<ReplayModel> collisionModels()
{
    std::vector<ReplayModel> models;
    for (const MistakeInfo& info : mistakeCatalogue()) {
        if (scopeOf(info.mistake) != ProbeScope::Collision) continue;
        for (int v = 0; v < info.variants; ++v) models.push_back({info.mistake, v});
    }
    return models;
}

Answers replayWithContacts(const Probe& probe, const ReplayModel& model, double c)
{
    // A motion model changes the step, a collision model the impulse; a pair may have one
    // of each (or two of one kind).
    ReplayModel stepModel{Mistake::None, model.variant};
    MistakeSet impulseMistakes{Mistake::None, Mistake::None, model.variant};
    for (Mistake m : {model.mistake, model.second}) {
        if (scopeOf(m) == ProbeScope::Motion) {
            Mistake& slot = stepModel.mistake == Mistake::None ? stepModel.mistake : stepModel.second;
            slot = m;
        } else if (scopeOf(m) == ProbeScope::Collision) {
            Mistake& slot = impulseMistakes.first == Mistake::None ? impulseMistakes.first : impulseMistakes.second;
            slot = m;
        }
    }
    std::vector<SimBody> bodies;
    Answers answers;
    for (const Command& cmd : probe.commands) {
        switch (cmd.kind) {
        case CommandKind::AddBody:
            bodies.push_back(addSimBody(cmd.a, cmd.b, cmd.mass, stepModel));
            break;
        case CommandKind::SetOrientation:
            bodies[cmd.body].r_WB = cmd.q.normalized();
            bodies[cmd.body].kept.orientationSet = true;
            break;
        case CommandKind::SetVelocity:
            bodies[cmd.body].v_W = cmd.a;
            break;
        case CommandKind::ApplyForce:
            bodies[cmd.body].forces.push_back({cmd.a, cmd.b});
            break;
        case CommandKind::Step:
            for (SimBody& b : bodies) stepSimBody(b, cmd.h, stepModel);
            for (std::size_t i = 0; i < bodies.size(); ++i) {
                for (std::size_t j = i + 1; j < bodies.size(); ++j) collide(bodies[i], bodies[j], c, impulseMistakes);
            }
            break;
        case CommandKind::State: {
            const SimBody& b = bodies[cmd.body];
            answers.push_back({b.x_W.x(), b.x_W.y(), b.x_W.z(), b.v_W.x(), b.v_W.y(), b.v_W.z(), b.omega_W.x(),
                               b.omega_W.y(), b.omega_W.z(), b.r_WB.w(), b.r_WB.x(), b.r_WB.y(), b.r_WB.z()});
            break;
        }
        }
    }
    return answers;
}

RestitutionFit fitRestitution(const std::vector<Probe>& probes, const std::vector<Answers>& given,
                              const ReplayModel& model)
{
    double num = 0.0, den = 0.0;
    for (std::size_t p = 0; p < std::min(probes.size(), given.size()); ++p) {
        if (!probes[p].collides) continue;
        const Answers a0 = replayWithContacts(probes[p], model, 0.0);
        const Answers a1 = replayWithContacts(probes[p], model, 1.0);
        const std::vector<AnswerSlot> slots = answerSlots(probes[p]);
        // the first answer that c changes: the step of the first impulse
        std::size_t first = a0.size();
        for (std::size_t k = 0; k < a0.size() && first == a0.size(); ++k) {
            if (a0[k] != a1[k]) first = k;
        }
        if (first == a0.size()) continue;
        // every answer of that step: v and omega are a0 + c (a1 - a0)
        for (std::size_t k = first; k < a0.size() && k < given[p].size() && slots[k].step == slots[first].step; ++k) {
            for (int i = 3; i < 9; ++i) {
                const double d = a1[k][i] - a0[k][i];
                num += (given[p][k][i] - a0[k][i]) * d;
                den += d * d;
            }
        }
    }
    RestitutionFit fit;
    if (den > 0.0) {
        fit.c = std::clamp(num / den, 0.0, 1.0);
        fit.determined = true;
    }
    return fit;
}

} // namespace rbw::probes
