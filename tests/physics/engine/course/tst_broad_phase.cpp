// The sweep-and-prune broad phase (physics/engine/collision/broad_phase.h): tight AABBs of
// oriented boxes, the pair set against brute force over all pairs, the skipping of
// fixed-fixed pairs, the counters, the persistent order across frames, and the
// pruning on a grid.
//
// Tolerance. AABB bounds are sums of three products |R_kj| h_j; compared with the
// bounds of the 8 corners (another rounding order) they agree to a few 1e-16 of the
// box size (<= 10 here): 1e-12 absolute. Pair sets and counters are integers: exact.

#include "tests/test_support.h"

#include <QtTest>

#include "physics/engine/collision/broad_phase.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace {

using rbw::Aabb;
using rbw::BoxPose;
using rbw::BroadPhaseStats;
using rbw::Mat3;
using rbw::Quat;
using rbw::SweepAndPrune;
using rbw::Vec3;

using PairList = std::vector<std::pair<int, int>>;

using rbw::test::box;

// Independent overlap test, written out per axis (touching counts).
bool overlapsOn(const Aabb& a, const Aabb& b, int k) { return a.min_W[k] <= b.max_W[k] && b.min_W[k] <= a.max_W[k]; }

// Brute force: every pair i < j with at least one movable box and overlapping AABBs.
// Also counts the pairs that overlap on x (with at least one movable box): the sweep
// tests exactly those (see xOverlapCountEqualsTests).
PairList bruteForce(const std::vector<Aabb>& boxes, const std::vector<char>& movable, long* xOverlapping)
{
    PairList pairs;
    long onX = 0;
    const int n = static_cast<int>(boxes.size());
    for (int i = 0; i < n; ++i) {
        for (int j = i + 1; j < n; ++j) {
            if (!movable[static_cast<size_t>(i)] && !movable[static_cast<size_t>(j)]) {
                continue;
            }
            const Aabb& a = boxes[static_cast<size_t>(i)];
            const Aabb& b = boxes[static_cast<size_t>(j)];
            if (overlapsOn(a, b, 0)) {
                ++onX;
                if (overlapsOn(a, b, 1) && overlapsOn(a, b, 2)) {
                    pairs.emplace_back(i, j);
                }
            }
        }
    }
    if (xOverlapping != nullptr) {
        *xOverlapping = onX;
    }
    return pairs;
}

struct RandomScene {
    std::vector<BoxPose> poses;
    std::vector<char> movable;
};

// n random boxes in [0, 10]^3, half extents in [0.1, 1], random orientations (a
// normalised Gaussian 4-vector is a uniform rotation), a quarter of them fixed.
RandomScene randomScene(int n, std::mt19937& rng)
{
    std::uniform_real_distribution<double> pos(0.0, 10.0);
    std::uniform_real_distribution<double> half(0.1, 1.0);
    std::normal_distribution<double> gauss(0.0, 1.0);
    std::uniform_int_distribution<int> quarter(0, 3);
    RandomScene s;
    for (int i = 0; i < n; ++i) {
        const Quat q = Quat(gauss(rng), gauss(rng), gauss(rng), gauss(rng)).normalized();
        s.poses.push_back(box(Vec3(pos(rng), pos(rng), pos(rng)), q.toRotationMatrix(),
                              Vec3(half(rng), half(rng), half(rng))));
        s.movable.push_back(quarter(rng) == 0 ? 0 : 1);
    }
    return s;
}

std::vector<Aabb> aabbsOf(const std::vector<BoxPose>& poses)
{
    std::vector<Aabb> out;
    for (const BoxPose& p : poses) {
        out.push_back(rbw::boxAabb(p));
    }
    return out;
}

QString pairText(const PairList& pairs)
{
    QStringList parts;
    for (const auto& [i, j] : pairs) {
        parts << QStringLiteral("(%1,%2)").arg(i).arg(j);
    }
    return parts.join(' ');
}

} // namespace

class TestBroadPhase : public QObject {
    Q_OBJECT

private slots:
    void aabbOfRotatedCube();
    void aabbMatchesCorners();
    void matchesBruteForce_data();
    void matchesBruteForce();
    void persistsAcrossFrames();
    void fixedPairsSkipped();
    void touchingCounts();
    void gridTestsFarFewerPairs();
    void treeLimits_data();
    void treeLimits();
    void fixedBoxNotCapped();
    void restingBoxesOutOfTheTree();
};

// A unit cube turned 45 deg about z: R = [[c, -s, 0], [s, c, 0], [0, 0, 1]], h = 1/2.
// e_x = |c| h + |-s| h + 0 = sqrt2/2, e_y = |s| h + |c| h = sqrt2/2, e_z = h = 1/2.
// At c = (1, 2, 3): min (1 - sqrt2/2, 2 - sqrt2/2, 2.5), max (1 + sqrt2/2, ..., 3.5).
void TestBroadPhase::aabbOfRotatedCube()
{
    const double e = std::numbers::sqrt2 / 2;
    const Aabb a = rbw::boxAabb(box(Vec3(1, 2, 3), Eigen::AngleAxisd(std::numbers::pi / 4, Vec3::UnitZ()).toRotationMatrix(),
                                    Vec3::Constant(0.5)));
    QVERIFY(((a.min_W - Vec3(1 - e, 2 - e, 2.5)).cwiseAbs().maxCoeff()) <= 1e-12);
    QVERIFY(((a.max_W - Vec3(1 + e, 2 + e, 3.5)).cwiseAbs().maxCoeff()) <= 1e-12);
}

// Tight: the AABB is exactly the bounding box of the 8 corners, since on each world
// axis k the extreme corner picks s_j = sign(R_kj), giving c_k +- sum_j |R_kj| h_j.
void TestBroadPhase::aabbMatchesCorners()
{
    std::mt19937 rng(7);
    const RandomScene s = randomScene(50, rng);
    for (const BoxPose& p : s.poses) {
        const Aabb a = rbw::boxAabb(p);
        Vec3 lo = Vec3::Constant(1e300);
        Vec3 hi = Vec3::Constant(-1e300);
        for (const Vec3& corner : rbw::boxCorners(p)) {
            lo = lo.cwiseMin(corner);
            hi = hi.cwiseMax(corner);
        }
        QVERIFY((a.min_W - lo).cwiseAbs().maxCoeff() <= 1e-12);
        QVERIFY((a.max_W - hi).cwiseAbs().maxCoeff() <= 1e-12);
    }
}

// Random boxes (fixed seeds): the pair set equals brute force's, each pair once with
// i < j, sorted; pairsOverlapping = the number of pairs; pairsTested = the number of
// pairs (with a movable box) whose x-intervals overlap: after sorting by min_x, box
// i's candidates are exactly the later boxes j with min_x(j) <= max_x(i), which with
// min_x(i) <= min_x(j) <= max_x(j) is x-overlap; the sweep stops at the first
// min_x(j) > max_x(i), and every later box starts further right.
void TestBroadPhase::matchesBruteForce_data()
{
    QTest::addColumn<int>("seed");
    QTest::addColumn<int>("count");
    QTest::newRow("seed 1, 200 boxes") << 1 << 200;
    QTest::newRow("seed 2, 500 boxes") << 2 << 500;
    QTest::newRow("seed 3, 2 boxes") << 3 << 2;
    QTest::newRow("no boxes") << 4 << 0;
}

void TestBroadPhase::matchesBruteForce()
{
    QFETCH(int, seed);
    QFETCH(int, count);

    std::mt19937 rng(static_cast<unsigned>(seed));
    const RandomScene s = randomScene(count, rng);
    const std::vector<Aabb> boxes = aabbsOf(s.poses);
    long xOverlapping = 0;
    const PairList expected = bruteForce(boxes, s.movable, &xOverlapping);

    SweepAndPrune sap;
    PairList pairs{{-1, -1}};   // must be cleared
    BroadPhaseStats stats{99, 99};
    sap.findPairs(boxes, s.movable, pairs, stats);
    QVERIFY2(pairs == expected, qPrintable(QStringLiteral("got %1\nexpected %2").arg(pairText(pairs), pairText(expected))));
    QCOMPARE(stats.pairsOverlapping, static_cast<long>(expected.size()));
    QCOMPARE(stats.pairsTested, xOverlapping);
    if (count >= 200) {
        // The scene is dense enough to be a real test: some pairs overlap, some
        // x-overlapping pairs are rejected on y or z.
        QVERIFY(!expected.empty());
        QVERIFY(stats.pairsTested > stats.pairsOverlapping);
    }
    // Each pair once, i < j (sorted and unique).
    for (size_t k = 0; k < pairs.size(); ++k) {
        QVERIFY(pairs[k].first < pairs[k].second);
        if (k > 0) {
            QVERIFY(pairs[k - 1] < pairs[k]);
        }
    }
    // The persistent order is sorted by min_x.
    const std::vector<int>& order = sap.order();
    QCOMPARE(static_cast<int>(order.size()), count);
    for (size_t k = 1; k < order.size(); ++k) {
        QVERIFY(boxes[static_cast<size_t>(order[k - 1])].min_W.x() <= boxes[static_cast<size_t>(order[k])].min_W.x());
    }
}

// Frames: the same SweepAndPrune over 30 frames of jittered boxes (each moves up to
// 0.2 per axis per frame, so the order changes a little), then a frame with boxes
// added and one with boxes removed. Every frame must equal brute force.
void TestBroadPhase::persistsAcrossFrames()
{
    std::mt19937 rng(11);
    RandomScene s = randomScene(300, rng);
    std::uniform_real_distribution<double> jitter(-0.2, 0.2);
    SweepAndPrune sap;
    PairList pairs;
    BroadPhaseStats stats;
    for (int frame = 0; frame < 32; ++frame) {
        if (frame == 30) {
            const RandomScene more = randomScene(40, rng);
            s.poses.insert(s.poses.end(), more.poses.begin(), more.poses.end());
            s.movable.insert(s.movable.end(), more.movable.begin(), more.movable.end());
        } else if (frame == 31) {
            s.poses.resize(150);
            s.movable.resize(150);
        } else if (frame > 0) {
            for (BoxPose& p : s.poses) {
                p.c_W += Vec3(jitter(rng), jitter(rng), jitter(rng));
            }
        }
        const std::vector<Aabb> boxes = aabbsOf(s.poses);
        long xOverlapping = 0;
        const PairList expected = bruteForce(boxes, s.movable, &xOverlapping);
        sap.findPairs(boxes, s.movable, pairs, stats);
        QVERIFY2(pairs == expected, qPrintable(QStringLiteral("frame %1 differs").arg(frame)));
        QCOMPARE(stats.pairsTested, xOverlapping);
        QCOMPARE(static_cast<int>(sap.order().size()), static_cast<int>(s.poses.size()));
    }
}

// Three unit cubes at x = 0, 0.5, 1 (all AABBs pairwise overlapping: centres <= 1
// apart, AABB width 1). Boxes 0 and 1 fixed, 2 movable: pairs (0,2), (1,2); the fixed
// pair (0,1) is skipped before its test, so pairsTested = 2, pairsOverlapping = 2.
// Negative control: all three fixed -> no pairs, no tests.
void TestBroadPhase::fixedPairsSkipped()
{
    const std::vector<BoxPose> poses{box(Vec3(0, 0, 0), Mat3::Identity(), Vec3::Constant(0.5)),
                                     box(Vec3(0.5, 0, 0), Mat3::Identity(), Vec3::Constant(0.5)),
                                     box(Vec3(1, 0, 0), Mat3::Identity(), Vec3::Constant(0.5))};
    const std::vector<Aabb> boxes = aabbsOf(poses);
    SweepAndPrune sap;
    PairList pairs;
    BroadPhaseStats stats;
    sap.findPairs(boxes, {0, 0, 1}, pairs, stats);
    QVERIFY2((pairs == PairList{{0, 2}, {1, 2}}), qPrintable(pairText(pairs)));
    QCOMPARE(stats.pairsTested, 2L);
    QCOMPARE(stats.pairsOverlapping, 2L);

    sap.findPairs(boxes, {0, 0, 0}, pairs, stats);
    QVERIFY(pairs.empty());
    QCOMPARE(stats.pairsTested, 0L);
    QCOMPARE(stats.pairsOverlapping, 0L);

    // All movable: all three pairs.
    sap.findPairs(boxes, {1, 1, 1}, pairs, stats);
    QVERIFY2((pairs == PairList{{0, 1}, {0, 2}, {1, 2}}), qPrintable(pairText(pairs)));
    QCOMPARE(stats.pairsTested, 3L);
}

// Touching boundaries count: unit cubes at x = 0 and x = 1 share the plane x = 0.5
// exactly (dyadic). Reported. Negative control: x = 1 + 2^-20 -> a gap, one x test
// fewer (the sweep stops before it), no pair.
void TestBroadPhase::touchingCounts()
{
    SweepAndPrune sap;
    PairList pairs;
    BroadPhaseStats stats;
    const std::vector<Aabb> touching{rbw::boxAabb(box(Vec3(0, 0, 0), Mat3::Identity(), Vec3::Constant(0.5))),
                                     rbw::boxAabb(box(Vec3(1, 0.3, -0.2), Mat3::Identity(), Vec3::Constant(0.5)))};
    sap.findPairs(touching, {1, 1}, pairs, stats);
    QVERIFY((pairs == PairList{{0, 1}}));
    QCOMPARE(stats.pairsTested, 1L);

    const std::vector<Aabb> apart{touching[0], rbw::boxAabb(box(Vec3(1 + std::ldexp(1.0, -20), 0.3, -0.2),
                                                               Mat3::Identity(), Vec3::Constant(0.5)))};
    sap.findPairs(apart, {1, 1}, pairs, stats);
    QVERIFY(pairs.empty());
    QCOMPARE(stats.pairsTested, 0L);
}

// A 10 x 10 x 10 grid of unit cubes at (2i, 2j, 2k), all movable: neighbours are 1
// apart, nothing overlaps. On x, a cube spans [2i - 0.5, 2i + 0.5]; the next slab
// starts at 2i + 1.5, so only cubes of the same slab i overlap on x: 10 slabs of 100
// cubes, C(100, 2) = 4950 tests each, 49500 in all, against n^2/2 = 500000 for all
// pairs (n(n-1)/2 = 499500). No pair is reported.
void TestBroadPhase::gridTestsFarFewerPairs()
{
    std::vector<Aabb> boxes;
    for (int i = 0; i < 10; ++i) {
        for (int j = 0; j < 10; ++j) {
            for (int k = 0; k < 10; ++k) {
                boxes.push_back(rbw::boxAabb(box(Vec3(2.0 * i, 2.0 * j, 2.0 * k), Mat3::Identity(), Vec3::Constant(0.5))));
            }
        }
    }
    // Shuffle the input order so the sweep's sort has work to do.
    std::mt19937 rng(5);
    std::shuffle(boxes.begin(), boxes.end(), rng);
    const std::vector<char> movable(boxes.size(), 1);
    SweepAndPrune sap;
    PairList pairs;
    BroadPhaseStats stats;
    sap.findPairs(boxes, movable, pairs, stats);
    QVERIFY(pairs.empty());
    QCOMPARE(stats.pairsOverlapping, 0L);
    QCOMPARE(stats.pairsTested, 49500L);
    QVERIFY(stats.pairsTested < 1000L * 1000L / 2 / 10 + 1);
    // Again, with the order kept from the last call: the same counts.
    sap.findPairs(boxes, movable, pairs, stats);
    QCOMPARE(stats.pairsTested, 49500L);
}

// The AABB tree's caps (PairLimits; the manifold model's work limits, issue 22) on 20
// coincident unit cubes: C(20, 2) = 190 overlapping pairs, 19 per cube. A cap stops the
// search at the first pair beyond it ("more than"): maxPerBody 18 stops when some cube
// gets its 19th pair, and that cube is then in exactly 19 of the pairs found;
// maxPerBody 19 and maxPairs 190 are just not exceeded (all 190 pairs, the control);
// maxPairs 189 stops at the 190th pair. With no cap: 190 pairs.
void TestBroadPhase::treeLimits_data()
{
    QTest::addColumn<long>("maxPairs");
    QTest::addColumn<int>("maxPerBody");
    QTest::addColumn<int>("hit");        // PairLimitHit
    QTest::addColumn<long>("pairCount");   // -1: not checked (where the search stopped)
    QTest::newRow("no caps") << 0L << 0 << int(rbw::PairLimitHit::None) << 190L;
    QTest::newRow("per body 19") << 0L << 19 << int(rbw::PairLimitHit::None) << 190L;
    QTest::newRow("per body 18") << 0L << 18 << int(rbw::PairLimitHit::PairsPerBody) << -1L;
    QTest::newRow("pairs 190") << 190L << 0 << int(rbw::PairLimitHit::None) << 190L;
    QTest::newRow("pairs 189") << 189L << 0 << int(rbw::PairLimitHit::Pairs) << 190L;
}

void TestBroadPhase::treeLimits()
{
    QFETCH(long, maxPairs);
    QFETCH(int, maxPerBody);
    QFETCH(int, hit);
    QFETCH(long, pairCount);
    const std::vector<Aabb> boxes(20, rbw::boxAabb(box(Vec3(0, 0, 0), Mat3::Identity(), Vec3::Constant(0.5))));
    rbw::AabbTree tree;
    PairList pairs;
    BroadPhaseStats stats;
    tree.findPairs(boxes, std::vector<char>(boxes.size(), 1), pairs, stats, rbw::PairLimits{maxPairs, maxPerBody});
    QCOMPARE(int(stats.limitHit), hit);
    if (pairCount >= 0) QCOMPARE(long(pairs.size()), pairCount);
    if (stats.limitHit == rbw::PairLimitHit::PairsPerBody) {
        QVERIFY(stats.limitBody >= 0 && stats.limitBody < 20);
        const long with = std::count_if(pairs.begin(), pairs.end(), [&stats](const std::pair<int, int>& p) {
            return p.first == stats.limitBody || p.second == stats.limitBody;
        });
        QCOMPARE(with, long(maxPerBody) + 1);
        QVERIFY(long(pairs.size()) < 190L);
    } else {
        QCOMPARE(stats.limitBody, -1);
    }
}

// A fixed box is not capped: each of its pairs has a movable box, which is. A fixed
// 100 x 1 x 1 floor under 20 unit cubes at x = 5i - 47.5 (5 m apart: they do not touch
// each other) has 20 pairs, each cube 1; maxPerBody 1 is not exceeded.
void TestBroadPhase::fixedBoxNotCapped()
{
    std::vector<Aabb> boxes{rbw::boxAabb(box(Vec3(0, -1, 0), Mat3::Identity(), Vec3(50, 0.5, 0.5)))};
    for (int i = 0; i < 20; ++i) {
        boxes.push_back(rbw::boxAabb(box(Vec3(5.0 * i - 47.5, 0, 0), Mat3::Identity(), Vec3::Constant(0.5))));
    }
    std::vector<char> movable(boxes.size(), 1);
    movable[0] = 0;
    rbw::AabbTree tree;
    PairList pairs;
    BroadPhaseStats stats;
    tree.findPairs(boxes, movable, pairs, stats, rbw::PairLimits{0, 1});
    QCOMPARE(int(stats.limitHit), int(rbw::PairLimitHit::None));
    QCOMPARE(long(pairs.size()), 20L);
    // Negative control: the same floor movable is capped at its second pair.
    movable[0] = 1;
    tree.findPairs(boxes, movable, pairs, stats, rbw::PairLimits{0, 1});
    QCOMPARE(int(stats.limitHit), int(rbw::PairLimitHit::PairsPerBody));
    QCOMPARE(stats.limitBody, 0);
}

// Sleeping boxes kept out of the tree (issue 19): with every third movable box resting,
// the pairs are brute force's less those of two resting boxes and of a resting and a
// fixed box (the manifold model never solves them), and no more AABB tests are done
// than without. Negative control: the random scene has such pairs, so the filter is
// not vacuous.
void TestBroadPhase::restingBoxesOutOfTheTree()
{
    std::mt19937 rng(7);
    const RandomScene s = randomScene(500, rng);
    const std::vector<Aabb> boxes = aabbsOf(s.poses);
    std::vector<char> resting(boxes.size(), 0);
    for (std::size_t i = 0; i < boxes.size(); i += 3) resting[i] = s.movable[i];
    const PairList all = bruteForce(boxes, s.movable, nullptr);
    PairList expected;
    for (const auto& [i, j] : all) {
        const bool awakeI = s.movable[static_cast<std::size_t>(i)] && !resting[static_cast<std::size_t>(i)];
        const bool awakeJ = s.movable[static_cast<std::size_t>(j)] && !resting[static_cast<std::size_t>(j)];
        if (awakeI || awakeJ) expected.push_back({i, j});
    }
    QVERIFY(expected.size() < all.size());   // the control: some pairs are left out
    QVERIFY(!expected.empty());
    rbw::AabbTree tree;
    PairList pairs;
    BroadPhaseStats whole;
    tree.findPairs(boxes, s.movable, pairs, whole);
    QVERIFY(pairs == all);
    BroadPhaseStats stats;
    tree.findPairs(boxes, s.movable, pairs, stats, {}, &resting);
    QVERIFY2(pairs == expected, qPrintable(QStringLiteral("got %1\nexpected %2").arg(pairText(pairs), pairText(expected))));
    QCOMPARE(stats.pairsOverlapping, static_cast<long>(expected.size()));
    QVERIFY(stats.pairsTested <= whole.pairsTested);
}

QTEST_APPLESS_MAIN(TestBroadPhase)
#include "tst_broad_phase.moc"
