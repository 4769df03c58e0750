// Reference: free spin about a principal axis.
//
// If omega is along a principal axis e of the body, L = I omega = I_e omega is
// parallel to omega, so Euler's equations I0 omega_B' = -omega_B x I0 omega_B give
// omega_B' = 0: omega stays constant in the body and, since R' = [omega]x R rotates
// about omega itself, in the world too. The orientation is then
//   q(t) = exp(1/2 (0, omega) t) q0 = [cos(|omega| t/2), omega/|omega| sin(|omega| t/2)] q0
// (quaternion product; Baraff, SIGGRAPH 2001 notes, section 2.9; Landau & Lifshitz,
// Mechanics, section 36, "free rotation about a principal axis").
//
// Glossary
//   I0    principal moments (I_x, I_y, I_z), body frame        [kg m^2]
//   q0    orientation at t = 0, body -> world
//   omega angular velocity, world frame, constant              [rad/s]
#pragma once

#include "physics/workbook/reference/exact_state.h"

#include <optional>
#include <string>

namespace rbw::reference {

class ConstantSpin {
public:
    // Fails (nullopt, error set) unless I0 > 0 and omega_W is along a principal axis of
    // the body at q0 (|omega_B x I0 omega_B| <= 1e-12 |omega_B| |I0 omega_B|).
    static std::optional<ConstantSpin> make(const Vec3& I0_B, const Quat& q0_WB, const Vec3& omega_W,
                                            std::string& error);

    Quat orientation(double t) const;                     // exp(1/2 omega t) q0
    const Vec3& omega_W() const { return omega_W_; }       // constant
    Vec3 L_W() const;                                      // R0 I0 R0^T omega, constant
    double kineticEnergy() const { return 0.5 * omega_W_.dot(L_W()); }   // T = 1/2 omega . L
    // x = 0, v = 0 (a spinning body at rest at the origin).
    ExactState at(double t) const;

private:
    ConstantSpin(const Vec3& I0_B, const Quat& q0_WB, const Vec3& omega_W)
        : I0_B_(I0_B), q0_WB_(q0_WB), omega_W_(omega_W) {}
    Vec3 I0_B_;
    Quat q0_WB_;
    Vec3 omega_W_;
};

} // namespace rbw::reference
