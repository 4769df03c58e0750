// The mouse spring: how a drag in the app becomes a force on a body (Box2D's
// b2MouseJoint, as a plain damped spring instead of a constraint so that it is an
// external force f_i at a point p_i like any other, and shows up in the trace).
//
// Glossary
//   p_B       the picked point, fixed in the body frame
//   p_W       that point now: p_W = x + R p_B
//   t_W       the target point under the mouse, world frame
//   v_p       the picked point's velocity v + omega x (p_W - x)
//   w_s       the spring's angular frequency on the body's mass        [rad/s]
//
//   f = M w_s^2 (t_W - p_W) - 2 zeta M w_s v_p          (zeta = 1: critically damped)
//
// Stability: explicit Euler on a spring of frequency w_s needs h w_s well below 2, so
// w_s is capped at 0.5/h; with h = 0.01 the spring pulls at 1 Hz, with lesson 1's
// h = 2 it is weak, as it must be.
#pragma once

#include "physics/engine/body.h"

#include <algorithm>
#include <numbers>

namespace rbw {

struct MouseSpring {
    int body = -1;
    Vec3 p_B = Vec3::Zero();
    Vec3 target_W = Vec3::Zero();
    double frequencyHz = 1.0;
    double dampingRatio = 1.0;

    // The spring's force on the body for a step of size h, at the point p_W.
    Vec3 force(const MassProperties& mp, const BodyState& s, double h) const
    {
        const double w_s = std::min(2.0 * std::numbers::pi * frequencyHz, 0.5 / h);
        // p_W = x + R p_B
        const Vec3 p_W = s.x_W + s.R_WB * p_B;
        // v_p = v + omega x (p_W - x)
        const Vec3 v_p = pointVelocity(s, p_W);
        // f = M w_s^2 (t - p) - 2 zeta M w_s v_p
        return (mp.M * w_s * w_s) * (target_W - p_W) - (2.0 * dampingRatio * mp.M * w_s) * v_p;
    }
};

} // namespace rbw
