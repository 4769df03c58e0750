#include "physics/engine/diagnostics.h"

namespace rbw {

BodyDiagnostics bodyDiagnostics(const MassProperties& mp, const BodyState& s)
{
    BodyDiagnostics d;
    if (mp.invM == 0.0) {
        return d;   // fixed: infinite mass, no kinetic energy of its own
    }
    // T_trans = 1/2 M |v|^2
    d.kineticTranslational = 0.5 * mp.M * s.v_W.squaredNorm();
    // T_rot = 1/2 omega . L
    d.kineticRotational = 0.5 * s.omega_W.dot(s.L_W);
    d.kinetic = d.kineticTranslational + d.kineticRotational;
    // L about the body's own centre of mass is the state's L
    d.L_W = s.L_W;
    d.L_norm = s.L_W.norm();
    return d;
}

Diagnostics computeDiagnostics(const std::vector<MassProperties>& mass,
                               const std::vector<BodyState>& states, const Vec3& g_W)
{
    Diagnostics d;
    d.bodies.reserve(states.size());
    for (size_t b = 0; b < states.size(); ++b) {
        const MassProperties& mp = mass[b];
        const BodyState& s = states[b];
        d.bodies.push_back(bodyDiagnostics(mp, s));
        if (mp.invM == 0.0) {
            continue;   // fixed: infinite mass, left out of every sum
        }
        const BodyDiagnostics& db = d.bodies.back();
        const Vec3 P_b = linearMomentum(mp, s);
        // T_trans = sum 1/2 M |v|^2,  T_rot = sum 1/2 omega . L
        d.kineticTranslational += db.kineticTranslational;
        d.kineticRotational += db.kineticRotational;
        // V = -M g . x  (zero at the origin)
        d.potential -= mp.M * g_W.dot(s.x_W);
        // P = sum M v
        d.P_W += P_b;
        // L_O = sum (x x P + L)
        d.L_O_W += s.x_W.cross(P_b) + s.L_W;
    }
    d.kinetic = d.kineticTranslational + d.kineticRotational;
    d.total = d.kinetic + d.potential;
    return d;
}

} // namespace rbw
