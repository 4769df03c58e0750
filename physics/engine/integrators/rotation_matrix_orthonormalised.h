// Napier SET09119 practical 6 with the orthonormalisation the practical asks for:
// R <- R + h [omega]x R as in rotation_matrix.h, then R <- the nearest rotation,
// the orthogonal polar factor U V^T of the SVD U S V^T (Higham, "Computing the polar
// decomposition", SIAM J. Sci. Stat. Comput. 7 (1986); it minimises ||R - Q||_F over
// rotations Q, so no axis is preferred as in Gram-Schmidt). First order;
// ||R^T R - E||_F stays at rounding level (<= 1e-12 in tests/physics/engine/integrators).
#pragma once

#include "physics/engine/integrators/rotation_matrix.h"

namespace rbw {

// The nearest rotation to M (polar factor, det +1); M must be finite.
Mat3 nearestRotation(const Mat3& M);

class RotationMatrixOrthonormalised final : public RotationMatrix {
public:
    static constexpr const char* kName = "rotation-matrix-orthonormalised";
    const char* name() const override { return kName; }

protected:
    bool orthonormalises() const override { return true; }
};

} // namespace rbw
