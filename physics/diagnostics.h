// Diagnostics after a step: energies and momenta of the whole world.
//
// Glossary
//   T_trans = sum 1/2 M |v|^2                 translational kinetic energy   [J]
//   T_rot   = sum 1/2 omega . L               rotational kinetic energy      [J]
//   V       = sum -M g . x                    potential energy (0 at x = 0)  [J]
//   P_W     = sum M v                          total linear momentum          [kg m/s]
//   L_O_W   = sum (x x M v + L)                angular momentum about origin  [kg m^2/s]
// Fixed bodies (infinite mass) are left out of every sum.
#pragma once

#include "physics/body.h"
#include "physics/math_types.h"

#include <vector>

namespace rbw {

struct Diagnostics {
    double kineticTranslational = 0.0;
    double kineticRotational = 0.0;
    double kinetic = 0.0;
    double potential = 0.0;   // 0 when the scene has no gravity
    double total = 0.0;
    Vec3 P_W = Vec3::Zero();
    Vec3 L_O_W = Vec3::Zero();
};

Diagnostics computeDiagnostics(const std::vector<MassProperties>& mass,
                               const std::vector<BodyState>& states, const Vec3& g_W);

} // namespace rbw
