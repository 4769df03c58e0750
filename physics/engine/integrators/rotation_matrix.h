// Napier SET09119 practical 6: the orientation kept as a rotation matrix and updated
// by explicit Euler on R' = [omega]x R,
//
//   x <- x + h v,   v <- v + h F/M,   R <- R + h [omega]x R,   L <- L + h q,
//   I^-1 = R I0^-1 R^T (or R^T I0^-1 R),   omega = I^-1 L          (the TUM order)
//
// First order. Here R_WB is the integrator's primary orientation state, read back at
// the start of the next step; q_WB is derived from it (Eigen's matrix-to-quaternion
// reading, then normalised) for the views. Without orthonormalisation R really drifts
// away from a rotation: R_{n+1}^T R_{n+1} = R_n^T (E + h^2 [omega]x^T [omega]x) R_n, so
// ||R^T R - E|| grows by about h^2 |omega|^2 per step, and I^-1 is built from the
// drifted R (docs/references.md §4). The trace records ||R^T R - E||_F and det R.
//
// Note: anything that calls updateDerived() between steps (a contact impulse does)
// rebuilds R from q_WB and so resets the drift.
#pragma once

#include "physics/engine/integrator.h"

namespace rbw {

// ||R^T R - E||_F: how far R is from an orthogonal matrix.
double orthonormalityError(const Mat3& R);

class RotationMatrix : public Integrator {
public:
    static constexpr const char* kName = "rotation-matrix";
    const char* name() const override { return kName; }

protected:
    Derived derivedFrom() const override { return Derived::FromMatrix; }
    void advance(const BodyStep& step, BodyState& s) const override;
    // The polar projection of rotation_matrix_orthonormalised.h after the update.
    virtual bool orthonormalises() const { return false; }
};

} // namespace rbw
