#include "physics/integrators/implicit_gyroscopic.h"

#include "physics/integrators/integrator_quantities.h"
#include "physics/integrators/rigid_ode.h"
#include "physics/quantities.h"

#include <Eigen/LU>

namespace rbw {

void ImplicitGyroscopic::integrate(const IntegrationInput& in, std::vector<BodyState>& states,
                                   StepTrace* trace) const
{
    const double h = in.h;
    for (int b = 0; b < static_cast<int>(states.size()); ++b) {
        if (!in.advances(b)) {
            continue;
        }
        BodyState& s = states[b];
        const MassProperties& mp = in.mass[b];
        const BodyLoad& load = in.loads[b];

        // v_{n+1} = v_n + h F/M,  x_{n+1} = x_n + h v_{n+1}
        s.v_W += (h * mp.invM) * load.F_W;
        record(trace, q::se_linear_velocity, b, s.v_W);
        s.x_W += h * s.v_W;
        record(trace, q::se_position, b, s.x_W);

        if (in.conventionOf(b) == InertiaConvention::CourseTemplate) {
            // No body frame turns with omega here: symplectic Euler on L (see the header).
            s.L_W += h * load.q_W;
            record(trace, q::se_angular_momentum, b, s.L_W);
            const Vec3 omega1_W = s.Iinv_W * s.L_W;
            record(trace, q::update_angular_velocity, b, omega1_W);
            s.q_WB.coeffs() += h * orientationRate(omega1_W, s.q_WB).coeffs();
            s.q_WB = normalisedOrientation(s.q_WB);
            record(trace, q::se_orientation, b, s.q_WB);
            updateDerived(mp, s, in.conventionOf(b));
            recordDerived(trace, b, mp, s, in.conventionOf(b));
            continue;
        }

        Vec3 omega1_W = s.omega_W;
        if (skipIsotropic_ && isIsotropic(mp.I0_B)) {
            // I0 = k E: omega x I0 omega = k omega x omega = 0, so omega_B' = omega_B.
            record(trace, q::gyroscopic_skipped, b, 1.0);
        } else {
            // omega_B = R^T omega   (body frame)
            const Vec3 omega_B = s.R_WB.transpose() * s.omega_W;
            record(trace, q::body_angular_velocity, b, omega_B);
            // J = I0 + h ([omega_B]x I0 - [I0 omega_B]x)
            const Vec3 Iomega_B = mp.I0_B * omega_B;
            const Mat3 J = mp.I0_B + h * (skew(omega_B) * mp.I0_B - skew(Iomega_B));
            record(trace, q::gyroscopic_jacobian, b, J);
            // omega_B' = omega_B - J^-1 f,  f = g(omega_B) = h omega_B x I0 omega_B
            const Vec3 f = h * omega_B.cross(Iomega_B);
            const Vec3 omega1_B = omega_B - J.partialPivLu().solve(f);
            record(trace, q::body_angular_velocity_new, b, omega1_B);
            record(trace, q::newton_iterations, b, 1.0);
            if (trace != nullptr) {
                // g(omega_B') = I0 (omega_B' - omega_B) + h omega_B' x I0 omega_B': what one step leaves
                const Vec3 g = mp.I0_B * (omega1_B - omega_B) + h * omega1_B.cross(mp.I0_B * omega1_B);
                trace->add(q::gyroscopic_residual, b, g.norm());
            }
            // back to the world frame: R omega_B'
            omega1_W = s.R_WB * omega1_B;
        }
        // omega' = R omega_B' + h I^-1 q
        omega1_W += h * (s.Iinv_W * load.q_W);
        record(trace, q::gyroscopic_angular_velocity, b, omega1_W);

        // r_{n+1} = normalise(r_n + h/2 (0, omega') r_n)
        s.q_WB.coeffs() += h * orientationRate(omega1_W, s.q_WB).coeffs();
        s.q_WB = normalisedOrientation(s.q_WB);
        record(trace, q::se_orientation, b, s.q_WB);

        // L_{n+1} = R_{n+1} I0 R_{n+1}^T omega': the momentum of omega' in the new pose
        const Mat3 R1_WB = s.q_WB.toRotationMatrix();
        s.L_W = R1_WB * (mp.I0_B * (R1_WB.transpose() * omega1_W));
        record(trace, q::gyroscopic_angular_momentum, b, s.L_W);

        // R = R(r), I^-1 = R I0^-1 R^T, omega = I^-1 L (= omega' up to rounding)
        updateDerived(mp, s, in.conventionOf(b));
        recordDerived(trace, b, mp, s, in.conventionOf(b));
    }
}

} // namespace rbw
