#include "physics/engine/scene.h"

#include "physics/engine/manifold/settings.h"

#include "physics/engine/integrator_registry.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <tuple>

namespace rbw {

int SceneDef::bodyIndex(const std::string& bodyName) const
{
    for (int i = 0; i < static_cast<int>(bodies.size()); ++i) {
        if (bodies[i].name == bodyName) {
            return i;
        }
    }
    return -1;
}

int SceneDef::planeIndex(const std::string& planeName) const
{
    for (int i = 0; i < static_cast<int>(planes.size()); ++i) {
        if (planes[i].name == planeName) {
            return i;
        }
    }
    return -1;
}

SceneNames::SceneNames(const SceneDef& scene)
{
    bodies_.reserve(scene.bodies.size());
    planes_.reserve(scene.planes.size());
    // emplace keeps the first index of a name used twice, as bodyIndex() finds it.
    for (int i = 0; i < static_cast<int>(scene.bodies.size()); ++i) {
        bodies_.emplace(scene.bodies[i].name, i);
    }
    for (int i = 0; i < static_cast<int>(scene.planes.size()); ++i) {
        planes_.emplace(scene.planes[i].name, i);
    }
}

int SceneNames::body(const std::string& name) const
{
    const auto it = bodies_.find(name);
    return it == bodies_.end() ? -1 : it->second;
}

int SceneNames::plane(const std::string& name) const
{
    const auto it = planes_.find(name);
    return it == planes_.end() ? -1 : it->second;
}

std::string messageText(std::string_view text, std::size_t maxChars)
{
    std::string out;
    std::size_t chars = 0;
    std::size_t i = 0;
    char escape[16];
    while (i < text.size()) {
        if (chars == maxChars) {
            out += "\u2026";
            break;
        }
        const auto c = static_cast<unsigned char>(text[i]);
        // One UTF-8 sequence: its length from the lead byte, then its code point.
        const std::size_t len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
        bool valid = len > 0 && i + len <= text.size();
        char32_t cp = len == 1 ? c : len == 2 ? (c & 0x1f) : len == 3 ? (c & 0x0f) : (c & 0x07);
        for (std::size_t k = 1; valid && k < len; ++k) {
            const auto cont = static_cast<unsigned char>(text[i + k]);
            valid = (cont >> 6) == 0x2;
            cp = (cp << 6) | (cont & 0x3f);
        }
        ++chars;
        if (!valid) {
            std::snprintf(escape, sizeof escape, "\\x%02x", c);
            out += escape;
            ++i;
            continue;
        }
        const bool control = cp < 0x20 || (cp >= 0x7f && cp < 0xa0) || cp == 0x2028 || cp == 0x2029 ||
                             (cp >= 0x202a && cp <= 0x202e) || (cp >= 0x2066 && cp <= 0x2069);
        if (control) {
            std::snprintf(escape, sizeof escape, "\\u%04x", static_cast<unsigned>(cp));
            out += escape;
        } else if (cp == '"' || cp == '\\') {
            out += '\\';
            out += static_cast<char>(cp);
        } else {
            out.append(text.substr(i, len));
        }
        i += len;
    }
    return out;
}

namespace {

bool samePair(const PairOverride& o, int a, int b, int planeB)
{
    return planeB >= 0 ? (o.planeB == planeB && o.bodyA == a)
                       : (o.planeB < 0 && ((o.bodyA == a && o.bodyB == b) || (o.bodyA == b && o.bodyB == a)));
}

const PairOverride* findOverride(const SceneDef& s, int a, int b, int planeB)
{
    for (const PairOverride& o : s.pairs) {
        if (samePair(o, a, b, planeB)) {
            return &o;
        }
    }
    return nullptr;
}

} // namespace

double SceneDef::restitutionFor(int a, int b, int planeB) const
{
    const PairOverride* o = findOverride(*this, a, b, planeB);
    return o != nullptr && o->restitution ? *o->restitution : restitution;
}

double SceneDef::frictionFor(int a, int b, int planeB) const
{
    const PairOverride* o = findOverride(*this, a, b, planeB);
    return o != nullptr && o->friction ? *o->friction : friction;
}

} // namespace rbw
