#include "physics/engine/integrators/rotation_matrix.h"

#include "physics/engine/integrators/rigid_ode.h"
#include "physics/engine/integrators/rotation_matrix_orthonormalised.h"
#include "physics/engine/quantities.h"

namespace rbw {

double orthonormalityError(const Mat3& R)
{
    // ||R^T R - E||_F
    return (R.transpose() * R - Mat3::Identity()).norm();
}

void RotationMatrix::advance(const BodyStep& step, BodyState& s) const
{
    const double h = step.h;

    // x <- x + h v   (old v)
    s.x_W += h * s.v_W;
    step.record(q::position, s.x_W);
    // v <- v + h F/M
    s.v_W += (h * step.mp.invM) * step.load.F_W;
    step.record(q::linear_velocity, s.v_W);

    // R <- R + h [omega]x R   (old omega; Napier practical 6)
    Mat3 R_WB = s.R_WB + h * (skew(s.omega_W) * s.R_WB);
    step.record(q::rotation_matrix_update, R_WB);
    if (orthonormalises()) {
        step.record(q::orthonormality_error_before, orthonormalityError(R_WB));
        // R <- U V^T, the nearest rotation (polar decomposition)
        if (R_WB.allFinite()) {
            R_WB = nearestRotation(R_WB);
        }
        step.record(q::polar_rotation_matrix, R_WB);
    } else {
        step.record(q::drifting_rotation_matrix, R_WB);
    }
    s.R_WB = R_WB;
    step.record(q::orthonormality_error, orthonormalityError(R_WB));
    step.record(q::rotation_determinant, R_WB.determinant());

    // r = r(R), normalised: for the views (R stays the state)
    s.q_WB = normalisedOrientation(Quat(R_WB));
    step.record(q::orientation_from_matrix, s.q_WB);

    // L <- L + h q
    s.L_W += h * step.load.q_W;
    step.record(q::angular_momentum, s.L_W);

    // I^-1 = R I0^-1 R^T with this R (drifted unless orthonormalised), omega = I^-1 L:
    // the base, updateDerivedFromMatrix() (derivedFrom() is FromMatrix)
}

} // namespace rbw
