// What the manifold model keeps between its stages and between steps: the settings,
// this step's manifolds, last step's impulses (warm starting), the sleep state, the
// solver's bodies and the broad phase's scratch. The world's pipeline builder creates
// one and hands it to the three stages (stages/manifold_contact_stage.h,
// manifold_position_stage.h, sleep_stage.h).
#pragma once

#include "physics/engine/collision/broad_phase.h"
#include "physics/engine/manifold/contact_solver.h"
#include "physics/engine/manifold/manifold.h"
#include "physics/engine/manifold/settings.h"
#include "physics/engine/manifold/sleep.h"
#include "physics/engine/manifold/warm_start.h"

#include <utility>
#include <vector>

namespace rbw {

struct ContactWorld {
    ManifoldSettings settings;
    std::vector<Manifold> manifolds;   // this step's, solved (sleeping pairs are not listed)
    ManifoldCache cache;               // last step's impulses by pair and feature id
    SleepState sleep;
    std::vector<SolverBody> bodies;    // one per body, and a last, static one for planes
    ContactSolver solver;              // this step's rows, impulses and iteration history
    int iterationsUsed = 0;            // velocity iterations of the last step
    // Broad-phase scratch
    AabbTree broadPhase;
    std::vector<Aabb> aabbs;
    std::vector<std::pair<int, int>> pairs;
    std::vector<char> pairDone;
};

} // namespace rbw
