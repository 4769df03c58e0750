#include "physics/workbook/lab/exact_motion.h"

#include "physics/engine/inertia.h"
#include "physics/workbook/reference/asymmetric_top.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace rbw::lab {

namespace {

// Two moments count as equal within this relative tolerance. A box with two equal
// edges gives bitwise equal moments (the same sums of squares), so rounding never
// comes near it; a truly asymmetric box is far from it.
constexpr double kEqualMoments = 1e-12;

bool nearlyEqual(double a, double b) { return std::abs(a - b) <= kEqualMoments * std::max(a, b); }

// C_BP: the columns are the body axes perm[0], perm[1], perm[2]; an odd permutation
// negates the last one so that det C = +1 (C is a rotation, P a right-handed frame).
Mat3 relabelling(const std::array<int, 3>& perm)
{
    Mat3 C = Mat3::Zero();
    for (int j = 0; j < 3; ++j) C(perm[j], j) = 1.0;
    if (C.determinant() < 0.0) C.col(2) = -C.col(2);
    return C;
}

std::string number(double x)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", x);
    return buf;
}

} // namespace

const char* rotationKindName(RotationKind kind)
{
    switch (kind) {
    case RotationKind::ConstantSpin: return "constant spin";
    case RotationKind::SymmetricTop: return "symmetric top";
    case RotationKind::AsymmetricTop: return "asymmetric top";
    }
    return "";
}

std::optional<ExactMotion> ExactMotion::fromScene(const SceneDef& scene, std::vector<SceneIssue>& reasons)
{
    reasons.clear();
    // The closed forms cover one free box in free flight: check that first.
    if (scene.bodies.size() != 1) {
        reasons.push_back({"bodies", "an exact reference needs exactly one body, the scene has " +
                                         std::to_string(scene.bodies.size())});
        return std::nullopt;
    }
    const BodyDef& body = scene.bodies[0];
    if (body.fixed) reasons.push_back({"bodies[0].fixed", "an exact reference needs a movable body"});
    if (!scene.forces.empty()) {
        reasons.push_back({"forces", "an exact reference needs a torque-free body in free flight, the scene has " +
                                         std::to_string(scene.forces.size()) + " force(s)"});
    }
    if (!scene.torques.empty()) {
        reasons.push_back({"torques", "an exact reference needs a torque-free body, the scene has " +
                                          std::to_string(scene.torques.size()) + " torque(s)"});
    }
    if (!scene.planes.empty()) {
        reasons.push_back({"planes", "an exact reference needs free flight without collisions, the scene has " +
                                         std::to_string(scene.planes.size()) + " plane(s)"});
    }
    if (scene.inertiaConvention != InertiaConvention::Standard) {
        reasons.push_back({"inertia_convention", "the exact references solve the standard convention "
                                                 "(I^-1 = R I0^-1 R^T); the course-template form is another ODE"});
    }
    if (!reasons.empty()) return std::nullopt;

    // I0 = M/12 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2)   (inertia.h)
    const Mat3 I0 = boxInertiaBody(body.size, body.mass);
    const Vec3 I0_B = I0.diagonal();
    const Quat q0_WB = body.q0_WB.normalized();
    // omega0_B = R0^T omega0_W, L0_B = I0 omega0_B   (L0 = I(r0) omega0, body.h)
    const Vec3 omega0_B = q0_WB.conjugate() * body.omega0_W;
    const Vec3 L0_B = I0_B.asDiagonal() * omega0_B;
    std::string error;

    // Constant spin: omega_B x I0 omega_B = 0 (Euler's equations give omega' = 0).
    if (std::optional<reference::ConstantSpin> spin = reference::ConstantSpin::make(I0_B, q0_WB, body.omega0_W, error)) {
        return ExactMotion(body.x0_W, body.v0_W, scene.g_W, I0_B, Mat3::Identity(), RotationKind::ConstantSpin, *spin);
    }

    // Symmetric top: two equal moments; relabel so the unequal axis is P's z.
    for (int odd = 0; odd < 3; ++odd) {
        const int a = (odd + 1) % 3;
        const int b = (odd + 2) % 3;
        if (!nearlyEqual(I0_B[a], I0_B[b])) continue;
        const Mat3 C_BP = relabelling({a, b, odd});
        const Quat q0_WP = q0_WB * Quat(C_BP);
        const Vec3 L0_P = C_BP.transpose() * L0_B;
        std::optional<reference::SymmetricTop> top =
            reference::SymmetricTop::make(I0_B[a], I0_B[odd], q0_WP, L0_P, error);
        if (!top) {
            reasons.push_back({"bodies[0]", error});
            return std::nullopt;
        }
        return ExactMotion(body.x0_W, body.v0_W, scene.g_W, I0_B, C_BP, RotationKind::SymmetricTop, *top);
    }

    // Asymmetric top: relabel so that I1 < I2 < I3 along P's x, y, z.
    std::array<int, 3> perm{0, 1, 2};
    std::sort(perm.begin(), perm.end(), [&I0_B](int i, int j) { return I0_B[i] < I0_B[j]; });
    const Mat3 C_BP = relabelling(perm);
    const Quat q0_WP = q0_WB * Quat(C_BP);
    const Vec3 I_P(I0_B[perm[0]], I0_B[perm[1]], I0_B[perm[2]]);
    const Vec3 L0_P = C_BP.transpose() * L0_B;
    std::optional<reference::AsymmetricTop> top = reference::AsymmetricTop::make(I_P, L0_P, error);
    if (!top) {
        reasons.push_back({"bodies[0].angular_velocity", error});
        return std::nullopt;
    }
    return ExactMotion(body.x0_W, body.v0_W, scene.g_W, I0_B, C_BP, RotationKind::AsymmetricTop,
                       AsymmetricTopOrientation(*top, q0_WP));
}

reference::ExactState ExactMotion::at(double t) const
{
    reference::ExactState s;
    // x = x0 + v0 t + 1/2 g t^2,  v = v0 + g t   (Newton; gravity exerts no torque about x)
    s.x_W = x0_W_ + v0_W_ * t + 0.5 * g_W_ * t * t;
    s.v_W = v0_W_ + g_W_ * t;
    // The rotation in the principal frame P, then back to the body: q_WB = q_WP * q(C_BP)^-1
    const Quat q_PB(Mat3(C_BP_.transpose()));
    if (const auto* spin = std::get_if<reference::ConstantSpin>(&rotation_)) {
        const reference::ExactState r = spin->at(t);
        s.q_WB = r.q_WB;
        s.L_W = r.L_W;
        s.omega_W = r.omega_W;
    } else if (const auto* top = std::get_if<reference::SymmetricTop>(&rotation_)) {
        const reference::ExactState r = top->at(t);
        s.q_WB = (r.q_WB * q_PB).normalized();
        s.L_W = r.L_W;
        s.omega_W = r.omega_W;
    } else {
        const auto& asym = std::get<AsymmetricTopOrientation>(rotation_);
        const Quat q_WP = asym.orientation(t);
        s.q_WB = (q_WP * q_PB).normalized();
        s.L_W = asym.L_W();
        // omega_W = R_WP omega_P
        s.omega_W = q_WP * asym.top().omega_B(t);
    }
    return s;
}

std::string ExactMotion::describe() const
{
    std::string text = rotationKindName(kind_);
    text += " (I0 = " + number(I0_B_.x()) + ", " + number(I0_B_.y()) + ", " + number(I0_B_.z()) + ")";
    text += hasGravity() ? ", projectile under gravity" : ", no gravity";
    return text;
}

} // namespace rbw::lab
