// What the manifold model carries from one step to the next: last step's impulses by
// pair and feature id (warm starting, warm_start.h) and the sleep state (rest times and
// sleeping islands, sleep.h). It is part of the world's state, beside the bodies' states
// (World, WorldSnapshot::contacts): a restored snapshot steps on bit for bit, in the
// same world (Step back, the history slider) and in a fresh one (the check panel's
// "world before this step", `rbw check`), as MuJoCo keeps its warm start in the state it
// saves and Jolt's ManifoldCache has SaveState / RestoreState. The stages read and write
// it through StepContext::contacts and keep nothing between steps themselves
// (contact_scratch.h is their per-step scratch). The course model leaves it untouched.
#pragma once

#include "physics/engine/manifold/sleep.h"
#include "physics/engine/manifold/warm_start.h"

#include <cstddef>

namespace rbw {

struct ContactState {
    ManifoldCache cache;   // last step's impulses by pair key and feature id
    SleepState sleep;      // rest times and sleeping islands, one entry per body

    // A fresh world's: nothing cached, every body awake with rest time 0.
    explicit ContactState(int bodies = 0) { sleep.resize(bodies); }

    // The heap bytes it holds (the history's memory budget).
    std::size_t bytes() const { return cache.bytes() + sleep.bytes(); }
};

} // namespace rbw
