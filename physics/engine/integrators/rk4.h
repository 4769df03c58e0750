// Classical fourth-order Runge-Kutta on the full state y = (x, r, P, L):
//
//   k1 = f(y_n)             k2 = f(y_n + h/2 k1)
//   k3 = f(y_n + h/2 k2)    k4 = f(y_n + h k3)
//   y_{n+1} = y_n + h/6 (k1 + 2 k2 + 2 k3 + k4),   then r /= |r|
//
// f from rigid_ode.h: r' = 1/2 (0, omega) r with omega = I^-1(r_i) L_i evaluated at
// every stage (R from the stage's normalised r). Fourth order (Kutta 1901; Hairer,
// Norsett & Wanner, "Solving ODEs I", section II.1, Table 1.2). Conserves nothing
// exactly; its energy error is O(h^4).
#pragma once

#include "physics/engine/integrator.h"

namespace rbw {

class Rk4 : public Integrator {
public:
    static constexpr const char* kName = "rk4";
    const char* name() const override { return kName; }
    void advance(const BodyStep& step, BodyState& s) const override;
};

} // namespace rbw
