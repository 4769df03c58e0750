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

// Pairs of the single models `singles` (issue 23: "every mistake model and pair of them";
// a student's code carries several, issue 21 item 1), each pair once, in the order of
// `singles`. Left out, because they cannot matter: two variants of one model (a box's
// I0 has one pair of axes swapped, MistakeSet one variant), and two models of the same
// slot, where the step takes one of them and ignores the other (sameSlotWinner()), so the
// pair replays exactly as that one model, which a diagnosis prefers anyway.
std::vector<ReplayModel> modelPairs(const std::vector<ReplayModel>& singles);

// For two models of the same slot, the one the hand calculation applies (the pair equals
// it alone; tst_probes measures that); None when a and b combine.
Mistake sameSlotWinner(Mistake a, Mistake b);

} // namespace rbw::probes
