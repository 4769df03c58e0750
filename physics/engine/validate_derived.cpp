// validate()'s rule on the constants a body derives from its inputs (validation_detail.h):
// M, 1/M, I0, I0^-1, L0 and omega0 must be finite doubles; the message names the input
// that breaks it and the limit that input must keep.
#include "physics/engine/validation_detail.h"

#include "physics/engine/body.h"

#include <algorithm>
#include <cmath>

namespace rbw::validation {

// Which sum of squares entry k of I0 = M/12 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2) holds.
const char* const kSquares[3] = {"b\u00b2 + c\u00b2", "a\u00b2 + c\u00b2", "a\u00b2 + b\u00b2"};

void checkDerived(std::vector<SceneIssue>& out, const std::string& at, const BodyDef& b,
                  InertiaConvention convention)
{
    // The sums of squares alone: the I0 of a body of mass 12, by the world's own
    // formula (boxInertiaBody computes 12/12 * (b^2 + c^2), exactly the sum).
    const Vec3 squares = boxInertiaBody(b.size, 12.0).diagonal();
    for (int k = 0; k < 3; ++k) {
        if (!std::isfinite(squares[k])) {
            // a^2 + b^2 <= DBL_MAX when a, b <= sqrt(DBL_MAX / 2) = 9.48e153.
            out.push_back({at + ".size", "edges " + vec(b.size) + " make " + kSquares[k] +
                                             " overflow, so I0 cannot be computed; every edge must be at most " +
                                             limit(std::sqrt(kMaxDouble / 2.0), false) + " m"});
            return;
        }
        if (squares[k] == 0.0) {
            // x^2 >= DBL_MIN > 0 when x >= sqrt(DBL_MIN) = 1.49e-154.
            out.push_back({at + ".size", "edges " + vec(b.size) + " make " + kSquares[k] +
                                             " underflow to 0, so I0 would have a zero entry; one of those two "
                                             "edges must be at least " +
                                             limit(std::sqrt(std::numeric_limits<double>::min()), true) + " m"});
            return;
        }
    }
    const MassProperties mp = massProperties(b);
    if (!(std::isfinite(mp.invM) && mp.invM > 0.0)) {
        out.push_back({at + ".mass", num(b.mass) + " makes 1/M overflow; must be at least " +
                                         limit(1.0 / kMaxDouble, true) + " kg"});
        return;
    }
    const double sMin = squares.minCoeff();
    const double sMax = squares.maxCoeff();
    for (int k = 0; k < 3; ++k) {
        if (!std::isfinite(mp.I0_B(k, k))) {
            // M/12 sMax <= DBL_MAX. Overflow implies sMax > 12, so DBL_MAX / sMax * 12 is finite.
            out.push_back({at + ".mass", num(b.mass) + " makes I0 overflow (I0 = M/12 (" + kSquares[k] +
                                             ") exceeds the largest double); for this size the mass must be at most " +
                                             limit(kMaxDouble / sMax * 12.0, false) + " kg"});
            return;
        }
    }
    for (int k = 0; k < 3; ++k) {
        const double I0 = mp.I0_B(k, k);
        if (!(I0 > 0.0 && std::isfinite(mp.I0inv_B(k, k)) && mp.I0inv_B(k, k) > 0.0)) {
            // 1/I0 <= DBL_MAX when M/12 sMin >= 1/DBL_MAX, i.e. M >= 12 / (sMin DBL_MAX),
            // computed without overflowing either product.
            const double least = sMin >= 1.0 ? 12.0 / sMin / kMaxDouble : 12.0 / (sMin * kMaxDouble);
            const std::string value = I0 == 0.0 ? "underflows to 0" : "= " + approx(I0) + ", too small";
            out.push_back({at + ".mass", num(b.mass) + " makes I0^-1 overflow (I0 = M/12 (" + kSquares[k] + ") " +
                                             value + " for its inverse to be a finite double)" +
                                             "; for this size the mass must be at least " + limit(least, true) +
                                             " kg"});
            return;
        }
    }
    const BodyState s0 = initialState(b, mp, convention);
    if (!s0.L_W.allFinite() || !s0.omega_W.allFinite()) {
        // |L0_i| <= sqrt(3) Imax |omega0|, and each term of omega = I^-1 L0 is at most
        // sqrt(3) Imax/Imin |omega0|; with |omega0| <= DBL_MAX / (6 Imax max(1, 1/Imin))
        // every product and sum stays below DBL_MAX.
        const double iMax = mp.I0_B.diagonal().maxCoeff();
        const double iMin = mp.I0_B.diagonal().minCoeff();
        const double most = kMaxDouble / 6.0 / iMax / std::max(1.0, 1.0 / iMin);
        out.push_back({at + ".angular_velocity",
                       "L0 = I(r0) \u03c90 overflows (|\u03c90| = " + approx(b.omega0_W.stableNorm()) +
                           " rad/s, I0 up to " + approx(iMax) + " kg m\u00b2); for this body |\u03c90| must be at most " +
                           limit(most, false) + " rad/s"});
    }
}

} // namespace rbw::validation
