// The soft step's lanes on two threads (issue 19; physics/engine/manifold/solver_islands.h):
// the constraints split into whole islands that share no moving body, and a world that
// solves them on two threads steps to the same bits as one that solves them on one.
#include <QtTest>

#include "physics/engine/manifold/solver_islands.h"
#include "physics/engine/world.h"
#include "physics/workbook/lab/contact_problems.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <set>
#include <vector>

using namespace rbw;

namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool sameStates(const std::vector<BodyState>& a, const std::vector<BodyState>& b)
{
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            if (!sameBits(a[i].x_W[k], b[i].x_W[k]) || !sameBits(a[i].v_W[k], b[i].v_W[k]) ||
                !sameBits(a[i].L_W[k], b[i].L_W[k]) || !sameBits(a[i].omega_W[k], b[i].omega_W[k])) {
                return false;
            }
        }
        if (!sameBits(a[i].q_WB.w(), b[i].q_WB.w()) || !sameBits(a[i].q_WB.x(), b[i].q_WB.x()) ||
            !sameBits(a[i].q_WB.y(), b[i].q_WB.y()) || !sameBits(a[i].q_WB.z(), b[i].q_WB.z())) {
            return false;
        }
    }
    return true;
}

} // namespace

class TestSolverLanes : public QObject {
    Q_OBJECT

private slots:
    // Bodies 0..6 moving, 7 fixed (the ground's stand-in), 8 the plane body. Constraints
    // (each one point): c0 (0,1), c1 (2,7), c2 (1,3), c3 (4,5), c4 (2,8), c5 (5,7).
    // Islands by union-find over the moving ends: {0,1,3} (c0, c2; weight 2), {2} (c1, c4;
    // weight 2), {4,5} (c3, c5; weight 2); body 6 has none. The fixed body 7 links nothing,
    // so c1 and c5 are in different islands although both touch it. In the order of the
    // first constraints: island {0,1,3} to lane 0, {2} to lane 1 (lighter), {4,5} to lane 0
    // (a tie: the first lane); body 6 to the lightest lane, lane 1.
    void splitsWholeIslands()
    {
        const std::vector<std::array<int, 2>> ends{{0, 1}, {2, 7}, {1, 3}, {4, 5}, {2, 8}, {5, 7}};
        const std::vector<int> weights(ends.size(), 1);
        const std::vector<char> moving{1, 1, 1, 1, 1, 1, 1, 0, 0};
        std::vector<SolverLane> lanes;
        IslandScratch scratch;
        splitIntoLanes(ends, weights, moving, 2, lanes, scratch);
        QCOMPARE(int(lanes.size()), 2);
        QCOMPARE(lanes[0].constraints, (std::vector<int>{0, 2, 3, 5}));
        QCOMPARE(lanes[1].constraints, (std::vector<int>{1, 4}));
        QCOMPARE(lanes[0].bodies, (std::vector<int>{0, 1, 3, 4, 5}));
        QCOMPARE(lanes[1].bodies, (std::vector<int>{2, 6}));
        QCOMPARE(lanes[0].weight, 4L);
        QCOMPARE(lanes[1].weight, 2L);
        // No moving body in both lanes (the invariant that makes the lanes independent)
        for (const int c0 : lanes[0].constraints) {
            for (const int c1 : lanes[1].constraints) {
                for (const int a : ends[static_cast<std::size_t>(c0)]) {
                    for (const int b : ends[static_cast<std::size_t>(c1)]) {
                        QVERIFY(a != b || !moving[static_cast<std::size_t>(a)]);
                    }
                }
            }
        }
        // One lane: every constraint in order, every moving body
        splitIntoLanes(ends, weights, moving, 1, lanes, scratch);
        QCOMPARE(int(lanes.size()), 1);
        QCOMPARE(lanes[0].constraints, (std::vector<int>{0, 1, 2, 3, 4, 5}));
        QCOMPARE(lanes[0].bodies, (std::vector<int>{0, 1, 2, 3, 4, 5, 6}));
        // Control: with body 7 moving, it joins {2} and {4,5} into one island
        std::vector<char> all = moving;
        all[7] = 1;
        splitIntoLanes(ends, weights, all, 2, lanes, scratch);
        QCOMPARE(lanes[1].constraints, (std::vector<int>{1, 3, 4, 5}));
    }

    // The rain of 100 boxes (the soft step, sleeping on) for 150 steps, through landing
    // (about step 43) and settling: one thread and two give the same bits in every step.
    // Control: the two-thread world did share its lanes between two threads in the steps
    // with 256 points or more, from the landing until the boxes sleep (38 of the 150 steps when written),
    // and the one-thread world never did.
    void twoThreadsSameBits()
    {
        SceneDef scene = lab::contactProblemScene(lab::ContactProblem::Rain, ContactModel::Manifold, 100);
        scene.solver = ManifoldSolver::SoftStep;
        WorldOptions one;
        one.contactThreads = 1;
        WorldOptions two;
        two.contactThreads = 2;
        World serial(scene, one);
        World parallel(scene, two);
        int twoLaneSteps = 0;
        for (int k = 1; k <= 150; ++k) {
            QVERIFY(serial.step().ok);
            QVERIFY(parallel.step().ok);
            QVERIFY2(sameStates(serial.states(), parallel.states()), qPrintable(QStringLiteral("step %1").arg(k)));
            QVERIFY(serial.lastContactLanes() <= 1);
            if (parallel.lastContactLanes() > 1) ++twoLaneSteps;
        }
        QVERIFY2(twoLaneSteps >= 10, qPrintable(QString::number(twoLaneSteps)));
    }
};

QTEST_GUILESS_MAIN(TestSolverLanes)
#include "tst_solver_lanes.moc"
