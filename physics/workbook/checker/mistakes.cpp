#include "physics/workbook/checker/mistakes.h"

#include "physics/engine/inertia.h"
#include "physics/engine/quantities.h"

#include <cmath>
#include <utility>

namespace rbw {

const std::vector<MistakeInfo>& mistakeCatalogue()
{
    static const std::vector<MistakeInfo> all = {
        {Mistake::VelocityBeforePosition, "velocity-before-position", "x <- x + h v_{n+1}",
         "The position was moved with the new velocity; step 2 uses the old one: x <- x + h v_n."},
        {Mistake::OmegaBeforeOrientation, "omega-before-orientation", "r <- r + h/2 (0, omega_{n+1}) r",
         "The orientation was turned with the new omega; step 4 uses the old one: r <- r + h/2 (0, omega_n) r."},
        {Mistake::TransposedInertia, "transposed-inertia", "I^-1 = R^T I0^-1 R",
         "The inverse inertia was rotated the wrong way round; the world frame needs I^-1 = R I0^-1 R^T."},
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

namespace {

// --- the mistakes, one small function each ---

// I0 = M/12 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2); half-extents-for-size puts a/2, b/2, c/2 in;
// inertia-axes-swapped exchanges two moments (variant 0: x and y, 1: y and z, 2: x and z)
Mat3 bodyInertia(const Vec3& size, double M, Mistake m, int variant)
{
    Mat3 I0 = boxInertiaBody(m == Mistake::HalfExtentsForSize ? Vec3(0.5 * size) : size, M);
    // inertia-half-extents-without-third: M diag(...) of a/2, b/2, c/2 = 12/4 = 3 times I0
    if (m == Mistake::InertiaHalfExtentsWithoutThird) I0 *= 3.0;
    if (m == Mistake::InertiaAxesSwapped) {
        static const int pairs[3][2] = {{0, 1}, {1, 2}, {0, 2}};
        const int i = pairs[variant % 3][0], j = pairs[variant % 3][1];
        std::swap(I0(i, i), I0(j, j));
    }
    return I0;
}

// The orientation at the start; quaternion-without-half-angle builds the initial one as
// (cos th, n sin th) for (cos th/2, n sin th/2): the angle doubled, r0^2
Quat startOrientation(const Quat& r0, bool firstStep, Mistake m)
{
    if (m != Mistake::QuaternionWithoutHalfAngle || !firstStep) return r0;
    return (r0 * r0).normalized();
}

// q_i = (p_i - x) x f_i;  torque-reversed: f_i x (p_i - x);  lever-arm-from-origin: p_i x f_i
Vec3 torqueOf(const Vec3& p, const Vec3& f, const Vec3& x, Mistake m)
{
    if (m == Mistake::TorqueReversed) return f.cross(p - x);
    if (m == Mistake::LeverArmFromOrigin) return p.cross(f);
    return (p - x).cross(f);
}

// h, or 1 for missing-time-step (L <- L + q, v <- v + F/M)
double stepFactor(double h, Mistake m)
{
    return m == Mistake::MissingTimeStep ? 1.0 : h;
}

// r <- r + (h/2) (0, omega) r, normalised; quaternion-missing-half: h instead of h/2;
// quaternion-not-normalised: no normalisation
Quat turned(const Quat& r, const Vec3& omega_W, double h, Mistake m)
{
    const double a = m == Mistake::QuaternionMissingHalf ? h : 0.5 * h;
    const Quat rDot = Quat(0.0, omega_W.x(), omega_W.y(), omega_W.z()) * r;
    Quat out = r;
    out.coeffs() += a * rDot.coeffs();
    if (m != Mistake::QuaternionNotNormalised) out.coeffs() /= out.coeffs().norm();
    return out;
}

// I^-1 = R I0^-1 R^T in the body's convention; transposed-inertia: the other way round
Mat3 worldInverseInertia(const Mat3& R, const Mat3& I0inv, InertiaConvention c, Mistake m)
{
    if (m == Mistake::TransposedInertia) {
        c = c == InertiaConvention::Standard ? InertiaConvention::CourseTemplate : InertiaConvention::Standard;
    }
    return inverseInertiaWorld(R, I0inv, c);
}

// omega = I^-1 L;  body-inverse-inertia: I0^-1 L;  inertia-not-inverted: I L, I = R I0 R^T
Vec3 angularVelocity(const Mat3& Iinv_W, const Mat3& R, const Mat3& I0, const Mat3& I0inv, const Vec3& L,
                     Mistake m)
{
    if (m == Mistake::BodyInverseInertia) return I0inv * L;
    if (m == Mistake::InertiaNotInverted) return Mat3(R * I0 * R.transpose()) * L;
    return Iinv_W * L;
}

// The rotational term [(I^-1 (x x n)) x x] . n;  impulse-denominator-missing-cross: (I^-1 (x x n)) . n
double rotationalTerm(const Mat3& Iinv, const Vec3& x, const Vec3& n, Mistake m)
{
    const Vec3 Iinv_xn = Iinv * x.cross(n);
    if (m == Mistake::ImpulseDenominatorMissingCross) return Iinv_xn.dot(n);
    return Iinv_xn.cross(x).dot(n);
}

// v_p = v + omega x (p - x);  point-velocity-without-rotation: v;
// point-velocity-cross-reversed: v + (p - x) x omega;  point-velocity-lever-arm-from-origin: v + omega x p
Vec3 pointVelocityOf(const Vec3& v, const Vec3& omega, const Vec3& p, const Vec3& x, Mistake m)
{
    if (m == Mistake::PointVelocityWithoutRotation) return v;
    if (m == Mistake::PointVelocityCrossReversed) return v + (p - x).cross(omega);
    if (m == Mistake::PointVelocityLeverArmFromOrigin) return v + omega.cross(p);
    return v + omega.cross(p - x);
}

} // namespace

HandEulerStep handEulerStep(const BodyStepInputs& in, Mistake m, int variant)
{
    HandEulerStep s;
    const double M = in.mass;
    s.I0_B = bodyInertia(in.size, M, m, variant);
    s.I0inv_B = Mat3::Zero();
    for (int i = 0; i < 3; ++i) s.I0inv_B(i, i) = 1.0 / s.I0_B(i, i);

    // The start of the step: R, I^-1 and omega of r_n and L_n (these carry no mistake of
    // this step: the student checks one step from the workbook's state), except the
    // mistakes made in setting the body up (its I0 or initial orientation).
    const bool setUp = m == Mistake::InertiaAxesSwapped || m == Mistake::QuaternionWithoutHalfAngle;
    const Quat r0 = startOrientation(in.q_WB, in.firstStep, m);
    const Mat3 R0 = r0.toRotationMatrix();
    const Mat3 I0inv_true = [&] {
        const Mat3 I0 = boxInertiaBody(in.size, M);
        Mat3 inv = Mat3::Zero();
        for (int i = 0; i < 3; ++i) inv(i, i) = 1.0 / I0(i, i);
        return inv;
    }();
    const Mat3 Iinv0 = inverseInertiaWorld(R0, setUp ? s.I0inv_B : I0inv_true, in.convention);
    const Vec3 omega0 = in.omega_W ? *in.omega_W : Vec3(Iinv0 * in.L_W);

    // Step 1: F = sum f_i + M g,  q = sum (p_i - x) x f_i + sum q_j
    s.F_W = M * in.g_W;
    s.q_W = in.couple_W;
    for (const auto& [p, f] : in.forces) {
        s.F_W += f;
        s.q_W += torqueOf(p, f, in.x_W, m);
    }
    const double hs = stepFactor(in.h, m);
    // Step 3 (needed by a student who moves x with the new v): v <- v + h F/M
    s.v_W = in.v_W + (hs / M) * s.F_W;
    // Step 2: x <- x + h v_n
    s.x_W = in.x_W + in.h * (m == Mistake::VelocityBeforePosition ? s.v_W : in.v_W);
    // Step 5: L <- L + h q
    s.L_W = in.L_W + hs * s.q_W;
    // Step 4: r <- r + h/2 (0, omega_n) r, normalised
    const Vec3 omegaUsed =
        m == Mistake::OmegaBeforeOrientation ? Vec3(Iinv0 * s.L_W) : omega0;   // new omega: I^-1(r_n) L_{n+1}
    s.q_WB = turned(r0, omegaUsed, in.h, m);
    // Steps 6-7: R = R(r), I^-1 = R I0^-1 R^T, omega = I^-1 L
    s.R_WB = s.q_WB.toRotationMatrix();
    s.Iinv_W = worldInverseInertia(s.R_WB, s.I0inv_B, in.convention, m);
    s.omega_W = angularVelocity(s.Iinv_W, s.R_WB, s.I0_B, s.I0inv_B, s.L_W, m);
    // omega-accumulated: omega' = omega_n + I^-1 L'
    if (m == Mistake::OmegaAccumulated) s.omega_W += omega0;
    // Step 8: p = x + R p_B,  v_p = v + omega x (p - x)
    for (const Vec3& p_B : in.probes_B) {
        const Vec3 p = s.x_W + s.R_WB * p_B;
        s.probe_W.push_back(p);
        s.probeVelocity_W.push_back(pointVelocityOf(s.v_W, s.omega_W, p, s.x_W, m));
    }
    return s;
}

bool HandEulerStep::value(std::string_view id, int index, TraceValue& out) const
{
    const std::pair<const QuantityInfo*, TraceValue> rows[] = {
        {&q::inertia_body, I0_B},       {&q::inverse_inertia_body, I0inv_B},
        {&q::force, F_W},               {&q::torque, q_W},
        {&q::position, x_W},            {&q::linear_velocity, v_W},
        {&q::orientation, q_WB},        {&q::angular_momentum, L_W},
        {&q::rotation_matrix, R_WB},    {&q::inverse_inertia_world, Iinv_W},
        {&q::inverse_inertia_world_template, Iinv_W},   // a template-convention body's row
        {&q::angular_velocity, omega_W},
    };
    for (const auto& [info, v] : rows) {
        if (id == info->id) {
            out = v;
            return true;
        }
    }
    if (index >= 0 && index < static_cast<int>(probe_W.size())) {
        if (id == q::probe_position.id) {
            out = probe_W[index];
            return true;
        }
        if (id == q::point_velocity.id) {
            out = probeVelocity_W[index];
            return true;
        }
    }
    return false;
}

HandImpulse handImpulse(const ContactInputs& in, Mistake m)
{
    HandImpulse r;
    const Vec3& n = in.g.n_W;
    // x_a = p - x_A,  x_b = p - x_B;  impulse-lever-arm-from-origin: x_a = x_b = p
    const bool fromOrigin = m == Mistake::ImpulseLeverArmFromOrigin;
    r.x_a = fromOrigin ? in.g.p_W : Vec3(in.g.p_W - in.x_A);
    r.x_b = fromOrigin ? in.g.p_W : Vec3(in.g.p_W - in.x_B);
    // v_A(p) = v_A + omega_A x x_a (and B)
    r.velocity_a = in.v_A + in.omega_A.cross(r.x_a);
    r.velocity_b = in.v_B + in.omega_B.cross(r.x_b);
    // v_rel = v_A(p) - v_B(p);  relative-velocity-reversed: v_B(p) - v_A(p)
    r.v_rel = m == Mistake::RelativeVelocityReversed ? Vec3(r.velocity_b - r.velocity_a)
                                                     : Vec3(r.velocity_a - r.velocity_b);
    r.v_rel_n = r.v_rel.dot(n);
    // numerator -(1 + c) v_rel.n;  impulse-without-one-plus: -c v_rel.n;  restitution-one-minus: -(1 - c) v_rel.n
    const double bounce = m == Mistake::ImpulseWithoutOnePlus ? in.restitution
                          : m == Mistake::RestitutionOneMinus ? 1.0 - in.restitution
                                                              : 1.0 + in.restitution;
    r.numerator = -bounce * r.v_rel_n;
    // 1/M_A + 1/M_B + [(I_A^-1 (x_a x n)) x x_a] . n + [...]_B;  impulse-linear-only: 1/M_A + 1/M_B
    // (impulse-linear-only computes the terms right but leaves them out of the sum)
    r.rotational_a = rotationalTerm(in.Iinv_A, r.x_a, n, m);
    r.rotational_b = rotationalTerm(in.Iinv_B, r.x_b, n, m);
    r.denominator = in.invM_A + in.invM_B;
    if (m != Mistake::ImpulseLinearOnly) r.denominator += r.rotational_a + r.rotational_b;
    // J = numerator / denominator; no impulse when separating (v_rel . n > 0), unless the
    // student forgot the check (no-separating-check) or a mistake of theirs flipped v_rel
    const bool checksSeparation = m != Mistake::NoSeparatingCheck && m != Mistake::RelativeVelocityReversed;
    r.J = (checksSeparation && r.v_rel_n > 0.0) ? 0.0 : r.numerator / r.denominator;
    return r;
}

bool HandImpulse::value(std::string_view id, TraceValue& out) const
{
    const std::pair<const QuantityInfo*, TraceValue> rows[] = {
        {&q::x_a, x_a},
        {&q::x_b, x_b},
        {&q::velocity_a, velocity_a},
        {&q::velocity_b, velocity_b},
        {&q::relative_velocity, v_rel},
        {&q::normal_velocity, v_rel_n},
        {&q::numerator, numerator},
        {&q::rotational_a, rotational_a},
        {&q::rotational_b, rotational_b},
        {&q::denominator, denominator},
        {&q::impulse, J},
    };
    for (const auto& [info, v] : rows) {
        if (id == info->id) {
            out = v;
            return true;
        }
    }
    return false;
}

} // namespace rbw
