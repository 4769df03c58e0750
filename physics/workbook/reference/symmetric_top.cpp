#include "physics/workbook/reference/symmetric_top.h"

#include <cmath>

namespace rbw::reference {

std::optional<SymmetricTop> SymmetricTop::make(double I1, double I3, const Quat& q0_WB, const Vec3& L0_B,
                                               std::string& error)
{
    if (!(std::isfinite(I1) && std::isfinite(I3) && I1 > 0.0 && I3 > 0.0)) {
        error = "symmetric top: I1 and I3 must be finite and > 0";
        return std::nullopt;
    }
    if (!(isFinite(q0_WB) && q0_WB.norm() > 0.0 && L0_B.allFinite())) {
        error = "symmetric top: q0 and L0 must be finite, q0 non-zero";
        return std::nullopt;
    }
    return SymmetricTop(I1, I3, q0_WB.normalized(), L0_B);
}

double SymmetricTop::Omega() const
{
    // Omega = L3 (I1 - I3) / (I1 I3)
    return L0_B_.z() * (I1_ - I3_) / (I1_ * I3_);
}

double SymmetricTop::precessionRate() const
{
    // |L| / I1
    return L0_B_.norm() / I1_;
}

Vec3 SymmetricTop::L_B(double t) const
{
    // L_B(t) = (L_perp sin(Omega t + phi0), L_perp cos(Omega t + phi0), L3)
    const double Lperp = std::hypot(L0_B_.x(), L0_B_.y());
    const double phi0 = std::atan2(L0_B_.x(), L0_B_.y());
    const double phase = Omega() * t + phi0;
    return Vec3(Lperp * std::sin(phase), Lperp * std::cos(phase), L0_B_.z());
}

Vec3 SymmetricTop::omega_B(double t) const
{
    // omega_B = I0^-1 L_B
    const Vec3 L = L_B(t);
    return Vec3(L.x() / I1_, L.y() / I1_, L.z() / I3_);
}

Vec3 SymmetricTop::L_W() const
{
    // L_W = R0 L_B(0)
    return q0_WB_ * L0_B_;
}

Quat SymmetricTop::orientation(double t) const
{
    // q(t) = p(t) q0 s(t):  p = rotation by |L| t / I1 about L_W,  s = rotation by Omega t about e3
    const Vec3 L = L_W();
    const double Lnorm = L.norm();
    const Quat p = Lnorm > 0.0 ? Quat(Eigen::AngleAxisd(precessionRate() * t, L / Lnorm)) : Quat::Identity();
    const Quat s(Eigen::AngleAxisd(Omega() * t, Vec3::UnitZ()));
    return p * q0_WB_ * s;
}

double SymmetricTop::kineticEnergy() const
{
    // T = 1/2 L_B . I0^-1 L_B
    return 0.5 * L0_B_.dot(omega_B(0.0));
}

ExactState SymmetricTop::at(double t) const
{
    ExactState s;
    s.q_WB = orientation(t);
    s.L_W = L_W();
    s.omega_W = s.q_WB * omega_B(t);
    return s;
}

} // namespace rbw::reference
