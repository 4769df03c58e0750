// One colour per body, the same everywhere: the 3D view (view_style.h), the per-body
// and "Plot over time" plots and the quantities table's body swatches all read this
// one function, so body 2 is the same green in the view, its plot lines and its rows.
//
// Distinct, medium-dark colours that stay readable on the light backgrounds and
// avoid the arrow colours of the view (orange, cyan, magenta, yellow); a fixed body
// is grey. A body named after a colour ("red", "green", ... as in lesson 4, whose
// text speaks of "red against green") is drawn in that colour, so the name and the
// picture agree. Header-only (Qt Gui's QColor), so every panel library can include it.
#pragma once

#include <QColor>

#include <QString>

#include <array>
#include <cstddef>
#include <string_view>

namespace rbw {

struct BodyRgb {
    float r = 0.f, g = 0.f, b = 0.f;
};

inline constexpr std::array<BodyRgb, 10> kBodyPalette{{
    {0.306f, 0.475f, 0.655f},   // blue
    {0.882f, 0.341f, 0.349f},   // red
    {0.349f, 0.631f, 0.310f},   // green
    {0.690f, 0.478f, 0.631f},   // mauve
    {0.612f, 0.459f, 0.373f},   // brown
    {0.184f, 0.294f, 0.486f},   // navy
    {0.549f, 0.604f, 0.235f},   // olive
    {1.000f, 0.616f, 0.655f},   // pink
    {0.157f, 0.471f, 0.451f},   // dark teal
    {0.463f, 0.353f, 0.690f},   // violet
}};
inline constexpr BodyRgb kFixedBodyRgb{0.62f, 0.62f, 0.62f};

// The colours a body's name can ask for (lower case, exact).
struct NamedBodyColour {
    std::string_view name;
    BodyRgb rgb;
};
inline constexpr std::array<NamedBodyColour, 12> kNamedBodyColours{{
    {"red", kBodyPalette[1]},
    {"green", kBodyPalette[2]},
    {"blue", kBodyPalette[0]},
    {"yellow", {0.851f, 0.722f, 0.247f}},
    {"purple", {0.569f, 0.404f, 0.722f}},
    {"violet", kBodyPalette[9]},
    {"cyan", {0.259f, 0.651f, 0.722f}},
    {"orange", {0.898f, 0.553f, 0.251f}},
    {"pink", kBodyPalette[7]},
    {"brown", kBodyPalette[4]},
    {"navy", kBodyPalette[5]},
    {"olive", kBodyPalette[6]},
}};

// The colour of body `body` (its index in the scene) named `name`; body < 0 (a
// world-level quantity) gets the first colour.
inline BodyRgb bodyRgb(int body, bool fixed, std::string_view name = {})
{
    if (fixed) return kFixedBodyRgb;
    for (const NamedBodyColour& c : kNamedBodyColours) {
        if (c.name == name) return c.rgb;
    }
    return kBodyPalette[static_cast<std::size_t>(body < 0 ? 0 : body) % kBodyPalette.size()];
}

inline QColor bodyQColor(int body, bool fixed, const QString& name = {})
{
    const QByteArray utf8 = name.toUtf8();
    const BodyRgb c = bodyRgb(body, fixed, std::string_view(utf8.constData(), static_cast<std::size_t>(utf8.size())));
    return QColor::fromRgbF(c.r, c.g, c.b);
}

} // namespace rbw
