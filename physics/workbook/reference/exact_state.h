// The exact state of a reference problem at time t (reference/*.h), in the same
// names and frames as BodyState, so tests can compare an integrator to it directly.
#pragma once

#include "physics/engine/math_types.h"

namespace rbw::reference {

struct ExactState {
    Vec3 x_W = Vec3::Zero();
    Vec3 v_W = Vec3::Zero();
    Quat q_WB = Quat::Identity();   // [w, x, y, z] when written out
    Vec3 L_W = Vec3::Zero();
    Vec3 omega_W = Vec3::Zero();
};

} // namespace rbw::reference
