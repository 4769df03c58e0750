// Internal to validate() (scene_validation.cpp): how its messages write numbers and
// names (validation_text.cpp), and its rule on the constants a body derives from its
// inputs (validate_derived.cpp). Not part of the physics API.
#pragma once

#include "physics/engine/scene.h"

#include <limits>
#include <string>
#include <vector>

namespace rbw::validation {

inline constexpr double kMaxDouble = std::numeric_limits<double>::max();

// The shortest text that reads back as the same double: 0.1, not 0.10000000000000001.
std::string num(double x);
// x (finite, > 0) to three significant digits for a message: "5.08e-310", "100".
std::string approx(double x);
// A limit (finite, > 0) to two significant digits, rounded towards the allowed side
// (up for a lower limit, down for an upper one), so that the limit a message prints
// is itself allowed: 1.0943e-307 as a lower limit is "1.1e-307".
std::string limit(double x, bool lower);
// "[x, y, z]", each with num().
std::string vec(const Vec3& v);
// A name in quotes, cut by messageText().
std::string quoted(const std::string& name);

// "a, b" for a message: at most the first 10 names, each cut by messageText(), so a
// scene of 100 000 bodies does not put every name into every message.
template <class Item>
std::string nameList(const std::vector<Item>& items)
{
    constexpr std::size_t kShown = 10;
    if (items.empty()) {
        return "none";
    }
    std::string list;
    for (std::size_t i = 0; i < items.size() && i < kShown; ++i) {
        list += (i == 0 ? "" : ", ") + messageText(items[i].name);
    }
    if (items.size() > kShown) {
        list += ", \u2026 (" + std::to_string(items.size()) + " in all)";
    }
    return list;
}

// A movable body's constants and initial state, which the world derives once
// (massProperties(), initialState()), must be finite doubles: M, 1/M and the diagonals
// of I0 and I0^-1 finite and > 0, then L0 = I(r0) omega0 and omega = I^-1 L0 finite.
// The first that is not is reported at the input that makes it so (`at`.size, .mass or
// .angular_velocity), with the limit that input must keep. Call it only when mass,
// size, omega0, the orientation and the convention are valid on their own.
void checkDerived(std::vector<SceneIssue>& out, const std::string& at, const BodyDef& b,
                  InertiaConvention convention);

} // namespace rbw::validation
