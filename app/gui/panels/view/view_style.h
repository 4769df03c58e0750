// The 3D view's visual language in one place: body colours, the colour of each kind
// of arrow (the legend names the same colours), and how arrows are scaled.
#pragma once

#include "app/gui/style/body_colours.h"

#include <array>
#include <cmath>

namespace rbw::view {

struct Rgba {
    float r = 0.f, g = 0.f, b = 0.f, a = 1.f;
};

// The body colours are the app's one body-colour function (app/gui/style/body_colours.h),
// which the plots and the quantities table read too.
inline constexpr Rgba kFixedBody{kFixedBodyRgb.r, kFixedBodyRgb.g, kFixedBodyRgb.b, 1.f};

inline Rgba bodyColour(int body, bool fixed, std::string_view name = {})
{
    const BodyRgb c = bodyRgb(body, fixed, name);
    return Rgba{c.r, c.g, c.b, 1.f};
}

inline constexpr Rgba kForce{1.00f, 0.55f, 0.05f, 1.f};      // applied force f_i (orange)
inline constexpr Rgba kGravity{0.72f, 0.40f, 0.08f, 1.f};    // M g (dark orange)
inline constexpr Rgba kTorque{0.00f, 0.45f, 0.40f, 1.f};    // couple q_j (dark teal)
inline constexpr Rgba kProbe{0.00f, 0.70f, 0.80f, 1.f};      // probe point and v_p (cyan)
inline constexpr Rgba kContact{0.85f, 0.10f, 0.75f, 1.f};    // contact point and n (magenta)
inline constexpr Rgba kImpulse{0.95f, 0.78f, 0.00f, 1.f};    // J n (yellow)
inline constexpr Rgba kFriction{0.35f, 0.75f, 0.10f, 1.f};   // J_t t (lime)
inline constexpr Rgba kTotalImpulse{0.55f, 0.35f, 0.05f, 0.45f};   // J n + J_t t (brown, translucent)
inline constexpr Rgba kForceDone{1.00f, 0.55f, 0.05f, 0.35f};  // f_i of the step just taken (faded orange)
inline constexpr Rgba kVelocity{0.05f, 0.45f, 0.95f, 1.f};   // v (bright blue)
inline constexpr Rgba kOmega{0.60f, 0.10f, 0.85f, 1.f};      // ω (purple)
inline constexpr Rgba kAngularMomentum{0.85f, 0.20f, 0.55f, 0.40f};   // L (pink, translucent, wider)
inline constexpr Rgba kSpring{0.10f, 0.10f, 0.10f, 1.f};     // drag spring (black)
inline constexpr Rgba kAxisX{0.90f, 0.15f, 0.15f, 1.f};
inline constexpr Rgba kAxisY{0.10f, 0.65f, 0.15f, 1.f};
inline constexpr Rgba kAxisZ{0.15f, 0.30f, 0.95f, 1.f};
inline constexpr Rgba kGrid{0.68f, 0.71f, 0.76f, 1.f};      // the ground grid (light grey)
inline constexpr Rgba kEdge{0.12f, 0.12f, 0.14f, 1.f};       // box outlines
inline constexpr Rgba kPlane{0.55f, 0.60f, 0.66f, 0.55f};    // planes (alpha: seen from the free side)
inline constexpr float kPlaneAlphaBehind = 0.10f;            // a wall seen from behind barely shows

// A state vector shorter than this (in its SI unit) is round-off, not motion (a
// falling cube's ω of 4e-15 rad/s): no arrow, since each kind is scaled to its
// longest arrow and noise would be drawn one box long.
inline constexpr double kNegligibleMagnitude = 1e-10;

// Display scale of one kind of arrow: the longest arrow of the kind is drawn
// refLength long (the smallest box's longest edge), so lengths compare within a kind, never across
// kinds. 0 when there is nothing to draw.
inline double arrowScale(double maxMagnitude, double refLength)
{
    return (maxMagnitude > 0.0 && std::isfinite(maxMagnitude)) ? refLength / maxMagnitude : 0.0;
}

} // namespace rbw::view
