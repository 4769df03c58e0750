// The workbook's side of a collision probe (issue 23): what a simulator that makes one
// mistake, a pair of them (or none) answers when its bodies touch. After every step of every body
// (the checker's handEulerStep(), chained as in replay.h) each pair i < j is tested
// with the course template's box-box test (physics/engine/course/box_box_sat.h, A =
// body i, B = body j) and a contact gets the checker's impulse handImpulse()
// (physics/workbook/checker/mistakes.h) as a simulator applies it: no impulse when its
// own v_rel.n > 0 (unless it makes no-separating-check), then
//   v_A += J n / M_A,  v_B -= J n / M_B,  L_A += x_a x J n,  L_B -= x_b x J n,
//   omega = Iinv_W L with the simulator's stored world inverse inertia.
// A motion model changes the step (and the inertia the impulse uses), a collision model
// the impulse.
//
// The coefficient of restitution c is the student's and not known in advance: the
// answers after a step with the first impulse are affine in c (J is, and nothing of
// that step before the impulse depends on c), so c is fitted to them by least squares
// and clamped to [0, 1] (fitRestitution). Two models cannot be told apart by any scene:
// impulse-without-one-plus with c and restitution-one-minus with 1 - c give the same
// numerator, -c v_rel.n.
#pragma once

#include "physics/workbook/probes/probes.h"
#include "physics/workbook/probes/replay.h"

#include <optional>
#include <vector>

namespace rbw::probes {

// The answers of a simulator with `model` and restitution c to the probe's `state`
// commands, contacts and all.
Answers replayWithContacts(const Probe& probe, const ReplayModel& model, double c);

// The collision group's own candidates: every Collision model of probe_models.h, in the
// catalogue's order (a motion model also changes the collision probes' answers; the
// diagnosis tries those too).
std::vector<ReplayModel> collisionModels();

struct RestitutionFit {
    double c = 0.5;
    bool determined = false;   // false: c changes no answer of these probes (no impulse)
};

// The c in [0, 1] with which `model` comes closest to `given` (least squares over the
// velocities and angular velocities of the answers right after each probe's first
// impulse); only probes that collide count.
RestitutionFit fitRestitution(const std::vector<Probe>& probes, const std::vector<Answers>& given,
                              const ReplayModel& model);

} // namespace rbw::probes
