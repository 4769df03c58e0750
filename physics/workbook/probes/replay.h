// The workbook's side of a probe (issue 23): what a simulator that makes one mistake,
// two at once (a pair), or none answers to each `state` question of a probe. It runs the probe's commands
// the way the course algorithm's simulator does (docs/simulator-protocol.md, "The
// algorithm"; examples/simulator/README.md), and takes every step of every body from
// the checker's hand calculation handEulerStep() (physics/workbook/checker/mistakes.h),
// chained step to step, so the mistake models have one home. replayWithEngine() runs
// the same probe in the engine's world: without a mistake both must agree
// (tests/physics/workbook/probes/tst_probes.cpp).
//
// An answer is 13 numbers, x, v, omega (world frame) and r = (w, x, y, z), as the
// protocol's `state` answer; a probe's answers are one per `state` command, in order.
#pragma once

#include "physics/engine/inertia.h"
#include "physics/engine/scene.h"
#include "physics/workbook/checker/mistakes.h"
#include "physics/workbook/probes/probes.h"

#include <string>
#include <vector>

namespace rbw::probes {

using Answer = std::vector<double>;    // 9 or 13 numbers
using Answers = std::vector<Answer>;   // one per `state` command of a probe

// A simulator the workbook can replay: the right algorithm (Mistake::None), one
// mistake model in one of its variants (MistakeInfo::variants), or a pair of two
// models made at once (`second`; students' code carries several, issue 21 item 1).
// `variant` is that of whichever of the two has variants (only inertia-axes-swapped).
struct ReplayModel {
    Mistake mistake = Mistake::None;
    int variant = 0;
    Mistake second = Mistake::None;   // None: a single model

    bool isPair() const { return mistake != Mistake::None && second != Mistake::None; }
    bool has(Mistake m) const { return m != Mistake::None && (mistake == m || second == m); }
    MistakeSet set() const { return MistakeSet{mistake, second, variant}; }
};

bool operator==(const ReplayModel& a, const ReplayModel& b);

// "the right algorithm", "transposed-inertia", "inertia-axes-swapped (y-z)",
// "transposed-inertia + lever-arm-from-origin" (a pair: its two labels, catalogue order).
std::string modelLabel(const ReplayModel& model);
// The mistake's catalogue id ("" for the right algorithm), a pair's two ids joined by
// " + ": what rbw diagnose names (without the variant).
std::string modelId(const ReplayModel& model);
// The catalogue ids one by one: none, one, or a pair's two.
std::vector<std::string> modelIds(const ReplayModel& model);

// The answers of a simulator with `model` to the probe's `state` commands.
Answers replay(const Probe& probe, const ReplayModel& model);

// The probe as an engine scene: its bodies (named "body 0", "body 1", …) at their
// add_body, set_orientation and set_velocity values, each apply_force as a force on
// its body for the one step after it, h of its steps, `steps` its number of steps;
// explicit Euler, no gravity, box collisions on (the scene's defaults otherwise: c = 1).
// What replayWithEngine() runs, and what the app opens in its main window (Compare
// with my simulator → Open in the main window).
SceneDef probeScene(const Probe& probe, InertiaConvention convention = InertiaConvention::Standard);

// The same probe in the engine's world (explicit Euler in the TUM order, no gravity,
// box collisions on): with the standard inertia convention, the right algorithm's
// answers; with the course template's (R^T I0^-1 R), those of transposed-inertia.
// The probe must keep probesAreWellFormed()'s rules.
Answers replayWithEngine(const Probe& probe, InertiaConvention convention = InertiaConvention::Standard);

// Where each answer of a probe stands: the number of steps before it and its body.
struct AnswerSlot {
    int step = 0;
    int body = 0;
};
std::vector<AnswerSlot> answerSlots(const Probe& probe);

} // namespace rbw::probes
