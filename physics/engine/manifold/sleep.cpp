#include "physics/engine/manifold/sleep.h"

#include <algorithm>

namespace rbw {

void SleepState::resize(int bodies)
{
    restTime_.assign(static_cast<std::size_t>(bodies), 0.0);
    island_.assign(static_cast<std::size_t>(bodies), -1);
    members_.clear();
}

void SleepState::reset()
{
    resize(static_cast<int>(restTime_.size()));
}

int SleepState::sleepingCount() const
{
    return static_cast<int>(std::count_if(island_.begin(), island_.end(), [](int i) { return i >= 0; }));
}

void SleepState::wake(int b)
{
    const int id = island_[static_cast<std::size_t>(b)];
    if (id < 0) return;
    for (int member : members_[static_cast<std::size_t>(id)]) {
        island_[static_cast<std::size_t>(member)] = -1;
        restTime_[static_cast<std::size_t>(member)] = 0.0;
    }
    members_[static_cast<std::size_t>(id)].clear();
}

std::size_t SleepState::bytes() const
{
    std::size_t n = restTime_.capacity() * sizeof(double) + island_.capacity() * sizeof(int) +
                    members_.capacity() * sizeof(std::vector<int>);
    for (const std::vector<int>& m : members_) n += m.capacity() * sizeof(int);
    return n;
}

namespace {

int rootOf(std::vector<int>& parent, int b)
{
    // Union-find with path halving.
    while (parent[static_cast<std::size_t>(b)] != b) {
        parent[static_cast<std::size_t>(b)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(b)])];
        b = parent[static_cast<std::size_t>(b)];
    }
    return b;
}

} // namespace

void SleepState::update(std::vector<BodyState>& states, const std::vector<char>& movable,
                        const std::vector<Manifold>& manifolds, double h, const ManifoldSettings& settings,
                        SleepScratch& scratch)
{
    const int n = static_cast<int>(states.size());
    std::vector<int>& parent = scratch.parent;
    parent.resize(static_cast<std::size_t>(n));
    const auto find = [&parent](int b) { return rootOf(parent, b); };
    const double lin2 = settings.sleepLinear * settings.sleepLinear;
    const double ang2 = settings.sleepAngular * settings.sleepAngular;
    for (int b = 0; b < n; ++b) {
        parent[static_cast<std::size_t>(b)] = b;
        if (!movable[static_cast<std::size_t>(b)] || asleep(b)) continue;
        const BodyState& s = states[static_cast<std::size_t>(b)];
        // t_rest <- t_rest + h if |v| <= v_sleep and |omega| <= omega_sleep, else 0
        const bool slow = s.v_W.squaredNorm() <= lin2 && s.omega_W.squaredNorm() <= ang2;
        restTime_[static_cast<std::size_t>(b)] = slow ? restTime_[static_cast<std::size_t>(b)] + h : 0.0;
    }
    // Islands: bodies joined by a manifold with points, both movable and awake.
    for (const Manifold& m : manifolds) {
        if (m.count == 0 || m.b < 0) continue;
        if (!movable[static_cast<std::size_t>(m.a)] || !movable[static_cast<std::size_t>(m.b)]) continue;
        if (asleep(m.a) || asleep(m.b)) continue;
        const int ra = find(m.a);
        const int rb = find(m.b);
        if (ra != rb) parent[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
    }
    // The least rest time of each island, kept at its root.
    std::vector<double>& least = scratch.least;
    least.assign(static_cast<std::size_t>(n), 1e300);
    for (int b = 0; b < n; ++b) {
        if (!movable[static_cast<std::size_t>(b)] || asleep(b)) continue;
        double& l = least[static_cast<std::size_t>(find(b))];
        l = std::min(l, restTime_[static_cast<std::size_t>(b)]);
    }
    std::vector<int>& idOfRoot = scratch.idOfRoot;
    idOfRoot.assign(static_cast<std::size_t>(n), -1);
    for (int b = 0; b < n; ++b) {
        if (!movable[static_cast<std::size_t>(b)] || asleep(b)) continue;
        const int root = find(b);
        if (least[static_cast<std::size_t>(root)] < settings.timeToSleep) continue;
        int& id = idOfRoot[static_cast<std::size_t>(root)];
        if (id < 0) {
            const auto freeSlot = std::find_if(members_.begin(), members_.end(),
                                               [](const std::vector<int>& v) { return v.empty(); });
            id = static_cast<int>(freeSlot - members_.begin());
            if (freeSlot == members_.end()) members_.emplace_back();
        }
        members_[static_cast<std::size_t>(id)].push_back(b);
        island_[static_cast<std::size_t>(b)] = id;
        // Asleep: v = L = omega = 0
        BodyState& s = states[static_cast<std::size_t>(b)];
        s.v_W = Vec3::Zero();
        s.L_W = Vec3::Zero();
        s.omega_W = Vec3::Zero();
    }
}

} // namespace rbw
