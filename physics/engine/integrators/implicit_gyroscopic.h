// One Newton step of implicit Euler on the gyroscopic term, in the body frame, as
// Bullet (btRigidBody::computeGyroscopicImpulseImplicit_Body) and Box2D describe it
// (Catto, "Numerical Methods", GDC 2015). First order. Angular velocity is the
// velocity state there, so the step reads omega, updates it and writes L back.
//
//   v_{n+1} = v_n + h F/M,   x_{n+1} = x_n + h v_{n+1}          (symplectic Euler)
//   omega_B = R^T omega_n
//   implicit Euler on I0 omega_B' + omega_B' x I0 omega_B' = 0, i.e.
//     g(omega_B') = I0 (omega_B' - omega_B) + h omega_B' x I0 omega_B' = 0,
//   one Newton step from omega_B' = omega_B:
//     J = I0 + h ([omega_B]x I0 - [I0 omega_B]x),   omega_B' = omega_B - J^-1 h omega_B x I0 omega_B
//   omega' = R omega_B' + h I^-1 q                                   (torque, as explicit Euler)
//   r_{n+1} = normalise(r_n + h/2 (0, omega') r_n)
//   L_{n+1} = I(r_{n+1}) omega' = R_{n+1} I0 R_{n+1}^T omega'       (so omega_{n+1} = omega')
//
// It damps |L| and T slowly instead of letting them grow (docs/references.md §5: max
// |dE|/E ~ 1e-2 over 100 s of the Dzhanibekov case at h = 0.01), and L_W is not
// conserved exactly. Its point is stability at large h|omega|.
//
// "Model only what a scene requires": when I0 = k E the term omega x I0 omega is
// exactly zero, so the Newton step is skipped (the trace says so). The result is the
// same as with the step, up to the rounding of R R^T (tests/physics/engine/integrators).
//
// Course-template convention: the gyroscopic term is the body-frame form of dL/dt = q
// for a rigid body whose I^-1 is R I0^-1 R^T. The template's I^-1 = R^T I0^-1 R does
// not come from a frame that turns with omega, so the term does not exist there:
// this integrator then takes the symplectic Euler update of L (L += h q, omega' =
// I^-1(r_n) L_{n+1}, r with omega'), which converges to the template's equations.
#pragma once

#include "physics/engine/integrator.h"

namespace rbw {

class ImplicitGyroscopic final : public Integrator {
public:
    static constexpr const char* kName = "implicit-gyroscopic";
    // skipIsotropic = false forces the Newton step even when I0 = k E (for the test
    // that shows skipping changes nothing).
    explicit ImplicitGyroscopic(bool skipIsotropic = true) : skipIsotropic_(skipIsotropic) {}
    const char* name() const override { return kName; }
    void advance(const BodyStep& step, BodyState& s) const override;

private:
    bool skipIsotropic_;
};

} // namespace rbw
