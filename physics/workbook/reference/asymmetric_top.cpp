#include "physics/workbook/reference/asymmetric_top.h"

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>

#include <cmath>

namespace rbw::reference {

std::optional<AsymmetricTop> AsymmetricTop::make(const Vec3& I, const Vec3& L0_B, std::string& error)
{
    if (!(I.allFinite() && L0_B.allFinite())) {
        error = "asymmetric top: I and L0 must be finite";
        return std::nullopt;
    }
    if (!(0.0 < I.x() && I.x() < I.y() && I.y() < I.z())) {
        error = "asymmetric top: needs 0 < I1 < I2 < I3 (principal moments along body x, y, z)";
        return std::nullopt;
    }
    if (!(L0_B.norm() > 0.0)) {
        error = "asymmetric top: L0 must not be zero";
        return std::nullopt;
    }
    AsymmetricTop top;
    top.I_ = I;
    const Vec3 omega0_B = L0_B.cwiseQuotient(I);
    // L^2 and 2T = L . omega
    top.L2_ = L0_B.squaredNorm();
    top.twoT_ = L0_B.dot(omega0_B);
    // L^2 - 2T I2 = L1^2 (I1 - I2)/I1 + L3^2 (I3 - I2)/I3: the L2 terms cancel exactly,
    // so this is computed without cancellation even next to the separatrix.
    const double gap = L0_B.x() * L0_B.x() * (I.x() - I.y()) / I.x() + L0_B.z() * L0_B.z() * (I.z() - I.y()) / I.z();
    if (std::abs(gap) <= 1e-12 * top.L2_) {
        error = "asymmetric top: L^2 = 2 T I2 (separatrix): the motion is not periodic";
        return std::nullopt;
    }
    // Relabel for L^2 < 2T I2: I' = (I3, I2, I1), w = (omega3, -omega2, omega1)
    top.swapped_ = gap < 0.0;
    const Vec3 Ip = top.swapped_ ? Vec3(I.z(), I.y(), I.x()) : I;
    const Vec3 w0 = top.swapped_ ? Vec3(omega0_B.z(), -omega0_B.y(), omega0_B.x()) : omega0_B;
    const double L2 = top.L2_;
    const double twoT = top.twoT_;
    // Amplitudes (Landau 37.10)
    const double A1 = std::sqrt((twoT * Ip.z() - L2) / (Ip.x() * (Ip.z() - Ip.x())));
    const double A2 = std::sqrt((twoT * Ip.z() - L2) / (Ip.y() * (Ip.z() - Ip.y())));
    const double A3 = std::sqrt((L2 - twoT * Ip.x()) / (Ip.z() * (Ip.z() - Ip.x())));
    top.A_ = Vec3(A1, A2, A3);
    // lambda = sqrt((I3 - I2)(L^2 - 2T I1)/(I1 I2 I3))
    top.lambda_ = std::sqrt((Ip.z() - Ip.y()) * (L2 - twoT * Ip.x()) / (Ip.x() * Ip.y() * Ip.z()));
    // k^2 = (I2 - I1)(2T I3 - L^2) / ((I3 - I2)(L^2 - 2T I1))
    const double k2 = (Ip.y() - Ip.x()) * (twoT * Ip.z() - L2) / ((Ip.z() - Ip.y()) * (L2 - twoT * Ip.x()));
    // k'^2 = 1 - k^2 = (I3 - I1)(L^2 - 2T I2) / ((I3 - I2)(L^2 - 2T I1)), without cancellation
    // (I'2 = I2, so L^2 - 2T I'2 is the gap above in either frame)
    top.kPrime2_ = (Ip.z() - Ip.x()) * gap / ((Ip.z() - Ip.y()) * (L2 - twoT * Ip.x()));
    if (!(k2 >= 0.0 && k2 < 1.0 && top.A_.allFinite() && std::isfinite(top.lambda_))) {
        error = "asymmetric top: too close to the separatrix for the elliptic solution (k^2 = " +
                std::to_string(k2) + ")";
        return std::nullopt;
    }
    top.k_ = std::sqrt(k2);
    // Signs: s1 = +1, s3 = sign(omega3(0)), s2 from s1 s2 s3 = +1 (-1 when relabelled)
    const double s3 = w0.z() >= 0.0 ? 1.0 : -1.0;
    const double sigma = top.swapped_ ? -1.0 : 1.0;
    top.s_ = Vec3(1.0, sigma * s3, s3);
    // tau0 = F(phi0, k),  phi0 = atan2(sn, cn) of the initial state
    const double sn0 = A2 > 0.0 ? w0.y() / (top.s_.y() * A2) : 0.0;
    const double cn0 = A1 > 0.0 ? w0.x() / (top.s_.x() * A1) : 1.0;
    const double phi0 = std::atan2(sn0, cn0);
    top.tau0_ = boost::math::ellint_1(top.k_, phi0);
    return top;
}

Vec3 AsymmetricTop::omega_B(double t) const
{
    // tau = lambda t + tau0;  (s1 A1 cn, s2 A2 sn, s3 A3 dn)
    const double tau = lambda_ * t + tau0_;
    double cn = 0.0;
    double dn = 0.0;
    const double sn = boost::math::jacobi_elliptic(k_, tau, &cn, &dn);
    // dn = sqrt(k'^2 + k^2 cn^2) (from dn^2 + k^2 sn^2 = 1): Boost 1.74's dn loses accuracy
    // where sn = +-1 for k near 1 (dn(K) for k^2 = 0.99996 is off by 1e-3 relative), while
    // this identity has no cancellation.
    dn = std::sqrt(kPrime2_ + k_ * k_ * cn * cn);
    const Vec3 w(s_.x() * A_.x() * cn, s_.y() * A_.y() * sn, s_.z() * A_.z() * dn);
    // back from the relabelled frame: omega = (w3, -w2, w1)
    return swapped_ ? Vec3(w.z(), -w.y(), w.x()) : w;
}

Vec3 AsymmetricTop::L_B(double t) const
{
    // L_B = I0 omega_B
    return I_.cwiseProduct(omega_B(t));
}

double AsymmetricTop::kineticEnergy() const
{
    return 0.5 * twoT_;
}

double AsymmetricTop::quarterPeriod() const
{
    return boost::math::ellint_1(k_);
}

double AsymmetricTop::period() const
{
    // sn, cn have period 4K in tau
    return 4.0 * quarterPeriod() / lambda_;
}

std::vector<double> AsymmetricTop::signChangesOfOmega2(double tEnd) const
{
    // sn tau = 0 at tau = 2 m K:  t_m = (2 m K - tau0) / lambda
    const double K = quarterPeriod();
    std::vector<double> times;
    const long mFirst = static_cast<long>(std::floor(tau0_ / (2.0 * K))) + 1;
    for (long m = mFirst;; ++m) {
        const double t = (2.0 * double(m) * K - tau0_) / lambda_;
        if (t > tEnd) {
            break;
        }
        if (t > 0.0) {
            times.push_back(t);
        }
    }
    return times;
}

} // namespace rbw::reference
