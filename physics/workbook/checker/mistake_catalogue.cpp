// The catalogue of mistake models (issue 10, issue 21 item 1): id, wrong equation and
// explanation of each; their effects are in mistakes.cpp.
#include "physics/workbook/checker/mistakes.h"

namespace rbw {

const std::vector<MistakeInfo>& mistakeCatalogue()
{
    static const std::vector<MistakeInfo> all = {
        {Mistake::VelocityBeforePosition, "velocity-before-position", "x <- x + h v_{n+1}",
         "The position was moved with the new velocity; step 2 uses the old one: x <- x + h v_n."},
        {Mistake::OmegaBeforeOrientation, "omega-before-orientation", "r <- r + h/2 (0, omega_{n+1}) r",
         "The orientation was turned with the new omega; step 4 uses the old one: r <- r + h/2 (0, omega_n) r."},
        {Mistake::TransposedInertia, "transposed-inertia",
         "I^-1 = R^T I0^-1 R (for a template-convention body: R I0^-1 R^T)",
         "The inverse inertia was rotated the wrong way round; in the standard convention the world frame "
         "needs I^-1 = R I0^-1 R^T (in the course template's, lesson 8: R^T I0^-1 R)."},
        {Mistake::BodyInverseInertia, "body-inverse-inertia", "omega = I0^-1 L",
         "omega was computed with the body-frame inverse inertia; rotate it to the world first: omega = R I0^-1 R^T L."},
        {Mistake::InertiaNotInverted, "inertia-not-inverted", "omega = I L",
         "omega was computed with the inertia instead of its inverse: omega = I^-1 L."},
        {Mistake::TorqueReversed, "torque-reversed", "q = f x (p - x)",
         "The cross product is the wrong way round; the torque is q = (p - x) x f."},
        {Mistake::LeverArmFromOrigin, "lever-arm-from-origin", "q = p x f",
         "The lever arm was taken from the world origin; it starts at the centre of mass: q = (p - x) x f."},
        {Mistake::MissingTimeStep, "missing-time-step", "L <- L + q,  v <- v + F/M",
         "The change over the step was not multiplied by h: L <- L + h q, v <- v + h F/M."},
        {Mistake::QuaternionMissingHalf, "quaternion-missing-half", "r <- r + h (0, omega) r",
         "The quaternion update lacks the factor 1/2: r <- r + (h/2) (0, omega) r."},
        {Mistake::QuaternionNotNormalised, "quaternion-not-normalised", "r <- r + h/2 (0, omega) r, |r| != 1",
         "The orientation was not renormalised after its update: r <- r / |r|."},
        {Mistake::HalfExtentsForSize, "half-extents-for-size", "I0 = M/12 diag((b/2)^2 + (c/2)^2, ...)",
         "The 1/12 formula takes the full edge lengths a, b, c, not the half extents."},
        {Mistake::PointVelocityWithoutRotation, "point-velocity-without-rotation", "v_p = v",
         "A point of a spinning body also moves with the rotation: v_p = v + omega x (p - x)."},
        {Mistake::RelativeVelocityReversed, "relative-velocity-reversed", "v_rel = v_B(p) - v_A(p)",
         "The relative velocity is A's minus B's, v_rel = v_A(p) - v_B(p), with n pointing from B to A."},
        {Mistake::ImpulseLinearOnly, "impulse-linear-only", "J = -(1 + c) v_rel.n / (1/M_A + 1/M_B)",
         "The denominator lacks the rotational terms [(I^-1 (x x n)) x x] . n of both bodies."},
        {Mistake::ImpulseWithoutOnePlus, "impulse-without-one-plus", "J = -c v_rel.n / (...)",
         "The numerator is -(1 + c) v_rel.n: the impulse first stops the approach, then c of it bounces back."},
        {Mistake::PointVelocityCrossReversed, "point-velocity-cross-reversed", "v_p = v + (p - x) x omega",
         "The cross product of the point velocity is the wrong way round: v_p = v + omega x (p - x)."},
        {Mistake::PointVelocityLeverArmFromOrigin, "point-velocity-lever-arm-from-origin", "v_p = v + omega x p",
         "The point's lever arm was taken from the world origin; it starts at the centre of mass: "
         "v_p = v + omega x (p - x)."},
        {Mistake::RestitutionOneMinus, "restitution-one-minus", "J = -(1 - c) v_rel.n / (...)",
         "The numerator is -(1 + c) v_rel.n, not -(1 - c) v_rel.n: the bounce adds c of the approach."},
        {Mistake::InertiaAxesSwapped, "inertia-axes-swapped", "I0 with two of its moments exchanged",
         "Two of the box's axes were read in another order: I0 = M/12 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2) "
         "with a, b, c its extents along the body's x, y and z.",
         3},
        {Mistake::QuaternionWithoutHalfAngle, "quaternion-without-half-angle", "r0 = (cos th, n sin th)",
         "A rotation by th about n is the quaternion (cos th/2, n sin th/2); the half angle was left out."},
        {Mistake::InertiaHalfExtentsWithoutThird, "inertia-half-extents-without-third",
         "I0 = M diag(b^2 + c^2, a^2 + c^2, a^2 + b^2), a, b, c half extents",
         "With the half extents the box's inertia is M/3 diag(b^2 + c^2, ...), not M diag(...): "
         "I0 = M/12 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2) with the full edges."},
        {Mistake::OmegaAccumulated, "omega-accumulated", "omega' = omega + I^-1 L'",
         "omega is not accumulated: it is the new I^-1 times the new L, omega' = I^-1 L'."},
        {Mistake::NoSeparatingCheck, "no-separating-check", "J applied although v_rel.n > 0",
         "The bodies separate (v_rel . n > 0): no impulse, J = 0."},
        {Mistake::ImpulseLeverArmFromOrigin, "impulse-lever-arm-from-origin", "x_a = p,  x_b = p",
         "The impulse's lever arms start at the centres of mass: x_a = p - x_A, x_b = p - x_B."},
        {Mistake::ImpulseDenominatorMissingCross, "impulse-denominator-missing-cross", "... + (I_A^-1 (x_a x n)) . n + ...",
         "The rotational term of the denominator is [(I^-1 (x_a x n)) x x_a] . n: the cross product with x_a "
         "was left out."},
        {Mistake::InertiaFromOldOrientation, "inertia-from-old-orientation", "omega' = R_n I0^-1 R_n^T L'",
         "The world inertia was built from the orientation before this step's update; omega' needs the new one: "
         "omega' = R_{n+1} I0^-1 R_{n+1}^T L'."},
        {Mistake::InertiaNotUpdated, "inertia-not-updated", "I^-1 = R_0 I0^-1 R_0^T, computed once",
         "The world inverse inertia was computed once, from the first orientation, and never again; it turns with "
         "the body: I^-1 = R I0^-1 R^T with this step's R.",
         1, false},
        {Mistake::InertiaAccumulatedRotation, "inertia-accumulated-rotation", "I^-1 <- R I^-1 R^T (last step's I^-1)",
         "The rotation was applied to last step's world tensor, so the turns pile up; rotate the body-frame one: "
         "I^-1 = R I0^-1 R^T.",
         1, false},
        {Mistake::QuaternionRightMultiplied, "quaternion-right-multiplied", "r <- r + h/2 r (0, omega)",
         "omega is in the world frame, so it multiplies from the left: r <- r + (h/2) (0, omega) r."},
        {Mistake::ForcesNotCleared, "forces-not-cleared", "F, q of earlier steps keep acting",
         "The accumulated force and torque were not set back to zero after the step; a force acts only in the "
         "step it is applied for.",
         1, false},
        {Mistake::GravityAlwaysOn, "gravity-always-on", "v <- v + h (F/M + g),  g = (0, -9.81, 0)",
         "Gravity was added although the scene has none; the scene's forces are all that act: v <- v + h F/M.",
         1, false},
        {Mistake::OrientationZeroQuaternion, "orientation-zero-quaternion", "r = (0, 0, 0, 0) when never set",
         "A body whose orientation was never set must start at r = (1, 0, 0, 0); the zero quaternion never turns "
         "(and R(0) = E).",
         1, false},
        {Mistake::AngleInDegrees, "angle-in-degrees", "r0 = (cos th'/2, n sin th'/2), th' = th in degrees as radians",
         "cos and sin take radians: convert the angle first, th = degrees * pi / 180, then r0 = (cos th/2, n sin th/2)."},
        {Mistake::ImpulseBodyInverseInertia, "impulse-body-inverse-inertia", "... + [(I0_A^-1 (x_a x n)) x x_a] . n + ...",
         "The impulse's angular terms need the world-frame inverse inertia I^-1 = R I0^-1 R^T, not I0^-1."},
    };
    return all;
}

const MistakeInfo* findMistake(std::string_view id)
{
    for (const MistakeInfo& m : mistakeCatalogue()) {
        if (id == m.id) return &m;
    }
    return nullptr;
}

std::string mistakeExplanation(const MistakeInfo& m, InertiaConvention convention)
{
    if (m.mistake == Mistake::TransposedInertia && convention == InertiaConvention::CourseTemplate) {
        return "This body is in the course template's convention (lesson 8): you used the standard I^-1 = R I0^-1 R^T, "
               "and this body needs I^-1 = R^T I0^-1 R.";
    }
    return m.explanation;
}

} // namespace rbw
