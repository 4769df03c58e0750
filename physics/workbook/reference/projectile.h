// Reference: a projectile under uniform gravity, spinning freely about a principal
// axis. The centre of mass and the rotation decouple (gravity acts at the centre of
// mass, so it exerts no torque about it):
//   x(t) = x0 + v0 t + 1/2 g t^2,   v(t) = v0 + g t          (Newton, constant force)
//   q(t) = exp(1/2 (0, omega) t) q0,  omega constant          (constant_spin.h)
// Energy per unit mass 1/2 |v|^2 - g . x is constant.
#pragma once

#include "physics/workbook/reference/constant_spin.h"
#include "physics/workbook/reference/exact_state.h"

namespace rbw::reference {

class Projectile {
public:
    Projectile(const Vec3& x0_W, const Vec3& v0_W, const Vec3& g_W, const ConstantSpin& spin)
        : x0_W_(x0_W), v0_W_(v0_W), g_W_(g_W), spin_(spin) {}

    Vec3 position(double t) const;   // x0 + v0 t + 1/2 g t^2
    Vec3 velocity(double t) const;   // v0 + g t
    ExactState at(double t) const;
    const ConstantSpin& spin() const { return spin_; }

private:
    Vec3 x0_W_;
    Vec3 v0_W_;
    Vec3 g_W_;
    ConstantSpin spin_;
};

} // namespace rbw::reference
