// The manifold model's narrow phase (issue 11): box-box face clipping and box-plane
// manifolds against hand-derived points, feature ids that survive a small move (the
// warm-start key), and a negative control for every count.
//
// Frames: world y up. A is the unit cube at the origin (half extents 0.5), whose top
// face is the plane y = 0.5; B is placed above it so that its lowest feature is at
// y = 0.49, an overlap of 0.01 m. n points from B to A, i.e. (0, -1, 0).
#include "physics/engine/collision/contact.h"
#include "physics/engine/manifold/box_box_clip.h"
#include "physics/engine/manifold/box_plane_manifold.h"
#include "tests/test_support.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <set>

using rbw::BoxPose;
using rbw::Manifold;
using rbw::Mat3;
using rbw::Quat;
using rbw::Vec3;

Q_DECLARE_METATYPE(rbw::Vec3)
Q_DECLARE_METATYPE(rbw::Quat)

namespace {

constexpr double kTol = 1e-12;
const double kSqrtHalf = std::sqrt(0.5);

BoxPose box(const Vec3& c_W, const Quat& q_WB, const Vec3& halfExtents)
{
    return BoxPose{c_W, q_WB.toRotationMatrix(), halfExtents};
}

// The rotation that turns the unit cube's body diagonal (1, 1, 1)/sqrt 3 onto -y, so a
// corner points straight down (the axis is (1,1,1) x (0,-1,0) = (1, 0, -1)).
Quat cornerDown()
{
    const Vec3 diagonal = Vec3(1, 1, 1).normalized();
    return Quat::FromTwoVectors(diagonal, Vec3(0, -1, 0));
}

bool containsPoint(const Manifold& m, const Vec3& p_W, double tol)
{
    for (int k = 0; k < m.count; ++k) {
        if ((m.points[static_cast<std::size_t>(k)].p_W - p_W).norm() <= tol) return true;
    }
    return false;
}

} // namespace

class TestManifold : public QObject {
    Q_OBJECT

private slots:
    // Face-face, edge-face, vertex-face and the octagon of two crossed squares.
    void clipping_data()
    {
        QTest::addColumn<Vec3>("centreB");
        QTest::addColumn<Quat>("orientationB");
        QTest::addColumn<Vec3>("halfB");
        QTest::addColumn<int>("count");
        QTest::addColumn<QList<Vec3>>("points");

        // Face-face: B a cube of edge 0.5 at (0.1, 0.74, 0), its bottom face y = 0.49
        // lies inside A's top face; all 4 corners (0.1 +- 0.25, 0.49, +-0.25) are kept,
        // each with s = 0.49 - 0.5 = -0.01; p = midway to the face: y = 0.495.
        QTest::newRow("face-face: 4 points")
            << Vec3(0.1, 0.74, 0.0) << Quat(Quat::Identity()) << Vec3(Vec3::Constant(0.25)) << 4
            << QList<Vec3>{Vec3(0.35, 0.495, 0.25), Vec3(-0.15, 0.495, 0.25), Vec3(-0.15, 0.495, -0.25),
                           Vec3(0.35, 0.495, -0.25)};
        // Edge-face: the unit cube turned 45 degrees about z stands on an edge along z,
        // sqrt(1/2) below its centre. Centre y = 0.49 + sqrt(1/2): the edge's two ends
        // (0, 0.49, +-0.5) are the points (s = -0.01); the other corners of the
        // incident face are 0.707 m higher, beyond the 0.02 m margin.
        QTest::newRow("edge-face: 2 points")
            << Vec3(0.0, 0.49 + kSqrtHalf, 0.0) << Quat(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitZ()))
            << Vec3(Vec3::Constant(0.5)) << 2 << QList<Vec3>{Vec3(0.0, 0.495, 0.5), Vec3(0.0, 0.495, -0.5)};
        // Vertex-face: a corner straight down, sqrt(3)/2 below the centre; its
        // neighbours on the incident face are 1/sqrt(3) = 0.577 m higher.
        QTest::newRow("vertex-face: 1 point")
            << Vec3(0.0, 0.49 + std::sqrt(3.0) / 2.0, 0.0) << cornerDown() << Vec3(Vec3::Constant(0.5)) << 1
            << QList<Vec3>{Vec3(0.0, 0.495, 0.0)};
        // Octagon: the unit cube turned 45 degrees about y on A. Its bottom square has
        // corners sqrt(1/2) = 0.7071 out along x and z, edges on |x| + |z| = sqrt(1/2).
        // A's side planes, moved out by the clip tolerance 0.005 m (box_box_clip.cpp),
        // |x| = 0.505 and |z| = 0.505, cut each edge twice: at the other coordinate
        // +-(sqrt(1/2) - 0.505) = +-0.2021.
        const double e = 0.505;
        const double c = kSqrtHalf - e;
        QTest::newRow("face-face turned 45 degrees: 8 points")
            << Vec3(0.0, 0.99, 0.0) << Quat(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitY())) << Vec3(Vec3::Constant(0.5)) << 8
            << QList<Vec3>{Vec3(e, 0.495, c), Vec3(e, 0.495, -c), Vec3(-e, 0.495, c), Vec3(-e, 0.495, -c),
                           Vec3(c, 0.495, e), Vec3(-c, 0.495, e), Vec3(c, 0.495, -e), Vec3(-c, 0.495, -e)};
    }

    void clipping()
    {
        QFETCH(Vec3, centreB);
        QFETCH(Quat, orientationB);
        QFETCH(Vec3, halfB);
        QFETCH(int, count);
        QFETCH(QList<Vec3>, points);
        const BoxPose A = box(Vec3::Zero(), Quat::Identity(), Vec3::Constant(0.5));
        const BoxPose B = box(centreB, orientationB, halfB);
        Manifold m;
        QVERIFY(rbw::collideBoxBoxManifold(A, B, 0.02, m));
        QCOMPARE(m.count, count);
        RBW_COMPARE_NEAR_STRICT(m.n_W, Vec3(0, -1, 0), 1e-12);   // from B (above) to A
        QCOMPARE(m.reference, rbw::ReferenceSide::A);         // A's top face is the reference
        for (const Vec3& p : points) {
            QVERIFY2(containsPoint(m, p, 1e-9), qPrintable(QStringLiteral("missing (%1, %2, %3)")
                                                                .arg(p.x()).arg(p.y()).arg(p.z())));
        }
        std::set<std::uint32_t> ids;
        for (int k = 0; k < m.count; ++k) {
            const rbw::ManifoldPoint& pt = m.points[static_cast<std::size_t>(k)];
            RBW_COMPARE_NEAR_STRICT(pt.separation, -0.01, 1e-9);   // 0.49 - 0.5
            // The anchors: on A's top face and on B, s = n . (pA - pB)
            const Vec3 pA_W = A.c_W + A.R_WB * pt.pA_A;
            const Vec3 pB_W = B.c_W + B.R_WB * pt.pB_B;
            RBW_COMPARE_NEAR_STRICT(pA_W.y(), 0.5, 1e-9);   // (on the face's plane)
            RBW_COMPARE_NEAR_STRICT(pB_W.y(), 0.49, 1e-9);
            RBW_COMPARE_NEAR_STRICT(m.n_W.dot(pA_W - pB_W), pt.separation, kTol);
            ids.insert(pt.feature);
        }
        QCOMPARE(static_cast<int>(ids.size()), m.count);   // one id per point

        // The ids survive a small move (what warm starting needs): B 1 mm to the side.
        Manifold moved;
        QVERIFY(rbw::collideBoxBoxManifold(A, box(centreB + Vec3(0.001, 0.0, 0.0005), orientationB, halfB), 0.02, moved));
        QCOMPARE(moved.count, m.count);
        for (int k = 0; k < moved.count; ++k) QVERIFY(ids.count(moved.points[static_cast<std::size_t>(k)].feature) == 1);

        // Negative control: lifted by 0.03 m (overlap -0.02, apart by 0.02 + 0.01 > margin)
        Manifold apart;
        QVERIFY(!rbw::collideBoxBoxManifold(A, box(centreB + Vec3(0, 0.031, 0), orientationB, halfB), 0.02, apart));
        QCOMPARE(apart.count, 0);
    }

    // Within the margin but apart: a speculative point with s > 0.
    void speculativePoint()
    {
        const BoxPose A = box(Vec3::Zero(), Quat::Identity(), Vec3::Constant(0.5));
        // B's bottom at y = 0.51: apart by 0.01 < margin 0.02
        Manifold m;
        QVERIFY(rbw::collideBoxBoxManifold(A, box(Vec3(0, 1.01, 0), Quat::Identity(), Vec3::Constant(0.5)), 0.02, m));
        QCOMPARE(m.count, 4);
        RBW_COMPARE_NEAR_STRICT(m.points[0].separation, 0.01, 1e-12);
    }

    // The reduction keeps the deepest point and spans the polygon.
    void reduction()
    {
        const BoxPose A = box(Vec3::Zero(), Quat::Identity(), Vec3::Constant(0.5));
        const BoxPose B = box(Vec3(0.0, 0.99, 0.0), Quat(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitY())), Vec3::Constant(0.5));
        Manifold m;
        QVERIFY(rbw::collideBoxBoxManifold(A, B, 0.02, m, 4));
        QCOMPARE(m.count, 4);
        Manifold all;
        QVERIFY(rbw::collideBoxBoxManifold(A, B, 0.02, all, 8));
        QCOMPARE(all.count, 8);
    }

    // Box-plane: every corner within the margin, feature = corner index.
    void boxPlane_data()
    {
        QTest::addColumn<Vec3>("centre");
        QTest::addColumn<Quat>("orientation");
        QTest::addColumn<int>("count");
        QTest::addColumn<double>("deepest");
        // The ground is y = 0 here; each box's lowest feature is at y = -0.01.
        // Flat, centre y = 0.49: the 4 lower corners (indices 0, 1, 4, 5: bit 1 clear).
        QTest::newRow("face: 4 corners") << Vec3(0, 0.49, 0) << Quat(Quat::Identity()) << 4 << -0.01;
        // On an edge (45 degrees about z), centre sqrt(1/2) - 0.01: the edge's 2 corners;
        // the next corners are sqrt(1/2) higher.
        QTest::newRow("edge: 2 corners") << Vec3(0, kSqrtHalf - 0.01, 0) << Quat(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitZ()))
                                         << 2 << -0.01;
        // On a corner, centre sqrt(3)/2 - 0.01; the next corners are 1/sqrt(3) higher.
        QTest::newRow("vertex: 1 corner") << Vec3(0, std::sqrt(3.0) / 2.0 - 0.01, 0) << cornerDown() << 1 << -0.01;
        // Negative control: 0.03 above the ground
        QTest::newRow("apart: none") << Vec3(0, 0.53, 0) << Quat(Quat::Identity()) << 0 << 0.0;
    }

    void boxPlane()
    {
        QFETCH(Vec3, centre);
        QFETCH(Quat, orientation);
        QFETCH(int, count);
        QFETCH(double, deepest);
        rbw::PlaneDef ground;
        Manifold m;
        const bool hit = rbw::collideBoxPlaneManifold(box(centre, orientation, Vec3::Constant(0.5)), ground, 0.02, m);
        QCOMPARE(hit, count > 0);
        QCOMPARE(m.count, count);
        for (int k = 0; k < m.count; ++k) {
            const rbw::ManifoldPoint& p = m.points[static_cast<std::size_t>(k)];
            RBW_COMPARE_NEAR_STRICT(p.separation, deepest, 1e-9);
            QVERIFY(p.feature < 8);
            RBW_COMPARE_NEAR_STRICT(p.pB_B.y(), 0.0, kTol);   // B's anchor lies on the plane
        }
    }
};

QTEST_APPLESS_MAIN(TestManifold)
#include "tst_manifold.moc"
