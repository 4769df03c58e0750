#include "physics/workbook/checker/mistakes.h"

#include "physics/engine/inertia.h"
#include "physics/engine/quantities.h"

#include <cmath>
#include <utility>

namespace rbw {

namespace {

// --- the mistakes, one small function each ---

// I0 = M/12 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2); half-extents-for-size puts a/2, b/2, c/2 in;
// inertia-axes-swapped exchanges two moments (variant 0: x and y, 1: y and z, 2: x and z)
Mat3 bodyInertia(const Vec3& size, double M, const MistakeSet& ms)
{
    Mat3 I0 = boxInertiaBody(ms.has(Mistake::HalfExtentsForSize) ? Vec3(0.5 * size) : size, M);
    // inertia-half-extents-without-third: M diag(...) of a/2, b/2, c/2 = 12/4 = 3 times I0
    if (ms.has(Mistake::InertiaHalfExtentsWithoutThird)) I0 *= 3.0;
    if (ms.has(Mistake::InertiaAxesSwapped)) {
        static const int pairs[3][2] = {{0, 1}, {1, 2}, {0, 2}};
        const int i = pairs[ms.variant % 3][0], j = pairs[ms.variant % 3][1];
        std::swap(I0(i, i), I0(j, j));
    }
    return I0;
}

// angle-in-degrees: r0 = (cos th/2, n sin th/2) built with th in degrees fed to cos and
// sin as radians: th' = th * 180/pi, r0' = (cos th'/2, n sin th'/2)
Quat degreesAsRadians(const Quat& r0)
{
    const Vec3 v = r0.vec();
    const double s = v.norm();
    if (s == 0.0) return r0;   // no turn: 0 degrees are 0 radians
    const double half = 0.5 * (2.0 * std::atan2(s, r0.w())) * 180.0 / std::acos(-1.0);
    const Vec3 n = v / s;
    return Quat(std::cos(half), std::sin(half) * n.x(), std::sin(half) * n.y(), std::sin(half) * n.z());
}

// The orientation at the start; quaternion-without-half-angle builds the initial one as
// (cos th, n sin th) for (cos th/2, n sin th/2): the angle doubled, r0^2; angle-in-degrees
// as above; orientation-zero-quaternion: a body never given one keeps r = (0, 0, 0, 0)
Quat startOrientation(const BodyStepInputs& in, const MistakeSet& ms)
{
    if (ms.has(Mistake::OrientationZeroQuaternion) && !in.orientationSet) return Quat(0.0, 0.0, 0.0, 0.0);
    if (!in.firstStep) return in.q_WB;
    if (ms.has(Mistake::QuaternionWithoutHalfAngle)) return (in.q_WB * in.q_WB).normalized();
    if (ms.has(Mistake::AngleInDegrees)) return degreesAsRadians(in.q_WB);
    return in.q_WB;
}

// q_i = (p_i - x) x f_i;  torque-reversed: f_i x (p_i - x);  lever-arm-from-origin: p_i x f_i
// (both: f_i x p_i)
Vec3 torqueOf(const Vec3& p, const Vec3& f, const Vec3& x, const MistakeSet& ms)
{
    const Vec3 arm = ms.has(Mistake::LeverArmFromOrigin) ? p : Vec3(p - x);
    return ms.has(Mistake::TorqueReversed) ? f.cross(arm) : arm.cross(f);
}

// h, or 1 for missing-time-step (L <- L + q, v <- v + F/M)
double stepFactor(double h, const MistakeSet& ms)
{
    return ms.has(Mistake::MissingTimeStep) ? 1.0 : h;
}

// The acceleration of gravity: the scene's g;  gravity-always-on: g + (0, -9.81, 0) (the
// template's y is up) although the scene did not ask for it
Vec3 gravityOf(const Vec3& g_W, const MistakeSet& ms)
{
    return ms.has(Mistake::GravityAlwaysOn) ? Vec3(g_W + Vec3(0.0, -9.81, 0.0)) : g_W;
}

// r <- r + (h/2) (0, omega) r, normalised; quaternion-missing-half: h instead of h/2;
// quaternion-right-multiplied: r (0, omega); quaternion-not-normalised: no normalisation
// (nor for r = 0, which has no direction: orientation-zero-quaternion keeps it)
Quat turned(const Quat& r, const Vec3& omega_W, double h, const MistakeSet& ms)
{
    const double a = ms.has(Mistake::QuaternionMissingHalf) ? h : 0.5 * h;
    const Quat w(0.0, omega_W.x(), omega_W.y(), omega_W.z());
    const Quat rDot = ms.has(Mistake::QuaternionRightMultiplied) ? Quat(r * w) : Quat(w * r);
    Quat out = r;
    out.coeffs() += a * rDot.coeffs();
    const double n = out.coeffs().norm();
    if (!ms.has(Mistake::QuaternionNotNormalised) && n > 0.0) out.coeffs() /= n;
    return out;
}

// R X R^T in the body's convention (R^T X R in the template's); transposed-inertia: the
// other way round. X need not be diagonal (inertia-accumulated-rotation).
Mat3 rotatedInertia(const Mat3& R, const Mat3& X, InertiaConvention c, const MistakeSet& ms)
{
    const bool standard = (c == InertiaConvention::Standard) != ms.has(Mistake::TransposedInertia);
    return standard ? Mat3(R * X * R.transpose()) : Mat3(R.transpose() * X * R);
}

// The step's world I^-1 = R_{n+1} I0^-1 R_{n+1}^T;  inertia-from-old-orientation:
// R_n I0^-1 R_n^T;  inertia-not-updated: R_0 I0^-1 R_0^T of the body's first step, then the
// stored one;  inertia-accumulated-rotation: R_{n+1} I_s R_{n+1}^T, I_s last step's stored tensor
Mat3 stepInverseInertia(const Mat3& R_n, const Mat3& R_next, const Mat3& I0inv, const Mat3& stored,
                        const BodyStepInputs& in, const MistakeSet& ms)
{
    if (ms.has(Mistake::InertiaNotUpdated)) return in.firstStep ? rotatedInertia(R_n, I0inv, in.convention, ms) : stored;
    if (ms.has(Mistake::InertiaAccumulatedRotation)) return rotatedInertia(R_next, stored, in.convention, ms);
    if (ms.has(Mistake::InertiaFromOldOrientation)) return rotatedInertia(R_n, I0inv, in.convention, ms);
    return rotatedInertia(R_next, I0inv, in.convention, ms);
}

// omega = I^-1 L;  body-inverse-inertia: I0^-1 L;  inertia-not-inverted: I L, I = R I0 R^T
Vec3 angularVelocity(const Mat3& Iinv_W, const Mat3& R, const Mat3& I0, const Mat3& I0inv, const Vec3& L,
                     const MistakeSet& ms)
{
    if (ms.has(Mistake::BodyInverseInertia)) return I0inv * L;
    if (ms.has(Mistake::InertiaNotInverted)) return Mat3(R * I0 * R.transpose()) * L;
    return Iinv_W * L;
}

// The rotational term [(I^-1 (x x n)) x x] . n;  impulse-denominator-missing-cross:
// (I^-1 (x x n)) . n;  impulse-body-inverse-inertia: I0^-1 for I^-1
double rotationalTerm(const Mat3& Iinv, const Mat3& I0inv, const Vec3& x, const Vec3& n, const MistakeSet& ms)
{
    const Vec3 Iinv_xn = (ms.has(Mistake::ImpulseBodyInverseInertia) ? I0inv : Iinv) * x.cross(n);
    if (ms.has(Mistake::ImpulseDenominatorMissingCross)) return Iinv_xn.dot(n);
    return Iinv_xn.cross(x).dot(n);
}

// v_p = v + omega x (p - x);  point-velocity-without-rotation: v;
// point-velocity-cross-reversed: v + (p - x) x omega;  point-velocity-lever-arm-from-origin: v + omega x p
Vec3 pointVelocityOf(const Vec3& v, const Vec3& omega, const Vec3& p, const Vec3& x, const MistakeSet& ms)
{
    if (ms.has(Mistake::PointVelocityWithoutRotation)) return v;
    const Vec3 arm = ms.has(Mistake::PointVelocityLeverArmFromOrigin) ? p : Vec3(p - x);
    return ms.has(Mistake::PointVelocityCrossReversed) ? Vec3(v + arm.cross(omega)) : Vec3(v + omega.cross(arm));
}

Mat3 diagonalInverse(const Mat3& I0)
{
    Mat3 inv = Mat3::Zero();
    for (int i = 0; i < 3; ++i) inv(i, i) = 1.0 / I0(i, i);
    return inv;
}

} // namespace

HandEulerStep handEulerStep(const BodyStepInputs& in, const MistakeSet& ms)
{
    HandEulerStep s;
    const double M = in.mass;
    s.I0_B = bodyInertia(in.size, M, ms);
    s.I0inv_B = diagonalInverse(s.I0_B);

    // The start of the step: R, I^-1 and omega of r_n and L_n (these carry no mistake of
    // this step: the student checks one step from the workbook's state), except the
    // mistakes made in setting the body up (its I0 or initial orientation).
    const bool setUp = ms.has(Mistake::InertiaAxesSwapped) || ms.has(Mistake::QuaternionWithoutHalfAngle) ||
                       ms.has(Mistake::AngleInDegrees);
    const Quat r0 = startOrientation(in, ms);
    const Mat3 R0 = r0.toRotationMatrix();
    const Mat3 I0inv_start = setUp ? s.I0inv_B : diagonalInverse(boxInertiaBody(in.size, M));
    const Mat3 Iinv0 = rotatedInertia(R0, I0inv_start, in.convention, MistakeSet{});
    const Vec3 omega0 = in.omega_W ? *in.omega_W : Vec3(Iinv0 * in.L_W);

    // Step 1: F = sum f_i + M g,  q = sum (p_i - x) x f_i + sum q_j (+ the loads a
    // simulator never cleared: forces-not-cleared)
    s.loadsF_W = Vec3::Zero();
    s.loadsq_W = in.couple_W;
    for (const auto& [p, f] : in.forces) {
        s.loadsF_W += f;
        s.loadsq_W += torqueOf(p, f, in.x_W, ms);
    }
    if (ms.has(Mistake::ForcesNotCleared)) {
        s.loadsF_W += in.keptF_W;
        s.loadsq_W += in.keptq_W;
    }
    s.F_W = s.loadsF_W + M * gravityOf(in.g_W, ms);
    s.q_W = s.loadsq_W;
    const double hs = stepFactor(in.h, ms);
    // Step 3 (needed by a student who moves x with the new v): v <- v + h F/M
    s.v_W = in.v_W + (hs / M) * s.F_W;
    // Step 2: x <- x + h v_n
    s.x_W = in.x_W + in.h * (ms.has(Mistake::VelocityBeforePosition) ? s.v_W : in.v_W);
    // Step 5: L <- L + h q
    s.L_W = in.L_W + hs * s.q_W;
    // Step 4: r <- r + h/2 (0, omega_n) r, normalised
    const Vec3 omegaUsed = ms.has(Mistake::OmegaBeforeOrientation) ? Vec3(Iinv0 * s.L_W)
                                                                   : omega0;   // new omega: I^-1(r_n) L_{n+1}
    s.q_WB = turned(r0, omegaUsed, in.h, ms);
    // Steps 6-7: R = R(r), I^-1 = R I0^-1 R^T, omega = I^-1 L
    s.R_WB = s.q_WB.toRotationMatrix();
    const Mat3 stored = in.IinvStored_W ? *in.IinvStored_W : rotatedInertia(R0, s.I0inv_B, in.convention, ms);
    s.Iinv_W = stepInverseInertia(R0, s.R_WB, s.I0inv_B, stored, in, ms);
    s.omega_W = angularVelocity(s.Iinv_W, s.R_WB, s.I0_B, s.I0inv_B, s.L_W, ms);
    // omega-accumulated: omega' = omega_n + I^-1 L'
    if (ms.has(Mistake::OmegaAccumulated)) s.omega_W += omega0;
    // Step 8: p = x + R p_B,  v_p = v + omega x (p - x)
    for (const Vec3& p_B : in.probes_B) {
        const Vec3 p = s.x_W + s.R_WB * p_B;
        s.probe_W.push_back(p);
        s.probeVelocity_W.push_back(pointVelocityOf(s.v_W, s.omega_W, p, s.x_W, ms));
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

HandImpulse handImpulse(const ContactInputs& in, const MistakeSet& ms)
{
    HandImpulse r;
    const Vec3& n = in.g.n_W;
    // x_a = p - x_A,  x_b = p - x_B;  impulse-lever-arm-from-origin: x_a = x_b = p
    const bool fromOrigin = ms.has(Mistake::ImpulseLeverArmFromOrigin);
    r.x_a = fromOrigin ? in.g.p_W : Vec3(in.g.p_W - in.x_A);
    r.x_b = fromOrigin ? in.g.p_W : Vec3(in.g.p_W - in.x_B);
    // v_A(p) = v_A + omega_A x x_a (and B)
    r.velocity_a = in.v_A + in.omega_A.cross(r.x_a);
    r.velocity_b = in.v_B + in.omega_B.cross(r.x_b);
    // v_rel = v_A(p) - v_B(p);  relative-velocity-reversed: v_B(p) - v_A(p)
    r.v_rel = ms.has(Mistake::RelativeVelocityReversed) ? Vec3(r.velocity_b - r.velocity_a)
                                                     : Vec3(r.velocity_a - r.velocity_b);
    r.v_rel_n = r.v_rel.dot(n);
    // numerator -(1 + c) v_rel.n;  impulse-without-one-plus: -c v_rel.n;  restitution-one-minus: -(1 - c) v_rel.n
    const double bounce = ms.has(Mistake::ImpulseWithoutOnePlus) ? in.restitution
                          : ms.has(Mistake::RestitutionOneMinus) ? 1.0 - in.restitution
                                                                 : 1.0 + in.restitution;
    r.numerator = -bounce * r.v_rel_n;
    // 1/M_A + 1/M_B + [(I_A^-1 (x_a x n)) x x_a] . n + [...]_B;  impulse-linear-only: 1/M_A + 1/M_B
    // (impulse-linear-only computes the terms right but leaves them out of the sum)
    r.rotational_a = rotationalTerm(in.Iinv_A, in.I0inv_A, r.x_a, n, ms);
    r.rotational_b = rotationalTerm(in.Iinv_B, in.I0inv_B, r.x_b, n, ms);
    r.denominator = in.invM_A + in.invM_B;
    if (!ms.has(Mistake::ImpulseLinearOnly)) r.denominator += r.rotational_a + r.rotational_b;
    // J = numerator / denominator; no impulse when separating (v_rel . n > 0), unless the
    // student forgot the check (no-separating-check) or a mistake of theirs flipped v_rel
    const bool checksSeparation = !ms.has(Mistake::NoSeparatingCheck) && !ms.has(Mistake::RelativeVelocityReversed);
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
