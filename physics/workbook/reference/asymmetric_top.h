// Reference: the torque-free asymmetric top, I1 < I2 < I3, through Jacobi elliptic
// functions (Landau & Lifshitz, Mechanics, section 37, eq. (37.10); docs/references.md
// §5). With L^2 = |L_B|^2 and 2T = L_B . I0^-1 L_B, for L^2 > 2 T I2 (the
// polhode circles axis 3):
//   omega1 = s1 sqrt((2T I3 - L^2)/(I1 (I3 - I1))) cn tau
//   omega2 = s2 sqrt((2T I3 - L^2)/(I2 (I3 - I2))) sn tau
//   omega3 = s3 sqrt((L^2 - 2T I1)/(I3 (I3 - I1))) dn tau
//   tau = lambda t + tau0,  lambda = sqrt((I3 - I2)(L^2 - 2T I1)/(I1 I2 I3)),
//   k^2 = (I2 - I1)(2T I3 - L^2) / ((I3 - I2)(L^2 - 2T I1))
// (docs/references.md §5 notes the equivalent form with both signs flipped). sn, cn and K(k)
// come from Boost.Math (jacobi_elliptic, ellint_1), modulus k, not k^2; dn is taken as
// sqrt(k'^2 + k^2 cn^2) with k'^2 = (I3 - I1)(L^2 - 2T I2)/((I3 - I2)(L^2 - 2T I1)),
// because Boost 1.74's dn is inaccurate where sn = +-1 when k is near 1.
//
// Sign and phase conventions (Landau fixes t0 by omega2(0) = 0; here any initial L_B):
//   - Euler's equations need s1 s2 s3 = +1 (checked by differentiating: cn' = -sn dn,
//     sn' = cn dn, dn' = -k^2 sn cn, each times lambda). dn > 0, so s3 = sign(omega3(0));
//     we take s1 = +1 and s2 = s3.
//   - tau0 = F(phi0, k), the incomplete elliptic integral of the first kind, with the
//     amplitude phi0 = atan2(omega2(0)/(s2 A2), omega1(0)/(s1 A1)): then cn tau0 = cos phi0,
//     sn tau0 = sin phi0 reproduce omega1(0), omega2(0).
//   - For L^2 < 2 T I2 (the polhode circles axis 1) Landau exchanges the indices 1 and 3.
//     An odd permutation flips the sign of the cross product in Euler's equations, so
//     we solve for w = (omega3, -omega2, omega1) with I' = (I3, I2, I1) (then
//     s1 s2 s3 = -1, since the order of I' is reversed) and map back.
// L^2 = 2 T I2 (the separatrix) is rejected: the motion is not periodic there.
//
// Only omega_B(t) and L_B(t) are given; the orientation needs an elliptic integral of
// the third kind (Landau section 37) and is not provided.
#pragma once

#include "physics/engine/math_types.h"

#include <optional>
#include <string>
#include <vector>

namespace rbw::reference {

class AsymmetricTop {
public:
    // I = (I1, I2, I3) with 0 < I1 < I2 < I3 (body axes x, y, z), L0_B != 0, and not on
    // the separatrix (|L^2 - 2T I2| > 1e-12 L^2).
    static std::optional<AsymmetricTop> make(const Vec3& I, const Vec3& L0_B, std::string& error);

    Vec3 omega_B(double t) const;
    Vec3 L_B(double t) const;        // I0 omega_B(t)
    double kineticEnergy() const;    // T = 1/2 L_B . I0^-1 L_B, constant
    double angularMomentumSquared() const { return L2_; }
    double modulus() const { return k_; }           // k
    double lambda() const { return lambda_; }       // tau = lambda t + tau0
    double quarterPeriod() const;                   // K(k)
    double period() const;                          // 4 K / lambda: the period of omega_B
    bool circlesAxis3() const { return !swapped_; } // L^2 > 2 T I2
    // The times in (0, tEnd] at which omega2 (and L_B,y) changes sign: sn tau = 0, i.e.
    // tau = 2 m K. They are 2K/lambda apart: the flips of the tennis-racket effect.
    std::vector<double> signChangesOfOmega2(double tEnd) const;
    const Vec3& inertia() const { return I_; }

private:
    AsymmetricTop() = default;
    Vec3 I_ = Vec3::Ones();      // the body's (I1, I2, I3)
    bool swapped_ = false;       // solved in the relabelled frame (I3, I2, I1)
    double L2_ = 0.0;            // L^2
    double twoT_ = 0.0;          // 2T
    Vec3 A_ = Vec3::Zero();      // amplitudes (A1, A2, A3), relabelled frame
    Vec3 s_ = Vec3::Ones();      // signs (s1, s2, s3), relabelled frame
    double k_ = 0.0;
    double kPrime2_ = 1.0;       // k'^2 = 1 - k^2, computed without cancellation
    double lambda_ = 0.0;
    double tau0_ = 0.0;
};

} // namespace rbw::reference
