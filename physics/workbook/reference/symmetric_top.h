// Reference: the torque-free symmetric top, I0 = diag(I1, I1, I3), in closed form.
//
// Body frame (Euler's equations, L_B' = L_B x omega_B with omega_B = I0^-1 L_B):
//   L_B(t) = (L_perp sin(Omega t + phi0), L_perp cos(Omega t + phi0), L3),
//   Omega  = L3 (I1 - I3) / (I1 I3),   L_perp = |(L_B,x, L_B,y)|,  phi0 = atan2(L_B,x, L_B,y)
// (docs/references.md §5; Landau & Lifshitz, Mechanics, section 33, problem 1 and
// section 36). Check: L_B x omega_B = (Omega L_y, -Omega L_x, 0), which is L_B'.
//
// Orientation: omega_B = L_B/I1 + Omega e3, so omega_W = L_W/I1 + Omega R e3 and
//   R' = [L_W/I1]x R + R [Omega e3]x   =>   R(t) = Rot(L_W, |L| t/I1) R0 Rot(e3, Omega t):
// precession about the fixed world L at the rate |L|/I1, composed with the body spin
// Omega about the symmetry axis e3. In quaternions q(t) = p(t) q0 s(t).
// Then R(t)^T L_W = Rot(e3, -Omega t) L_B(0), the body-frame formula above.
//
// Worked case (docs/references.md §5): I = (3, 3, 9), L_B(0) = (0, 5, 7): Omega = 7 (3 - 9)/27 = -14/9,
// L_perp = 5, phi0 = 0, |L| = sqrt(74), precession rate sqrt(74)/3.
#pragma once

#include "physics/workbook/reference/exact_state.h"

#include <optional>
#include <string>

namespace rbw::reference {

class SymmetricTop {
public:
    // Fails unless I1 > 0, I3 > 0 and everything is finite.
    static std::optional<SymmetricTop> make(double I1, double I3, const Quat& q0_WB, const Vec3& L0_B,
                                            std::string& error);

    double Omega() const;            // L3 (I1 - I3)/(I1 I3), body-frame rate of L_B about e3
    double precessionRate() const;   // |L|/I1
    Vec3 L_B(double t) const;
    Vec3 omega_B(double t) const;    // I0^-1 L_B(t)
    Vec3 L_W() const;                // R0 L_B(0), constant
    Quat orientation(double t) const;
    double kineticEnergy() const;    // T = 1/2 L_B . I0^-1 L_B, constant
    Vec3 inertia() const { return Vec3(I1_, I1_, I3_); }
    ExactState at(double t) const;   // x = 0, v = 0

private:
    SymmetricTop(double I1, double I3, const Quat& q0_WB, const Vec3& L0_B)
        : I1_(I1), I3_(I3), q0_WB_(q0_WB), L0_B_(L0_B) {}
    double I1_;
    double I3_;
    Quat q0_WB_;
    Vec3 L0_B_;
};

} // namespace rbw::reference
