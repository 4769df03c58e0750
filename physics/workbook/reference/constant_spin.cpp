#include "physics/workbook/reference/constant_spin.h"

#include <cmath>

namespace rbw::reference {

std::optional<ConstantSpin> ConstantSpin::make(const Vec3& I0_B, const Quat& q0_WB, const Vec3& omega_W,
                                               std::string& error)
{
    if (!(I0_B.allFinite() && I0_B.minCoeff() > 0.0)) {
        error = "constant spin: the principal moments must be finite and > 0";
        return std::nullopt;
    }
    if (!(isFinite(q0_WB) && q0_WB.norm() > 0.0 && omega_W.allFinite())) {
        error = "constant spin: q0 and omega must be finite, q0 non-zero";
        return std::nullopt;
    }
    const Quat q0 = q0_WB.normalized();
    // omega_B = R0^T omega; along a principal axis iff omega_B x I0 omega_B = 0
    const Vec3 omega_B = q0.conjugate() * omega_W;
    const Vec3 L_B = I0_B.asDiagonal() * omega_B;
    if (omega_B.cross(L_B).norm() > 1e-12 * omega_B.norm() * L_B.norm()) {
        error = "constant spin: omega is not along a principal axis, so it would not stay constant";
        return std::nullopt;
    }
    return ConstantSpin(I0_B, q0, omega_W);
}

Quat ConstantSpin::orientation(double t) const
{
    // q(t) = [cos(|omega| t/2), n sin(|omega| t/2)] q0,  n = omega/|omega|
    const double w = omega_W_.norm();
    if (w == 0.0) {
        return q0_WB_;
    }
    const Quat spin(Eigen::AngleAxisd(w * t, omega_W_ / w));
    return spin * q0_WB_;
}

Vec3 ConstantSpin::L_W() const
{
    // L = R0 I0 R0^T omega
    const Mat3 R0 = q0_WB_.toRotationMatrix();
    return R0 * (I0_B_.asDiagonal() * (R0.transpose() * omega_W_));
}

ExactState ConstantSpin::at(double t) const
{
    ExactState s;
    s.q_WB = orientation(t);
    s.omega_W = omega_W_;
    s.L_W = L_W();
    return s;
}

} // namespace rbw::reference
