// What the manifold model's stages hand on to each other within one step: the settings,
// this step's manifolds, the solver's bodies and rows, the broad phase's and the
// sleep update's scratch. The world's pipeline builder creates one and hands it to the
// three stages (manifold_contact_stage.h, manifold_position_stage.h, sleep_stage.h).
// Every step rebuilds what it reads from here before reading it: nothing in it carries
// over to the next step. What does carry over (the warm-start impulses, the sleep
// state) is the world's state, ContactState (contact_state.h), in WorldSnapshot.
#pragma once

#include "physics/engine/collision/broad_phase.h"
#include "physics/engine/manifold/contact_solver.h"
#include "physics/engine/manifold/manifold.h"
#include "physics/engine/manifold/settings.h"
#include "physics/engine/manifold/sleep.h"
#include "physics/engine/manifold/soft_step_solver.h"
#include "physics/engine/manifold/solver_worker.h"
#include "physics/engine/manifold/warm_start.h"

#include <utility>
#include <vector>

namespace rbw {

struct ContactScratch {
    ManifoldSettings settings;         // the scene's, fixed when the world is built
    std::vector<Manifold> manifolds;   // this step's, solved (sleeping pairs are not listed)
    ManifoldCache cacheSpare;          // ManifoldCache::store's spare storage
    SleepScratch sleepScratch;         // SleepState::update's
    std::vector<SolverBody> bodies;    // one per body, and a last, static one for planes
    ContactSolver solver;              // this step's rows, impulses and iteration history
    int iterationsUsed = 0;            // velocity iterations of the last step
    SoftStepSolver softSolver;         // the soft step's rows (solver "soft-step")
    std::vector<SubstepMotion> motion; // the soft step's per-body loads and displacement, for the position stage
    std::vector<char> moving;          // per solver body: moved by the soft step (awake, movable)
    int threads = 2;                   // threads the soft step may use (WorldOptions::contactThreads)
    SolverWorker worker;               // its second thread, started when first needed
    // Broad-phase scratch
    AabbTree broadPhase;
    std::vector<Aabb> aabbs;
    std::vector<char> resting;         // per body: asleep, kept out of the tree
    std::vector<std::pair<int, int>> pairs;
    std::vector<char> pairDone;
    std::vector<std::pair<int, int>> pairsBefore;   // the pairs before a wake, and which were collided
    std::vector<char> pairDoneBefore;
};

} // namespace rbw
