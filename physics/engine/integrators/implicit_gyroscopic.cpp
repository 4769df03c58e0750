#include "physics/engine/integrators/implicit_gyroscopic.h"

#include "physics/engine/integrators/rigid_ode.h"
#include "physics/engine/quantities.h"

#include <Eigen/LU>

namespace rbw {

void ImplicitGyroscopic::advance(const BodyStep& step, BodyState& s) const
{
    const double h = step.h;

    // v_{n+1} = v_n + h F/M,  x_{n+1} = x_n + h v_{n+1}
    s.v_W += (h * step.mp.invM) * step.load.F_W;
    step.record(q::se_linear_velocity, s.v_W);
    s.x_W += h * s.v_W;
    step.record(q::se_position, s.x_W);

    if (step.convention == InertiaConvention::CourseTemplate) {
        // No body frame turns with omega here: symplectic Euler on L (see the header).
        s.L_W += h * step.load.q_W;
        step.record(q::se_angular_momentum, s.L_W);
        const Vec3 omega1_W = s.Iinv_W * s.L_W;
        step.record(q::update_angular_velocity, omega1_W);
        s.q_WB.coeffs() += h * orientationRate(omega1_W, s.q_WB).coeffs();
        if (step.trace != nullptr) step.record(q::se_orientation_norm, orientationNorm(s.q_WB));
        s.q_WB = normalisedOrientation(s.q_WB);
        step.record(q::se_orientation, s.q_WB);
        return;   // the base derives R, I^-1 and omega
    }

    Vec3 omega1_W = s.omega_W;
    if (skipIsotropic_ && isIsotropic(step.mp.I0_B)) {
        // I0 = k E: omega x I0 omega = k omega x omega = 0, so omega_B' = omega_B.
        step.record(q::gyroscopic_skipped, 1.0);
    } else {
        // omega_B = R^T omega   (body frame)
        const Vec3 omega_B = s.R_WB.transpose() * s.omega_W;
        step.record(q::body_angular_velocity, omega_B);
        // J = I0 + h ([omega_B]x I0 - [I0 omega_B]x)
        const Vec3 Iomega_B = step.mp.I0_B * omega_B;
        const Mat3 J = step.mp.I0_B + h * (skew(omega_B) * step.mp.I0_B - skew(Iomega_B));
        step.record(q::gyroscopic_jacobian, J);
        // omega_B' = omega_B - J^-1 f,  f = g(omega_B) = h omega_B x I0 omega_B
        const Vec3 f = h * omega_B.cross(Iomega_B);
        const Vec3 omega1_B = omega_B - J.partialPivLu().solve(f);
        step.record(q::body_angular_velocity_new, omega1_B);
        step.record(q::newton_iterations, 1.0);
        if (step.trace != nullptr) {
            // g(omega_B') = I0 (omega_B' - omega_B) + h omega_B' x I0 omega_B': what one step leaves
            const Vec3 g = step.mp.I0_B * (omega1_B - omega_B) + h * omega1_B.cross(step.mp.I0_B * omega1_B);
            step.record(q::gyroscopic_residual, g.norm());
        }
        // back to the world frame: R omega_B'
        omega1_W = s.R_WB * omega1_B;
    }
    // omega' = R omega_B' + h I^-1 q
    omega1_W += h * (s.Iinv_W * step.load.q_W);
    step.record(q::gyroscopic_angular_velocity, omega1_W);

    // r_{n+1} = normalise(r_n + h/2 (0, omega') r_n)
    s.q_WB.coeffs() += h * orientationRate(omega1_W, s.q_WB).coeffs();
    if (step.trace != nullptr) step.record(q::se_orientation_norm, orientationNorm(s.q_WB));
    s.q_WB = normalisedOrientation(s.q_WB);
    step.record(q::se_orientation, s.q_WB);

    // L_{n+1} = R_{n+1} I0 R_{n+1}^T omega': the momentum of omega' in the new pose
    const Mat3 R1_WB = s.q_WB.toRotationMatrix();
    s.L_W = R1_WB * (step.mp.I0_B * (R1_WB.transpose() * omega1_W));
    step.record(q::gyroscopic_angular_momentum, s.L_W);
}

} // namespace rbw
