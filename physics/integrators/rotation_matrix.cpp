#include "physics/integrators/rotation_matrix.h"

#include "physics/integrators/integrator_quantities.h"
#include "physics/integrators/rigid_ode.h"
#include "physics/integrators/rotation_matrix_orthonormalised.h"
#include "physics/quantities.h"

namespace rbw {

double orthonormalityError(const Mat3& R)
{
    // ||R^T R - E||_F
    return (R.transpose() * R - Mat3::Identity()).norm();
}

void integrateRotationMatrix(const IntegrationInput& in, std::vector<BodyState>& states,
                             StepTrace* trace, bool orthonormalise)
{
    const double h = in.h;
    for (int b = 0; b < static_cast<int>(states.size()); ++b) {
        if (!in.advances(b)) {
            continue;
        }
        BodyState& s = states[b];
        const MassProperties& mp = in.mass[b];
        const BodyLoad& load = in.loads[b];

        // x <- x + h v   (old v)
        s.x_W += h * s.v_W;
        record(trace, q::position, b, s.x_W);
        // v <- v + h F/M
        s.v_W += (h * mp.invM) * load.F_W;
        record(trace, q::linear_velocity, b, s.v_W);

        // R <- R + h [omega]x R   (old omega; Napier practical 6)
        Mat3 R_WB = s.R_WB + h * (skew(s.omega_W) * s.R_WB);
        record(trace, q::rotation_matrix_update, b, R_WB);
        if (orthonormalise) {
            record(trace, q::orthonormality_error_before, b, orthonormalityError(R_WB));
            // R <- U V^T, the nearest rotation (polar decomposition)
            if (R_WB.allFinite()) {
                R_WB = nearestRotation(R_WB);
            }
            record(trace, q::polar_rotation_matrix, b, R_WB);
        } else {
            record(trace, q::drifting_rotation_matrix, b, R_WB);
        }
        s.R_WB = R_WB;
        record(trace, q::orthonormality_error, b, orthonormalityError(R_WB));
        record(trace, q::rotation_determinant, b, R_WB.determinant());

        // r = r(R), normalised: for the views (R stays the state)
        s.q_WB = normalisedOrientation(Quat(R_WB));
        record(trace, q::orientation_from_matrix, b, s.q_WB);

        // L <- L + h q
        s.L_W += h * load.q_W;
        record(trace, q::angular_momentum, b, s.L_W);

        // I^-1 = R I0^-1 R^T with this R (drifted unless orthonormalised), omega = I^-1 L
        s.Iinv_W = inverseInertiaWorld(s.R_WB, mp.I0inv_B, in.conventionOf(b));
        s.omega_W = s.Iinv_W * s.L_W;
        if (trace != nullptr) {
            // as recordDerived(), without R: its row is the update above
            trace->add(q::inertia_body, b, mp.I0_B);
            trace->add(q::inverse_inertia_body, b, mp.I0inv_B);
            trace->add(in.conventionOf(b) == InertiaConvention::CourseTemplate ? q::inverse_inertia_world_template
                                                                          : q::inverse_inertia_world,
                       b, s.Iinv_W);
            trace->add(q::angular_velocity, b, s.omega_W);
        }
    }
}

} // namespace rbw
