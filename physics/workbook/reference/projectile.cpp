#include "physics/workbook/reference/projectile.h"

namespace rbw::reference {

Vec3 Projectile::position(double t) const
{
    // x(t) = x0 + v0 t + 1/2 g t^2
    return x0_W_ + t * v0_W_ + (0.5 * t * t) * g_W_;
}

Vec3 Projectile::velocity(double t) const
{
    // v(t) = v0 + g t
    return v0_W_ + t * g_W_;
}

ExactState Projectile::at(double t) const
{
    ExactState s = spin_.at(t);
    s.x_W = position(t);
    s.v_W = velocity(t);
    return s;
}

} // namespace rbw::reference
