// Diagnostics after a step: energies and momenta of the whole world, and of each
// body on its own (so variants in one scene can be compared side by side).
//
// Glossary
//   T_trans = sum 1/2 M |v|^2                 translational kinetic energy   [J]
//   T_rot   = sum 1/2 omega . L               rotational kinetic energy      [J]
//   V       = sum -M g . x                    potential energy (0 at x = 0)  [J]
//   P_W     = sum M v                          total linear momentum          [kg m/s]
//   L_O_W   = sum (x x M v + L)                angular momentum about origin  [kg m^2/s]
//   per body b: T_trans,b, T_rot,b, T_b = T_trans,b + T_rot,b, L_W,b (about its own
//   centre of mass: the state's L) and |L_W,b|
// Fixed bodies (infinite mass) are left out of every sum; their per-body part is zero.
#pragma once

#include "physics/engine/body.h"
#include "physics/engine/math_types.h"

#include <vector>

namespace rbw {

// One body's part of the diagnostics.
struct BodyDiagnostics {
    double kineticTranslational = 0.0;   // 1/2 M |v|^2          [J]
    double kineticRotational = 0.0;      // 1/2 omega . L         [J]
    double kinetic = 0.0;                // T = T_trans + T_rot   [J]
    Vec3 L_W = Vec3::Zero();             // about its own centre of mass [kg m^2/s]
    double L_norm = 0.0;                 // |L_W|                 [kg m^2/s]
};

// One body's part: T_trans, T_rot, T, L_W and |L_W| (all 0 for a fixed body).
BodyDiagnostics bodyDiagnostics(const MassProperties& mp, const BodyState& s);

// T = 1/2 M |v|^2 + 1/2 omega . L of one body (0 for a fixed body): the same sum as
// bodyDiagnostics().kinetic, without the rest (the per-step energy-jump check).
inline double kineticEnergy(const MassProperties& mp, const BodyState& s)
{
    if (mp.invM == 0.0) return 0.0;
    return 0.5 * mp.M * s.v_W.squaredNorm() + 0.5 * s.omega_W.dot(s.L_W);
}

struct Diagnostics {
    double kineticTranslational = 0.0;
    double kineticRotational = 0.0;
    double kinetic = 0.0;
    double potential = 0.0;   // 0 when the scene has no gravity
    double total = 0.0;
    Vec3 P_W = Vec3::Zero();
    Vec3 L_O_W = Vec3::Zero();
    std::vector<BodyDiagnostics> bodies;   // one per body, in scene order
};

Diagnostics computeDiagnostics(const std::vector<MassProperties>& mass,
                               const std::vector<BodyState>& states, const Vec3& g_W);

} // namespace rbw
