// Which mistake models a probe group can show (issue 23). A simulator answers only x,
// v, omega and r after whole steps, so a mistake in a quantity that only a hand
// calculation writes down (a point's velocity, the initial quaternion built from an
// angle) never changes an answer: those models are excluded from every group, by the
// explicit list below, each with its reason. The collision models need the collision
// group (not built yet); the motion group replays the rest.
#pragma once

#include "physics/workbook/checker/mistakes.h"
#include "physics/workbook/probes/replay.h"

#include <optional>
#include <vector>

namespace rbw::probes {

enum class ProbeScope {
    Motion,      // a step of a free body: the motion probes show it
    Collision,   // the contact impulse: only the collision probes can show it
    HandOnly,    // a quantity of the hand calculation no `state` answer contains
};

struct ScopedMistake {
    Mistake mistake;
    ProbeScope scope;
    const char* reason;   // why it belongs there (HandOnly: why no answer can show it)
};

// Every model of the checker's catalogue that has a scope; a model added to the
// catalogue without one gets nullopt from scopeOf() (tst_probes fails on it).
const std::vector<ScopedMistake>& mistakeScopes();
std::optional<ProbeScope> scopeOf(Mistake m);

// The motion group's candidates: every Motion model in each of its variants, in the
// catalogue's order (the right algorithm is not among them).
std::vector<ReplayModel> motionModels();

} // namespace rbw::probes
