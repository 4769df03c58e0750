// Collision response: one impulse at one contact point (TUM rigid-body slides;
// Baraff, "Physically Based Modeling", rigid body notes, section 8; docs/references.md
// §3), with Coulomb friction as a second, tangential impulse.
//
// Glossary (A is the first body; B the second body or a fixed plane)
//   x_a, x_b     contact point relative to each centre of mass: p - x_A, p - x_B  [m]
//   v_A(p)       velocity of A's material point at p: v_A + omega_A x x_a         [m/s]
//   v_rel        v_A(p) - v_B(p)                                                  [m/s]
//   n            unit normal from B to A                                          [-]
//   c            coefficient of restitution (0 plastic, 1 elastic)                [-]
//   mu           Coulomb friction coefficient                                     [-]
//   J            normal impulse magnitude, applied +J n to A and -J n to B        [N s]
//   t, J_t       unit tangent opposite to the sliding velocity, friction impulse  [-], [N s]
//
// Normal impulse (docs/references.md §3):
//   J = -(1 + c) (v_rel . n) / (1/M_A + 1/M_B + [(I_A^-1 (x_a x n)) x x_a + (I_B^-1 (x_b x n)) x x_b] . n)
// Friction (derived the same way for the tangent t instead of n, with no bounce):
//   the impulse that stops sliding is J_t* = -(v_rel' . t) / (1/M_A + 1/M_B + [(I_A^-1 (x_a x t)) x x_a
//   + (I_B^-1 (x_b x t)) x x_b] . t), where v_rel' is the relative velocity after the
//   normal impulse; Coulomb's law clamps it to the friction cone: J_t = min(J_t*, mu J).
// Both impulses change the bodies as  v_A += J n / M_A,  L_A += x_a x (J n)  and the
// opposite for B, then omega = I^-1 L.
#pragma once

#include "physics/engine/body.h"
#include "physics/engine/collision/contact.h"
#include "physics/engine/inertia.h"
#include "physics/engine/trace.h"

namespace rbw {

// One side of a contact. A fixed body, a plane, or a side whose rotation is switched
// off ("particle" response) contributes 0 to the matching terms.
struct ResponseBody {
    BodyState* state = nullptr;          // nullptr for a fixed plane
    const MassProperties* mass = nullptr;
    bool angular = true;                 // false: treated as a particle (no x_a x J n term)
    int index = -1;                      // the body's index in the world (trace rows), -1 for a plane
    InertiaConvention convention = InertiaConvention::Standard;   // for omega = I^-1 L after the impulse

    double invM() const { return state != nullptr && mass != nullptr ? mass->invM : 0.0; }
};

struct ImpulseResult {
    Vec3 x_a = Vec3::Zero(), x_b = Vec3::Zero();
    Vec3 velocity_a = Vec3::Zero(), velocity_b = Vec3::Zero();   // v_A(p), v_B(p) before
    Vec3 v_rel = Vec3::Zero();
    double v_rel_n = 0.0;
    bool separating = false;        // v_rel . n > 0: no impulse (docs/references.md §3)
    double restitution = 0.0;
    double numerator = 0.0;         // -(1 + c) v_rel . n
    double invMassA = 0.0, invMassB = 0.0;
    double rotationalA = 0.0;       // [(I_A^-1 (x_a x n)) x x_a] . n
    double rotationalB = 0.0;
    double denominator = 0.0;
    double J = 0.0;
    // Friction
    double mu = 0.0;
    Vec3 t_W = Vec3::Zero();        // unit tangent the friction impulse acts along (zero if none)
    double J_t = 0.0;               // >= 0, along t
    bool frictionClamped = false;   // true when |J_t*| > mu J (sliding), false when it sticks
    Vec3 frictionImpulse_W = Vec3::Zero();   // J_t t
    // Total changes of the two bodies
    Vec3 dv_A = Vec3::Zero(), dv_B = Vec3::Zero();
    Vec3 dL_A = Vec3::Zero(), dL_B = Vec3::Zero();
    double kineticBefore = 0.0, kineticAfter = 0.0;   // of the two bodies
};

// Computes and applies the impulse at contact g between A and B (B may be a plane),
// updating v, L and the derived omega of both (each with its own convention). Returns
// every intermediate number and, given a trace, records each where it is computed, as
// entries of contact number `contact`.
ImpulseResult applyContactImpulse(const ContactGeometry& g, ResponseBody A, ResponseBody B, double restitution,
                                  double mu, StepTrace* trace = nullptr, int contact = -1);

} // namespace rbw
