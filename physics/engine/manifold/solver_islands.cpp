// The soft step's lanes; the rules are in solver_islands.h.
#include "physics/engine/manifold/solver_islands.h"

#include <algorithm>
#include <cstddef>

namespace rbw {

namespace {

int findRoot(std::vector<int>& parent, int b)
{
    while (parent[static_cast<std::size_t>(b)] != b) {
        // path halving
        parent[static_cast<std::size_t>(b)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(b)])];
        b = parent[static_cast<std::size_t>(b)];
    }
    return b;
}

int lightestLane(const std::vector<SolverLane>& out)
{
    int best = 0;
    for (int l = 1; l < static_cast<int>(out.size()); ++l) {
        if (out[static_cast<std::size_t>(l)].weight < out[static_cast<std::size_t>(best)].weight) best = l;
    }
    return best;
}

} // namespace

void splitIntoLanes(const std::vector<std::array<int, 2>>& ends, const std::vector<int>& weights,
                    const std::vector<char>& moving, int lanes, std::vector<SolverLane>& out, IslandScratch& scratch)
{
    const int bodies = static_cast<int>(moving.size());
    const int constraints = static_cast<int>(ends.size());
    lanes = std::max(lanes, 1);
    out.resize(static_cast<std::size_t>(lanes));
    for (SolverLane& lane : out) {
        lane.constraints.clear();
        lane.bodies.clear();
        lane.weight = 0;
    }
    // Islands: union of the two ends of every constraint between two moving bodies
    std::vector<int>& parent = scratch.parent;
    parent.resize(static_cast<std::size_t>(bodies));
    for (int b = 0; b < bodies; ++b) parent[static_cast<std::size_t>(b)] = b;
    const auto movingBody = [&moving, bodies](int b) { return b >= 0 && b < bodies && moving[static_cast<std::size_t>(b)]; };
    for (const std::array<int, 2>& e : ends) {
        if (!movingBody(e[0]) || !movingBody(e[1])) continue;
        const int ra = findRoot(parent, e[0]);
        const int rb = findRoot(parent, e[1]);
        if (ra != rb) parent[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
    }
    // Number the islands in the order of their first constraints; weigh them
    scratch.islandOf.assign(static_cast<std::size_t>(bodies), -1);
    scratch.islandWeight.clear();
    std::vector<int> islandOfConstraint(static_cast<std::size_t>(constraints), -1);
    for (int c = 0; c < constraints; ++c) {
        const std::array<int, 2>& e = ends[static_cast<std::size_t>(c)];
        const int body = movingBody(e[0]) ? e[0] : (movingBody(e[1]) ? e[1] : -1);
        if (body < 0) continue;   // moves nothing: lane 0
        const int root = findRoot(parent, body);
        int& island = scratch.islandOf[static_cast<std::size_t>(root)];
        if (island < 0) {
            island = static_cast<int>(scratch.islandWeight.size());
            scratch.islandWeight.push_back(0);
        }
        scratch.islandWeight[static_cast<std::size_t>(island)] += weights[static_cast<std::size_t>(c)];
        islandOfConstraint[static_cast<std::size_t>(c)] = island;
    }
    // Each island, in order, to the lightest lane
    scratch.laneOfIsland.resize(scratch.islandWeight.size());
    for (std::size_t i = 0; i < scratch.islandWeight.size(); ++i) {
        const int lane = lightestLane(out);
        scratch.laneOfIsland[i] = lane;
        out[static_cast<std::size_t>(lane)].weight += scratch.islandWeight[i];
    }
    for (int c = 0; c < constraints; ++c) {
        const int island = islandOfConstraint[static_cast<std::size_t>(c)];
        const int lane = island < 0 ? 0 : scratch.laneOfIsland[static_cast<std::size_t>(island)];
        out[static_cast<std::size_t>(lane)].constraints.push_back(c);
    }
    for (int b = 0; b < bodies; ++b) {
        if (!moving[static_cast<std::size_t>(b)]) continue;
        const int island = scratch.islandOf[static_cast<std::size_t>(findRoot(parent, b))];
        const int lane = island < 0 ? lightestLane(out) : scratch.laneOfIsland[static_cast<std::size_t>(island)];
        out[static_cast<std::size_t>(lane)].bodies.push_back(b);
    }
}

} // namespace rbw
