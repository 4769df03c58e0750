// Sleeping (Catto GDC 2006; Box2D b2Island / b2_timeToSleep): a body that moves slower
// than the sleep tolerances accumulates rest time; the bodies that touch each other form
// an island (union-find over this step's manifolds), and when every body of an island has
// rested for timeToSleep the whole island sleeps: v = L = omega = 0, no contact of it is
// solved, and the contact stage holds it still (F_c = -F, q_c = -q). An island wakes as a
// whole when an awake movable body touches one of its bodies, when a load other than
// gravity acts on one of them, or when one of them is found moving (a restored state).
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
                const std::vector<Manifold>& manifolds, double h, const ManifoldSettings& settings);

    // Forgets everything: every body awake, rest times 0.
    void reset();

private:
    int find(int b);
    std::vector<double> restTime_;
    std::vector<int> island_;                 // per body: sleeping island id, -1 awake
    std::vector<std::vector<int>> members_;   // per island id: its bodies (empty: free id)
    std::vector<int> parent_;                 // union-find scratch
    std::vector<double> least_;               // update() scratch: least rest time per root
    std::vector<int> idOfRoot_;               // update() scratch: island id per root
};

} // namespace rbw
