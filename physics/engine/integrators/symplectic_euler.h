// Symplectic (semi-implicit) Euler: velocities and momenta first, then positions and
// orientation with the NEW v and omega. First order.
//
//   v_{n+1} = v_n + h F/M              x_{n+1} = x_n + h v_{n+1}
//   L_{n+1} = L_n + h q                omega'  = I^-1(r_n) L_{n+1}
//   r_{n+1} = normalise(r_n + h/2 (0, omega') r_n)
//
// For the translation this is the symplectic Euler method of Hairer, Lubich & Wanner,
// "Geometric Numerical Integration", Thm VI.3.3 (x_n is off by +1/2 a h t under a
// constant acceleration a). Box2D and Bullet integrate in this order. The rotation
// part is first order and not symplectic: it is explicit Euler on r with the updated
// omega (conventions.md, "A semi-implicit order").
#pragma once

#include "physics/engine/integrator.h"

namespace rbw {

class SymplecticEuler final : public Integrator {
public:
    static constexpr const char* kName = "symplectic-euler";
    const char* name() const override { return kName; }
    void advance(const BodyStep& step, BodyState& s) const override;
};

} // namespace rbw
