// Sleeping (Catto GDC 2006; Box2D b2Island / b2_timeToSleep): a body that moves slower
// than the sleep tolerances accumulates rest time; the bodies that touch each other form
// an island (union-find over this step's manifolds), and when every body of an island has
// rested for timeToSleep the whole island sleeps: v = L = omega = 0, no contact of it is
// solved, and the contact stage holds it still (F_c = -F, q_c = -q). An island wakes as a
// whole when an awake movable body touches one of its bodies, when a load other than
// gravity acts on one of them, or when one of them is found moving (a restored state).
//
// SleepState is part of the world's state (ContactState, WorldSnapshot::contacts): a
// restored snapshot restores who sleeps and for how long each body has rested. What
// update() only needs while it runs is in SleepScratch, outside the state.
//
// Glossary
//   restTime   how long the body has been slower than the tolerances              [s]
//   island     per sleeping body: the id of the island it fell asleep with; -1 awake [-]
#pragma once

#include "physics/engine/body.h"
#include "physics/engine/manifold/manifold.h"
#include "physics/engine/manifold/settings.h"

#include <vector>

namespace rbw {

// What SleepState::update() works in; nothing in it outlives the call.
struct SleepScratch {
    std::vector<int> parent;       // union-find
    std::vector<double> least;     // least rest time per root
    std::vector<int> idOfRoot;     // island id per root
};

class SleepState {
public:
    void resize(int bodies);
    bool asleep(int b) const { return island_[static_cast<std::size_t>(b)] >= 0; }
    double restTime(int b) const { return restTime_[static_cast<std::size_t>(b)]; }
    int sleepingCount() const;

    // Wakes b and every body that fell asleep in its island; their rest times restart.
    void wake(int b);

    // After the step: updates the rest times of the awake movable bodies, builds the
    // islands from the manifolds with points (between two movable bodies) and puts every
    // island whose bodies all rested timeToSleep to sleep (v = L = omega = 0).
    void update(std::vector<BodyState>& states, const std::vector<char>& movable,
                const std::vector<Manifold>& manifolds, double h, const ManifoldSettings& settings,
                SleepScratch& scratch);

    // Forgets everything: every body awake, rest times 0.
    void reset();

    int bodyCount() const { return static_cast<int>(restTime_.size()); }
    // The heap bytes it holds (the history's memory budget).
    std::size_t bytes() const;

private:
    std::vector<double> restTime_;
    std::vector<int> island_;                 // per body: sleeping island id, -1 awake
    std::vector<std::vector<int>> members_;   // per island id: its bodies (empty: free id)
};

} // namespace rbw
