// The explicit midpoint rule (RK2) on the full state y = (x, r, P, L), second order:
//
//   k1 = f(y_n),   k2 = f(y_n + h/2 k1),   y_{n+1} = y_n + h k2,   then r /= |r|
//
// with f from rigid_ode.h (omega evaluated at each stage). Hairer, Norsett & Wanner,
// "Solving Ordinary Differential Equations I", section II.1, eq. (1.7) (Runge 1895).
// Conserves nothing exactly; |r| is restored by the final normalisation.
#pragma once

#include "physics/engine/integrator.h"

namespace rbw {

class Midpoint final : public Integrator {
public:
    static constexpr const char* kName = "midpoint";
    const char* name() const override { return kName; }
    void advance(const BodyStep& step, BodyState& s) const override;
};

} // namespace rbw
