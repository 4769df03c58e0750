// The exact motion of a scene, when it has one: the reference an accuracy study
// measures every integrator against.
//
// A scene has an exact answer if it is a single free box: one movable body, no forces,
// no torques, no planes, the standard inertia convention. Then the centre of mass
// moves as a projectile (x0 + v0 t + 1/2 g t^2, v0 + g t; no gravity: g = 0) and the
// rotation, which gravity does not touch, is one of
//   - constant spin, if omega0 is along a principal axis (reference/constant_spin.h);
//   - the symmetric top, if two principal moments are equal (reference/symmetric_top.h);
//   - the asymmetric top otherwise (reference/asymmetric_top.h, orientation from
//     lab/asymmetric_top_orientation.h).
// The principal moments come from the box's size and mass (inertia.h). The top
// references want their special axis last (symmetric: the unequal moment; asymmetric:
// I1 < I2 < I3), so the body axes are relabelled by a proper rotation C_BP (a signed
// permutation, det +1) into a "principal" frame P:  q_WP = q_WB * q(C_BP).
//
// Glossary
//   x0_W, v0_W, g_W  initial position and velocity, gravity         [m], [m/s], [m/s^2]
//   I0_B             principal moments of the box, body frame       [kg m^2]
//   C_BP             P -> B relabelling of the body axes
#pragma once

#include "physics/workbook/lab/asymmetric_top_orientation.h"
#include "physics/engine/math_types.h"
#include "physics/workbook/reference/constant_spin.h"
#include "physics/workbook/reference/exact_state.h"
#include "physics/workbook/reference/symmetric_top.h"
#include "physics/engine/scene.h"

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace rbw::lab {

enum class RotationKind { ConstantSpin, SymmetricTop, AsymmetricTop };

class ExactMotion {
public:
    // The exact motion of the scene, or nullopt with the reasons it has none (in the
    // scene file's terms: {"bodies", "an exact reference needs exactly one body, ..."}).
    static std::optional<ExactMotion> fromScene(const SceneDef& scene, std::vector<SceneIssue>& reasons);

    reference::ExactState at(double t) const;   // x, v, q_WB, L_W, omega_W at time t
    RotationKind rotationKind() const { return kind_; }
    bool hasGravity() const { return g_W_ != Vec3::Zero(); }
    // One line, e.g. "symmetric top (I = 0.4167, 0.4167, 0.1667), no gravity".
    std::string describe() const;

private:
    using Rotation = std::variant<reference::ConstantSpin, reference::SymmetricTop, AsymmetricTopOrientation>;
    ExactMotion(const Vec3& x0_W, const Vec3& v0_W, const Vec3& g_W, const Vec3& I0_B, const Mat3& C_BP,
                RotationKind kind, Rotation rotation)
        : x0_W_(x0_W), v0_W_(v0_W), g_W_(g_W), I0_B_(I0_B), C_BP_(C_BP), kind_(kind), rotation_(std::move(rotation)) {}

    Vec3 x0_W_;
    Vec3 v0_W_;
    Vec3 g_W_;
    Vec3 I0_B_;
    Mat3 C_BP_;
    RotationKind kind_;
    Rotation rotation_;
};

const char* rotationKindName(RotationKind kind);   // "constant spin", "symmetric top", "asymmetric top"

} // namespace rbw::lab
