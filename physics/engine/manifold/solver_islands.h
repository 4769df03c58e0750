// Lanes of the soft step: the step's constraints split into groups that share no moving
// body, so that each group can be solved on its own thread (docs/performance.md, "A
// second thread"). The groups are whole islands, the bodies linked by constraints
// (union-find over the constraints between two moving bodies; a fixed, sleeping or plane
// body links nothing: it is never moved). Gauss-Seidel on constraints of different
// islands commutes, they touch different moving bodies, so a lane that solves its
// constraints in the step's order does exactly what the serial solver does to them:
// the result is the same bits for any number of lanes (Box2D v3 gets the same from its
// graph colouring, constraint_graph.c, one colour of constraints at a time; islands need
// no barrier inside the step, only at its end, but one big island stays on one lane).
//
// Glossary
//   moving     per solver body: non-zero if the solver moves it (awake and movable)
//   weight     per constraint: its share of the work (its points)
//   lane       constraints (in the step's order) and moving bodies one thread solves
#pragma once

#include <array>
#include <vector>

namespace rbw {

struct SolverLane {
    std::vector<int> constraints;   // ascending: the step's order
    std::vector<int> bodies;        // the moving bodies it integrates, ascending
    long weight = 0;                // the sum of its constraints' weights
};

// What splitIntoLanes() works in; nothing in it outlives the call.
struct IslandScratch {
    std::vector<int> parent;     // union-find over the bodies
    std::vector<int> islandOf;   // per root body: its island, -1 none
    std::vector<long> islandWeight;
    std::vector<int> laneOfIsland;
};

// Splits the constraints (ends[c] = its two solver bodies) into `lanes` lanes, whole
// islands each, the next island (in the order of their first constraints) always to
// the lane with the least weight so far; every moving body goes to its island's lane
// (a body without constraints: to the lightest lane). `out` gets `lanes` lanes; some
// may be empty. Deterministic: the same input gives the same lanes.
void splitIntoLanes(const std::vector<std::array<int, 2>>& ends, const std::vector<int>& weights,
                    const std::vector<char>& moving, int lanes, std::vector<SolverLane>& out, IslandScratch& scratch);

} // namespace rbw
