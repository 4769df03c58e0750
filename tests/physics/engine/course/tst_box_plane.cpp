// Box-plane contacts (physics/engine/course/box_plane.h, Napier practical 6 and the
// rigid-body assessment, docs/references.md §4): a unit cube landing on the ground
// on a vertex, an edge and a face (1, 2, 4 contacts), touching, above, a wall and a
// tilted plane; and the averaged contact point.
//
// Notation. Unit cube: half extents 1/2. c = s = 1/sqrt2. Corners are numbered as in
// boxCorners (contact.h): bit j of k set means +h along body axis j, so 0 = ---,
// 1 = +--, 2 = -+-, 3 = ++-, 4 = --+, 5 = +-+, 6 = -++, 7 = +++.
//
// Tolerance. Positions and depths are exact numbers; the code forms them from cos/sin
// of pi/4 and sqrt3 rounded to doubles, in sums of a few terms of size <= 3, so the
// errors are a few 1e-16. 1e-12 absolute leaves ample headroom; the depths tested
// are >= 0.01, so any wrong corner or sign is off by far more. Rows built only from
// dyadic numbers (touching, above) are exact and compared with tolerance 0.

#include <QtTest>

#include "physics/engine/course/box_plane.h"
#include "tests/test_support.h"

#include <cmath>
#include <numbers>

Q_DECLARE_METATYPE(rbw::Vec3)
Q_DECLARE_METATYPE(rbw::BoxPose)
Q_DECLARE_METATYPE(rbw::PlaneDef)

namespace {

using rbw::BoxPose;
using rbw::ContactFeature;
using rbw::ContactGeometry;
using rbw::Mat3;
using rbw::PlaneDef;
using rbw::Vec3;

const double kPi = std::numbers::pi;
const double kSqrt2 = std::numbers::sqrt2;
const double kSqrt3 = std::numbers::sqrt3;

BoxPose unitCube(const Vec3& c, const Mat3& R = Mat3::Identity())
{
    BoxPose b;
    b.c_W = c;
    b.R_WB = R;
    b.halfExtents = Vec3::Constant(0.5);
    return b;
}

PlaneDef plane(const char* name, const Vec3& point, const Vec3& n)
{
    PlaneDef p;
    p.name = name;
    p.point_W = point;
    p.n_W = n;
    return p;
}

PlaneDef ground() { return plane("ground", Vec3::Zero(), Vec3::UnitY()); }

QString vecText(const Vec3& v)
{
    return QStringLiteral("(%1, %2, %3)").arg(v.x(), 0, 'g', 17).arg(v.y(), 0, 'g', 17).arg(v.z(), 0, 'g', 17);
}

bool near(const Vec3& a, const Vec3& b, double tol)
{
    return (a - b).cwiseAbs().maxCoeff() <= tol;
}

// R maps the body diagonal (-1,-1,-1)/sqrt3 to (0,-1,0): corner 0 hangs straight down.
Mat3 diagonalDown()
{
    return rbw::Quat::FromTwoVectors(Vec3(-1, -1, -1).normalized(), Vec3(0, -1, 0)).toRotationMatrix();
}

} // namespace

class TestBoxPlane : public QObject {
    Q_OBJECT

private slots:
    void corners_data();
    void corners();
    void appendsWithoutClearing();
    void averageOfFaceContactsIsFaceCentre();
    void averageOfEdgeContactsIsEdgeMidpoint();
    void averageTakesMaxDepth();
};

// ---------------------------------------------------------------------------------
// Which corners are contacts, where, how deep. Columns: the corners expected (their
// world positions, in corner order) and one depth shared by all of them.
void TestBoxPlane::corners_data()
{
    QTest::addColumn<BoxPose>("box");
    QTest::addColumn<PlaneDef>("plane");
    QTest::addColumn<QList<Vec3>>("points");
    QTest::addColumn<double>("depth");
    QTest::addColumn<double>("tol");

    // Vertex: the body diagonal vertical (diagonalDown), c = (1, sqrt3/2 - 0.01, -2).
    // Corner 0 is sqrt3/2 (half the diagonal sqrt3) straight below c: (1, -0.01, -2),
    // d = -0.01, depth 0.01. Its three neighbours differ by +1 along one body axis b_j,
    // whose height is b_j . y = 1/sqrt3 (R maps (1,1,1)/sqrt3 to y): y = -0.01 +
    // 0.577 > 0; the rest are higher still. One contact.
    QTest::newRow("vertex: 1 contact") << unitCube(Vec3(1.0, kSqrt3 / 2 - 0.01, -2.0), diagonalDown()) << ground()
                                       << QList<Vec3>{Vec3(1.0, -0.01, -2.0)} << 0.01 << 1e-12;

    // Edge: rotated 45 deg about z, b_0 = (c, s, 0), b_1 = (-s, c, 0). A corner's
    // height above c is 1/2 (+-s +-c): -sqrt2/2 for (-,-) (corners 0 and 4), 0 for
    // (+,-) and (-,+), +sqrt2/2 for (+,+). With c = (0, sqrt2/2 - 0.02, 0): corners 0
    // and 4 at c + 1/2 (-b_0 - b_1) -+ 1/2 z = (0, -0.02, -+0.5), depth 0.02; the
    // (+,-), (-,+) ones at y = 0.687. Two contacts.
    QTest::newRow("edge: 2 contacts") << unitCube(Vec3(0.0, kSqrt2 / 2 - 0.02, 0.0),
                                                  Eigen::AngleAxisd(kPi / 4, Vec3::UnitZ()).toRotationMatrix())
                                      << ground() << QList<Vec3>{Vec3(0, -0.02, -0.5), Vec3(0, -0.02, 0.5)} << 0.02
                                      << 1e-12;

    // Face: axis-aligned at c = (3, 0.48, 1). The four corners with body y = -1/2
    // (0, 1, 4, 5) are at y = -0.02: (3 -+ 0.5, -0.02, 1 -+ 0.5). Depth 0.02 (0.48 is
    // not dyadic: 0.48 - 0.5 carries a rounding of ~1e-17).
    QTest::newRow("face: 4 contacts")
        << unitCube(Vec3(3.0, 0.48, 1.0)) << ground()
        << QList<Vec3>{Vec3(2.5, -0.02, 0.5), Vec3(3.5, -0.02, 0.5), Vec3(2.5, -0.02, 1.5), Vec3(3.5, -0.02, 1.5)}
        << 0.02 << 1e-12;

    // Touching exactly: c_y = 0.5, the bottom corners at 0.5 - 0.5 = 0 exactly: d = 0
    // counts (as in SAT, touching is a contact of depth 0). Four contacts, depth 0.
    QTest::newRow("touching: 4 contacts of depth 0")
        << unitCube(Vec3(0.0, 0.5, 0.0)) << ground()
        << QList<Vec3>{Vec3(-0.5, 0, -0.5), Vec3(0.5, 0, -0.5), Vec3(-0.5, 0, 0.5), Vec3(0.5, 0, 0.5)} << 0.0 << 0.0;

    // Negative control: c_y = 0.5 + 2^-20, the lowest corners at y = 2^-20 > 0. None.
    QTest::newRow("above: none") << unitCube(Vec3(0.0, 0.5 + std::ldexp(1.0, -20), 0.0)) << ground() << QList<Vec3>{}
                                 << 0.0 << 0.0;

    // Negative control: far above, rotated. None.
    QTest::newRow("far above, on a vertex: none") << unitCube(Vec3(0.0, 5.0, 0.0), diagonalDown()) << ground()
                                                  << QList<Vec3>{} << 0.0 << 0.0;

    // A wall: the plane x = -2 with normal (1, 0, 0) (free side x > -2). The cube at
    // (-1.55, 1, 0) has its x = -2.05 face through it: corners with body x = -1/2
    // (0, 2, 4, 6), d = 1 * (-2.05 - (-2)) = -0.05, depth 0.05.
    QTest::newRow("wall: 4 contacts")
        << unitCube(Vec3(-1.55, 1.0, 0.0)) << plane("wall", Vec3(-2, 0, 0), Vec3::UnitX())
        << QList<Vec3>{Vec3(-2.05, 0.5, -0.5), Vec3(-2.05, 1.5, -0.5), Vec3(-2.05, 0.5, 0.5), Vec3(-2.05, 1.5, 0.5)}
        << 0.05 << 1e-12;

    // A tilted plane through the origin with n = (c, s, 0), and the cube turned 45 deg
    // about z so that b_0 = n: its -b_0 face is parallel to the plane. With c_box =
    // 0.47 n the face is at signed distance 0.47 - 0.5 = -0.03: corners 0, 2, 4, 6
    // (body x = -1/2), each c_box - 1/2 b_0 -+ 1/2 b_1 -+ 1/2 z = -0.03 n -+ 1/2 b_1
    // -+ 1/2 z, with b_1 = (-s, c, 0); depth 0.03.
    {
        const Vec3 n(1 / kSqrt2, 1 / kSqrt2, 0);
        const Vec3 b1(-1 / kSqrt2, 1 / kSqrt2, 0);
        const Vec3 z = Vec3::UnitZ();
        const Vec3 base = -0.03 * n;
        QTest::newRow("tilted plane: 4 contacts")
            << unitCube(0.47 * n, Eigen::AngleAxisd(kPi / 4, Vec3::UnitZ()).toRotationMatrix())
            << plane("slope", Vec3::Zero(), n)
            << QList<Vec3>{Vec3(base - 0.5 * b1 - 0.5 * z), Vec3(base + 0.5 * b1 - 0.5 * z),
                           Vec3(base - 0.5 * b1 + 0.5 * z), Vec3(base + 0.5 * b1 + 0.5 * z)}
            << 0.03 << 1e-12;
    }
}

void TestBoxPlane::corners()
{
    QFETCH(BoxPose, box);
    QFETCH(PlaneDef, plane);
    QFETCH(QList<Vec3>, points);
    QFETCH(double, depth);
    QFETCH(double, tol);

    std::vector<ContactGeometry> out;
    const int count = rbw::collideBoxPlane(box, plane, out);
    QCOMPARE(count, static_cast<int>(points.size()));
    QCOMPARE(static_cast<int>(out.size()), count);
    for (int k = 0; k < count; ++k) {
        const ContactGeometry& g = out[static_cast<size_t>(k)];
        QVERIFY2(near(g.p_W, points[k], tol),
                 qPrintable(QStringLiteral("contact %1 at %2, expected %3").arg(k).arg(vecText(g.p_W), vecText(points[k]))));
        RBW_COMPARE_NEAR(g.depth, depth, tol, QStringLiteral("contact %1's depth").arg(k));
        QVERIFY(g.depth >= 0.0);
        // n is the plane normal, which points from the plane (B) to the box (A).
        QVERIFY(g.n_W == plane.n_W);
        QVERIFY(g.n_W.dot(Vec3(box.c_W - plane.point_W)) > 0.0);
        QCOMPARE(static_cast<int>(g.feature), static_cast<int>(ContactFeature::VertexPlane));
    }
}

// collideBoxPlane appends: earlier contacts (e.g. another plane's) stay, and the
// return value counts only the new ones.
void TestBoxPlane::appendsWithoutClearing()
{
    std::vector<ContactGeometry> out(3);
    out[1].depth = 7.0;
    const int count = rbw::collideBoxPlane(unitCube(Vec3(3.0, 0.48, 1.0)), ground(), out);
    QCOMPARE(count, 4);
    QCOMPARE(static_cast<int>(out.size()), 7);
    QCOMPARE(out[1].depth, 7.0);
}

// The face landing's four contacts (3 -+ 0.5, -0.02, 1 -+ 0.5) average to the centre
// of the bottom face, (3, -0.02, 1): the +-0.5 cancel pairwise. The normal is the
// ground's, the depth 0.02.
void TestBoxPlane::averageOfFaceContactsIsFaceCentre()
{
    std::vector<ContactGeometry> out;
    QCOMPARE(rbw::collideBoxPlane(unitCube(Vec3(3.0, 0.48, 1.0)), ground(), out), 4);
    const ContactGeometry avg = rbw::averageContact(out, 0, 4);
    QVERIFY2(near(avg.p_W, Vec3(3.0, -0.02, 1.0), 1e-12), qPrintable(vecText(avg.p_W)));
    QVERIFY(avg.n_W == Vec3(0, 1, 0));
    RBW_COMPARE_NEAR(avg.depth, 0.02, 1e-12);
    QCOMPARE(static_cast<int>(avg.feature), static_cast<int>(ContactFeature::VertexPlane));
}

// The edge landing's two contacts (0, -0.02, -+0.5) average to the midpoint of the
// bottom edge, (0, -0.02, 0). They sit after two unrelated entries, so first = 2.
void TestBoxPlane::averageOfEdgeContactsIsEdgeMidpoint()
{
    std::vector<ContactGeometry> out(2);
    out[0].p_W = Vec3(100, 100, 100);
    out[1].p_W = Vec3(-100, 100, 100);
    const BoxPose cube =
        unitCube(Vec3(0.0, kSqrt2 / 2 - 0.02, 0.0), Eigen::AngleAxisd(kPi / 4, Vec3::UnitZ()).toRotationMatrix());
    QCOMPARE(rbw::collideBoxPlane(cube, ground(), out), 2);
    const ContactGeometry avg = rbw::averageContact(out, 2, 2);
    QVERIFY2(near(avg.p_W, Vec3(0.0, -0.02, 0.0), 1e-12), qPrintable(vecText(avg.p_W)));
    RBW_COMPARE_NEAR(avg.depth, 0.02, 1e-12);
}

// Unequal depths (a tilted landing): hand-made contacts at (0,-0.01,0), (1,-0.03,0),
// (0,-0.02,1) with depths 0.01, 0.03, 0.02. Mean point (1/3, -0.02, 1/3); depth the
// largest, 0.03; normal that of the first.
void TestBoxPlane::averageTakesMaxDepth()
{
    std::vector<ContactGeometry> cs(3);
    const double depths[3] = {0.01, 0.03, 0.02};
    const Vec3 points[3] = {Vec3(0, -0.01, 0), Vec3(1, -0.03, 0), Vec3(0, -0.02, 1)};
    for (int k = 0; k < 3; ++k) {
        cs[static_cast<size_t>(k)].p_W = points[k];
        cs[static_cast<size_t>(k)].n_W = Vec3::UnitY();
        cs[static_cast<size_t>(k)].depth = depths[k];
        cs[static_cast<size_t>(k)].feature = ContactFeature::VertexPlane;
    }
    const ContactGeometry avg = rbw::averageContact(cs, 0, 3);
    QVERIFY2(near(avg.p_W, Vec3(1.0 / 3.0, -0.02, 1.0 / 3.0), 1e-15), qPrintable(vecText(avg.p_W)));
    QCOMPARE(avg.depth, 0.03);
    QVERIFY(avg.n_W == Vec3(0, 1, 0));
}

QTEST_APPLESS_MAIN(TestBoxPlane)
#include "tst_box_plane.moc"
