// The 3D view's visual language in one place: body colours, the colour of each kind
// of arrow (the legend names the same colours), and how arrows are scaled.
#pragma once

#include <array>
#include <cmath>

namespace rbw::view {

struct Rgba {
    float r = 0.f, g = 0.f, b = 0.f, a = 1.f;
};

// Distinct, medium-dark body colours that stay readable on the light background and
// avoid the arrow colours below (orange, cyan, magenta, yellow).
inline constexpr std::array<Rgba, 10> kBodyPalette{{
    {0.306f, 0.475f, 0.655f, 1.f},   // blue
    {0.882f, 0.341f, 0.349f, 1.f},   // red
    {0.349f, 0.631f, 0.310f, 1.f},   // green
    {0.690f, 0.478f, 0.631f, 1.f},   // mauve
    {0.612f, 0.459f, 0.373f, 1.f},   // brown
    {0.184f, 0.294f, 0.486f, 1.f},   // navy
    {0.549f, 0.604f, 0.235f, 1.f},   // olive
    {1.000f, 0.616f, 0.655f, 1.f},   // pink
    {0.157f, 0.471f, 0.451f, 1.f},   // dark teal
    {0.463f, 0.353f, 0.690f, 1.f},   // violet
}};
inline constexpr Rgba kFixedBody{0.62f, 0.62f, 0.62f, 1.f};

inline Rgba bodyColour(int body, bool fixed)
{
    if (fixed) return kFixedBody;
    return kBodyPalette[static_cast<size_t>(body < 0 ? 0 : body) % kBodyPalette.size()];
}

inline constexpr Rgba kForce{1.00f, 0.55f, 0.05f, 1.f};      // applied force f_i (orange)
inline constexpr Rgba kGravity{0.72f, 0.40f, 0.08f, 1.f};    // M g (dark orange)
inline constexpr Rgba kProbe{0.00f, 0.70f, 0.80f, 1.f};      // probe point and v_p (cyan)
inline constexpr Rgba kContact{0.85f, 0.10f, 0.75f, 1.f};    // contact point and n (magenta)
inline constexpr Rgba kImpulse{0.95f, 0.78f, 0.00f, 1.f};    // J n (yellow)
inline constexpr Rgba kSpring{0.10f, 0.10f, 0.10f, 1.f};     // drag spring (black)
inline constexpr Rgba kAxisX{0.90f, 0.15f, 0.15f, 1.f};
inline constexpr Rgba kAxisY{0.10f, 0.65f, 0.15f, 1.f};
inline constexpr Rgba kAxisZ{0.15f, 0.30f, 0.95f, 1.f};
inline constexpr Rgba kEdge{0.12f, 0.12f, 0.14f, 1.f};       // box outlines
inline constexpr Rgba kPlane{0.55f, 0.60f, 0.66f, 0.55f};    // planes (alpha: seen from the free side)
inline constexpr float kPlaneAlphaBehind = 0.10f;            // a wall seen from behind barely shows

// Display scale of one kind of arrow: the longest arrow of the kind is drawn
// refLength long (about one box), so lengths compare within a kind, never across
// kinds. 0 when there is nothing to draw.
inline double arrowScale(double maxMagnitude, double refLength)
{
    return (maxMagnitude > 0.0 && std::isfinite(maxMagnitude)) ? refLength / maxMagnitude : 0.0;
}

} // namespace rbw::view
