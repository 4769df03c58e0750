// The orientation of the torque-free asymmetric top, which physics/workbook/reference/
// asymmetric_top.h leaves out: R_WB(t), given omega_B(t) and L_B(t) from the Jacobi
// elliptic solution.
//
// Method (Landau & Lifshitz, Mechanics, section 37). Take Euler angles (phi, theta, psi)
// in the z-x-z convention about a frame Z whose axis Z is the fixed direction of L:
//   R_ZB(t) = Rz(phi) Rx(theta) Rz(psi).
// Then R_ZB^T e_Z = L_B/|L| = (sin theta sin psi, sin theta cos psi, cos theta), so theta
// and psi follow from L_B(t) alone:
//   cos theta = L_B,z/|L|,   psi = atan2(L_B,x, L_B,y)                      (L-L 37.13)
// and the precession angle phi from
//   phi' = |L| (I1 w1^2 + I2 w2^2) / (I1^2 w1^2 + I2^2 w2^2)                (L-L 37.14)
// which L-L integrate with theta functions (an elliptic integral of the third kind).
// Here phi(t) = integral_0^t phi' ds is taken by 30-point Gauss-Legendre quadrature
// (Boost.Math) on pieces of 1/16 of omega_B's period; phi' is analytic and bounded
// (between |L|/I2 and |L|/I1 for I1 < I2), so each piece is exact to rounding.
// The fixed frame Z is found from t = 0: R_WB(t) = R_WB(0) E(0)^T E(t),
// E(t) = Rz(phi(t)) Rx(theta(t)) Rz(psi(t)), phi(0) = 0.
//
// Glossary
//   q0_WB     orientation at t = 0, body -> world
//   L_B, w_B  angular momentum and angular velocity in the body frame (the top's frame,
//             I1 < I2 < I3 along body x, y, z)
//   E(t)      body -> "L frame" rotation of the Euler angles
#pragma once

#include "physics/engine/math_types.h"
#include "physics/workbook/reference/asymmetric_top.h"

namespace rbw::lab {

class AsymmetricTopOrientation {
public:
    AsymmetricTopOrientation(const reference::AsymmetricTop& top, const Quat& q0_WB);

    Quat orientation(double t) const;          // q_WB(t)
    Vec3 omega_W(double t) const;              // R_WB(t) omega_B(t)
    Vec3 L_W() const { return L_W_; }          // R_WB(0) L_B(0), constant
    const reference::AsymmetricTop& top() const { return top_; }

private:
    Mat3 eulerRotation(double t, double phi) const;   // E(t) with the given phi
    double precessionAngle(double t) const;           // phi(t), by quadrature

    reference::AsymmetricTop top_;
    Mat3 R0_WB_;
    Mat3 E0_;        // E(0)
    Vec3 L_W_;
};

} // namespace rbw::lab
