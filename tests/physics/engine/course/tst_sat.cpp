// The box-box separating axis test (physics/engine/course/box_box_sat.h) on collisions:
// the course's reference case (docs/references.md §2), the TUM template's own
// testCheckCollision cases, and hand-built cases in which each class of axis wins, each
// with its axis, feature, depth, normal and point derived by hand and the winning axis
// checked by an independent projection. Notation, the independent check and the
// tolerances: sat_cases.h. The rows without a collision, the swap of A and B and the
// tie of equally rotated boxes are in tst_sat_symmetry.cpp.
#include "tests/physics/engine/course/sat_cases.h"

#include <QtTest>

using namespace sat_test;

class TestSat : public QObject {
    Q_OBJECT

private slots:
    void collision_data();
    void collision();
};

// ---------------------------------------------------------------------------------
// Collisions: axis, feature, depth, normal and point, each derived below.
void TestSat::collision_data()
{
    QTest::addColumn<BoxPose>("A");
    QTest::addColumn<BoxPose>("B");
    QTest::addColumn<int>("axis");
    QTest::addColumn<int>("feature");
    QTest::addColumn<double>("depth");
    QTest::addColumn<Vec3>("n");
    QTest::addColumn<Vec3>("p");
    QTest::addColumn<double>("tol");

    const int VF = static_cast<int>(ContactFeature::VertexFace);
    const int FV = static_cast<int>(ContactFeature::FaceVertex);
    const int EE = static_cast<int>(ContactFeature::EdgeEdge);

    // Reference case. Both boxes axis-aligned, so the faces are x, y, z for both and
    // a_i x b_j is 0 for i = j (skipped) and +-(the third axis) otherwise.
    //   x: A [-0.5, 0.5], B [0.4, 1.4]   -> overlap 0.5 - 0.4    = 0.1
    //   y: A [-0.5, 0.5], B [-0.3, 0.7]  -> overlap 0.5 + 0.3    = 0.8
    //   z: A [-0.5, 0.5], B [-0.4, 0.6]  -> overlap 0.5 + 0.4    = 0.9
    // B's faces and the edge axes repeat these values: only strictly smaller wins, so
    // axis 0 (a_0 = x) with depth 0.1. toCenter = (0.9, 0.2, 0.1), x . toCenter = 0.9
    // > 0: the axis stays +x, n = (-1, 0, 0). A face wins: the corner of B with the
    // smallest corner . toCenter = 0.9 x + 0.2 y + 0.1 z is (-,-,-) = (0.4, -0.3, -0.4).
    QTest::newRow("reference: A face") << refA() << refB() << 0 << VF << 0.1 << Vec3(-1, 0, 0)
                                       << Vec3(0.4, -0.3, -0.4) << 1e-12;

    // Touching exactly: B at (1, 0.2, 0.1). x: A [-0.5, 0.5], B [0.5, 1.5] -> overlap
    // 0.5 - 0.5 = 0 (all numbers dyadic: exact). Touching counts: a collision of depth
    // 0 on axis 0, n = (-1, 0, 0), point (-,-,-) of B = (0.5, -0.3, -0.4).
    QTest::newRow("touching exactly on a face") << refA() << unitCube(Vec3(1.0, 0.2, 0.1)) << 0 << VF << 0.0
                                                << Vec3(-1, 0, 0) << Vec3(0.5, -0.3, -0.4) << 0.0;

    // Template case 1: unit cubes at (1,1,1) and (2,2,2) touch at one corner: the
    // overlap is 1.5 - 1.5 = 0 on every axis, so axis 0 wins (first), n = (-1, 0, 0)
    // as toCenter = (1, 1, 1). B's corner with the smallest x + y + z is (-,-,-) =
    // (1.5, 1.5, 1.5). The template prints exactly this: normal (-1, -0, -0), point
    // (1.5, 1.5, 1.5).
    QTest::newRow("template case 1: corners touch") << unitCube(Vec3(1, 1, 1)) << unitCube(Vec3(2, 2, 2)) << 0 << VF
                                                    << 0.0 << Vec3(-1, 0, 0) << Vec3(1.5, 1.5, 1.5) << 0.0;

    // B face, d = 0.1 (see bFaceB). c_B = (1/2 + 0.9c, 1/2 + 0.9s, 0).
    //   b_0 = (c, s, 0): A's radius 0.5 (c + s) = sqrt2/2; c_A . b_0 = 0, so A is
    //     [-sqrt2/2, sqrt2/2]; c_B . b_0 = c + 0.9 = sqrt2/2 + 0.9, B's radius 1, so
    //     B is [sqrt2/2 - 0.1, ...]: overlap 0.1.
    //   a_0 = x: B's radius (|c| + |s|) * 1 = sqrt2, c_B.x = 0.5 + 0.9c = 1.1364; B's
    //     min x = 1.1364 - 1.4142 = -0.2778; overlap 0.5 + 0.2778 = 0.7778 (a_1 same).
    //   a_2 = b_2 = z: A [-0.5, 0.5] inside B [-1, 1]: overlap 1.
    //   b_1 = (-s, c, 0): c_B . b_1 = 0, A [-sqrt2/2, sqrt2/2] inside B [-1, 1]: sqrt2.
    //   Edge axes: a_2 x b_2 = 0 (skipped); a_0 x b_0, a_0 x b_1, a_1 x b_0, a_1 x b_1
    //     are +-z (1); a_0 x b_2 = -y, a_1 x b_2 = x (0.7778); a_2 x b_0 = b_1 (sqrt2);
    //     a_2 x b_1 = (0,0,1) x (-s, c, 0) = (-c, -s, 0) = -b_0: overlap 0.1 again, a
    //     tie, and an exact one: its components are those of b_0 negated, normalised
    //     by the same norm, so the projections are exact negatives. Ties go to the
    //     earlier axis: axis 3 (b_0), depth 0.1.
    // toCenter = c_B has b_0 . c_B > 0: the axis stays b_0, n = -b_0 = (-c, -s, 0).
    // B face wins: A's corner with the smallest corner . (-toCenter), i.e. the largest
    // x + y: (+,+,-) = (0.5, 0.5, -0.5) and (+,+,+) tie; the first in the order
    // ---, +--, -+-, ++-, ... is ++- = (0.5, 0.5, -0.5).
    QTest::newRow("B face: A's corner in B's rotated face")
        << bFaceA() << bFaceB(0.1) << 3 << FV << 0.1 << Vec3(-1 / kSqrt2, -1 / kSqrt2, 0) << Vec3(0.5, 0.5, -0.5)
        << 1e-12;

    // Edge pair, d = 0.1 (see edgeA/edgeB). a = (x, (0,c,s), (0,-s,c)), b = ((c,s,0),
    // (-s,c,0), z).
    //   a_0 x b_2 = x cross z = (0, -1, 0): A's y-extent is sqrt2/2 (its top edge), B's
    //     bottom edge is at sqrt2 - 0.1 - sqrt2/2: overlap 0.1.
    //   a_1 = (0, c, s): A [-0.5, 0.5]; B's radius 0.5 (|b_0.a_1| + |b_1.a_1| +
    //     |b_2.a_1|) = 0.5 (1/2 + 1/2 + s) = 0.5 + sqrt2/4, c_B . a_1 = (sqrt2 - 0.1) c
    //     = 1 - 0.1c. Overlap 0.5 - (1 - 0.1c - 0.5 - sqrt2/4) = sqrt2/4 + 0.1c =
    //     0.4243. a_2, b_0, b_1 give the same by symmetry; a_0, b_2: 1.
    //   The other edge axes: a_0 x b_0, a_0 x b_1 are +-z (1); a_1 x b_2 = x (1);
    //     a_2 x b_2 = -x (1); the four a_{1,2} x b_{0,1} = (+-1, +-1, +-1)/sqrt3 give
    //     0.635 (checked independently below).
    // So axis 6 + 3*0 + 2 = 8 with depth 0.1. toCenter = (0, sqrt2 - 0.1, 0): the axis
    // flips to (0, 1, 0), n = (0, -1, 0) (B is above A).
    // Edge points (template rule, oriented axis y): A: coordinate 0 = 0; a_1 . y = c
    // > 0 -> +h; a_2 . y = -s < 0 -> -h: p_A = 0.5 a_1 - 0.5 a_2 = (0, sqrt2/2, 0).
    // B: coordinate 2 = 0; b_0 . y = s > 0 -> -h; b_1 . y = c > 0 -> -h: p_B = c_B -
    // 0.5 (b_0 + b_1) = (0, sqrt2/2 - 0.1, 0). The lines (x and z through these points)
    // are perpendicular, denom = 1; closest points at mua = mub = 0 (in range): the
    // midpoint (0, sqrt2/2 - 0.05, 0).
    QTest::newRow("edge pair: 45 deg about x vs 45 deg about z")
        << edgeA() << edgeB(0.1) << 8 << EE << 0.1 << Vec3(0, -1, 0) << Vec3(0, kSqrt2 / 2 - 0.05, 0) << 1e-12;

    // Vertex-face, d = 0.05 (see slabA/vertexB). Each b_j has b_j . y = 1/sqrt3 (R maps
    // the diagonal (1,1,1)/sqrt3 to y), so B's y-radius is 0.5 * 3/sqrt3 = sqrt3/2 and
    // B's y-extent starts at 0.5 + sqrt3/2 - 0.05 - sqrt3/2 = 0.45: overlap on a_1 = y
    // is 0.5 - 0.45 = 0.05. Every other axis overlaps by at least 1: on a_0, a_2 and
    // on each b_j the cube's projection (length >= 1) lies inside A's, and the edge
    // axes likewise (checked independently below). Axis 1, depth 0.05; toCenter =
    // (0, 0.5 + sqrt3/2 - 0.05, 0): y stays, n = (0, -1, 0). A face wins: B's corner
    // with the smallest y, the bottom corner (0, 0.45, 0) (the next ones are
    // 1/sqrt3 higher).
    QTest::newRow("A face: B on its vertex on A's top face")
        << slabA() << vertexB(0.05) << 1 << VF << 0.05 << Vec3(0, -1, 0) << Vec3(0, 0.45, 0) << 1e-12;

    // The vertex-face point is picked along toCenter, not along the face normal, so
    // it need not be the deepest corner (the usual wording "the corner of B deepest
    // towards A" is only approximately the rule; docs/references.md §2). A: the
    // slab. B: a unit cube turned -10 deg about z, R(x, y) = (x co + y si, -x si +
    // y co), co = cos 10, si = sin 10, at c_B = (1.5, y_B, 0). B's bottom corners in
    // the xy-plane, relative to c_B:
    //   (-,-): (-(co + si)/2, (si - co)/2) = (-0.5792, -0.4056)
    //   (+,-): ((co - si)/2, -(co + si)/2) = ( 0.4056, -0.5792)   <- the lowest
    // With y_B = 0.5 + (co + si)/2 - 0.05 the (+,-) corners are 0.05 inside A, the
    // (-,-) ones at y = 0.45 + si = 0.6236, 0.1236 ABOVE A's face. Overlaps: a_1 = y:
    // 0.05; a_0 x b_2 = x cross z = -y: the same numbers negated (exact tie, axis 1
    // keeps it). b_1 = R(0, 1) = (si, co, 0), and a_2 x b_0 = z x (co, -si, 0) = b_1:
    // A's radius 2 si + co/2 = 0.8397 about 0, B's 1/2 about c_B . b_1 = 1.5 si + y_B co
    // = 1.2741: overlap 0.8397 - 0.7741 = 0.0656. Every other axis >= 1 (B's
    // projection inside A's; checked independently). So axis 1, depth
    // 0.05, n = (0, -1, 0) (toCenter.y > 0). The point minimises corner . toCenter,
    // toCenter = (1.5, y_B, 0) = (1.5, 1.0292, 0):
    //   (-,-): 1.5 * -0.5792 + 1.0292 * -0.4056 = -1.2862
    //   (+,-): 1.5 *  0.4056 + 1.0292 * -0.5792 = +0.0123
    // (the top corners are larger still), so (-,-,-) (z = -1/2 ties with +1/2; the
    // first in order wins): (1.5 - (co + si)/2, 0.45 + si, -0.5), a corner that does
    // not touch A at all. The template does the same.
    {
        const double co = std::cos(kPi / 18);
        const double si = std::sin(kPi / 18);
        const BoxPose tilted = unitCube(Vec3(1.5, 0.5 + (co + si) / 2 - 0.05, 0.0), rotation(-kPi / 18, Vec3::UnitZ()));
        QTest::newRow("A face: point along toCenter, not the deepest corner")
            << slabA() << tilted << 1 << VF << 0.05 << Vec3(0, -1, 0) << Vec3(1.5 - (co + si) / 2, 0.45 + si, -0.5)
            << 1e-12;
    }

    // Rotated boxes: the same two configurations moved rigidly by Q (0.7 rad about
    // (1,2,2)/3). Projections are invariant under a common rotation (Q u . Q x = u . x)
    // and so is every rule (corner order is per body, sign tests use dot products),
    // so axis, feature and depth stay, and n, p rotate: n = Q n0, p = Q p0. The
    // winners above have margins >= 0.3, far from any rounding tie.
    QTest::newRow("rotated: vertex-face under Q")
        << rotated(Q(), slabA()) << rotated(Q(), vertexB(0.05)) << 1 << VF << 0.05 << Vec3(Q() * Vec3(0, -1, 0))
        << Vec3(Q() * Vec3(0, 0.45, 0)) << 1e-12;
    QTest::newRow("rotated: edge pair under Q")
        << rotated(Q(), edgeA()) << rotated(Q(), edgeB(0.1)) << 8 << EE << 0.1 << Vec3(Q() * Vec3(0, -1, 0))
        << Vec3(Q() * Vec3(0, kSqrt2 / 2 - 0.05, 0)) << 1e-12;

    // Template case 2 (see case2A/case2B), with B's size the exact 4 sqrt2 and A sunk
    // by 1e-9 so the result does not hang on the rounding of an exact touch (see
    // noCollision for the literal 5.656854). B is a square of half side 2 sqrt2 turned
    // 45 deg: a diamond with corners at distance 2 sqrt2 * sqrt2 = 4 on +-x, +-y; its
    // top corner edge is at y = 4, z in [-1, 1]. A spans x [-4.3, 4.7], y [4 - 1e-9,
    // 6 - 1e-9], z [-0.5, 2.5].
    //   a_0 = x: B [-4, 4] inside A: 8.   a_1 = y: 4 - (4 - 1e-9) = 1e-9.
    //   a_2 = z: min(2.5, 1) - max(-0.5, -1) = 1.5.
    //   b_0 = (c, s, 0): A's centre 5.2c (less 1e-9 c), radius 4.5c + 1c = 5.5c: A
    //     [-0.3c, 10.7c]; B [-2 sqrt2, 2 sqrt2] = [-4c, 4c]: overlap 4.3c = 3.04.
    //   b_1 = (-s, c, 0): A's centre 4.8c, A [-0.7c, 10.3c]: overlap 4.7c = 3.32.
    //   b_2 = z: 1.5.   Edge axes: a_0 x b_2 = (0, -1, 0): 1e-9 again (a tie: the
    //     same numbers negated, exactly; the earlier axis 1 keeps it); the others are
    //     z (1.5), x (8) or b_0, b_1 (3.04, 3.32); a_2 x b_2 = 0 is skipped.
    // Axis 1, depth 1e-9. toCenter = c_B - c_A = (-0.2, -5 + 1e-9, -1): y . toCenter
    // < 0, the axis flips to -y, n = (0, 1, 0). A face wins: B's corner with the
    // smallest -0.2x - 5y - z: the top corners (0, 4, +-1) give -20 -+ 1, so (0, 4, 1).
    // The template prints normal (0, 1, 0), point (0, 4, 1): the same.
    QTest::newRow("template case 2, sunk by 1e-9")
        << case2A(1e-9) << case2B(4.0 * kSqrt2) << 1 << VF << 1e-9 << Vec3(0, 1, 0) << Vec3(0, 4, 1) << 1e-12;

    // Template case 3 (see case3A/case3B). A is a diamond in plan with half side
    // 1.4145: its corners lie 1.4145 sqrt2 = 2.000405 from (-2, 0) along +-x, +-y, so
    // its right corner edge is at x = 0.000405084 (= 1.4145 sqrt2 - 2), z in [0, 2]. B
    // turned 90 deg: b_0 = (0, 1, 0) (half 4.5), b_1 = (-1, 0, 0) (half 1), b_2 = z
    // (half 2): B spans x [0, 2], y [-4, 5], z [-2, 2].
    //   b_1 = -x: on -x, A spans [-0.000405, 4.000405] and B [-2, 0]: overlap
    //     0.000405 = 1.4145 sqrt2 - 2.
    //   a_0 = (c, s, 0): A's radius 1.4145, c_A . a_0 = -2c: A [-2c - 1.4145, -2c +
    //     1.4145]; B's radius 4.5s + 1c = 5.5c, c_B . a_0 = 1.5c: B [-4c, 7c]: overlap
    //     -2c + 1.4145 + 4c = 2.8287. a_1 = (-s, c, 0): similarly 2.829. a_2 = b_2 = z:
    //     A [0, 2] inside B [-2, 2]: 2. b_0 = y: A [-2.0004, 2.0004], B [-4, 5]: 4.0008.
    //   Edge axes: a_2 x b_0 = z x y = -x = b_1 exactly (both (-1, 6e-17, 0) from the
    //     same cos 90, sin 90): a tie, exact, kept by the earlier axis 4; the others
    //     are +-z (2), b_0 (4.0008) or A's face directions (2.83).
    // Axis 4, depth 0.000405084. toCenter = (3, 0.5, -1): b_1 . toCenter = -3 < 0, the
    // axis flips to +x, n = (-1, 0, 0). B face wins: A's corner with the smallest
    // corner . (-3, -0.5, 1): the right corner at z = 0, (+,-,-) = c_A + 1.4145 (a_0 -
    // a_1) - a_2 = (1.4145 sqrt2 - 2, 0, 0) (value -0.0012; its z = 2 twin gives
    // +1.9988, all other corners >= 4.9998). The template prints normal (-1, 0, -0),
    // point (0.000405, 0, 0): the same to its 6 decimals.
    const double case3Depth = 1.4145 * kSqrt2 - 2.0;
    QTest::newRow("template case 3: both rotated, B face")
        << case3A() << case3B() << 4 << FV << case3Depth << Vec3(-1, 0, 0) << Vec3(case3Depth, 0, 0) << 1e-12;

    // Parallel-edge fallback, d = 0.02, phi = 0.5 deg (see fallbackA/fallbackB). With
    // R_y(phi) (x, y, z) = (x cos phi + z sin phi, y, -x sin phi + z cos phi):
    //   b_0 = (cos phi, 0, -sin phi), b_1 = (s sin phi, c, s cos phi),
    //   b_2 = (c sin phi, -s, c cos phi).
    //   a_0 x b_0 = (0, sin phi, 0): axis 6 is y. A's top edge is at sqrt2/2, B's
    //     bottom edge (horizontal; R_y keeps y) at sqrt2 - d - sqrt2/2: overlap d.
    //   a_1 = (0, c, s): B's radius LB |b_0.a_1| + 0.5 |b_1.a_1| + 0.5 |b_2.a_1| =
    //     LB s sin phi + 0.5 (c^2 + s^2 cos phi) + 0.5 sc (1 - cos phi) = LB s sin phi
    //     + 0.5; c_B . a_1 = (sqrt2 - d) c = 1 - dc: overlap 0.5 - (1 - dc - LB s
    //     sin phi - 0.5) = dc + LB s sin phi; a_2 the same (mirror).
    //   b_1, b_2: by the same algebra with the roles swapped, dc + LA s sin phi.
    //   With d = 0.02: dc = 0.014142, s sin phi = 0.0061706. The other edge axes lie
    //   within phi of the face normals, with overlaps between the two values
    //   (0.0265 ... 0.0296, checked independently below); a_0, b_0: about 2 LA, 2 LB.
    // Axis 6 wins with depth 0.02 < 0.0265. toCenter = (0, sqrt2 - d, 0): y stays,
    // n = (0, -1, 0). Edge points (as in the edge-pair row; R_y(phi) keeps the signs):
    // p_A = (0, sqrt2/2, 0), p_B = c_B + 0.5 (-b_1 + b_2) = (0, sqrt2/2 - d, 0) (the x
    // and z parts cancel since c = s). contactPoint: denom = 1 - (a_0 . b_0)^2 =
    // sin^2 phi = 7.6e-5 < 1e-4: parallel, so the point is p_A if bestSingleAxis else
    // p_B. bestSingleAxis is true iff one of B's faces became the running minimum:
    //   LA = 2, LB = 2.5: A's faces 0.029569, B's 0.026483 < that: true -> p_A.
    //   LA = 2.5, LB = 2: A's faces 0.026483, B's 0.029569 never below: false -> p_B.
    QTest::newRow("edge pair, parallel fallback, B face was the running minimum")
        << fallbackA(2.0) << fallbackB(2.5, 0.02) << 6 << EE << 0.02 << Vec3(0, -1, 0) << Vec3(0, kSqrt2 / 2, 0)
        << 1e-12;
    QTest::newRow("edge pair, parallel fallback, A face stayed the running minimum")
        << fallbackA(2.5) << fallbackB(2.0, 0.02) << 6 << EE << 0.02 << Vec3(0, -1, 0)
        << Vec3(0, kSqrt2 / 2 - 0.02, 0) << 1e-12;

    // The reference case with A and B swapped: A at (0.9, 0.2, 0.1), B at the origin.
    // The overlaps are the same, axis 0 (x) with 0.1; toCenter = (-0.9, -0.2, -0.1),
    // x . toCenter < 0: the axis flips to -x, n = (1, 0, 0), opposite to the reference
    // row's n. B's corner with the smallest -0.9x - 0.2y - 0.1z: (+,+,+) = (0.5, 0.5,
    // 0.5) (a different point: the vertex-face rule picks a corner of the other box).
    QTest::newRow("reference swapped: n flips") << refB() << refA() << 0 << VF << 0.1 << Vec3(1, 0, 0)
                                                << Vec3(0.5, 0.5, 0.5) << 1e-12;
}

void TestSat::collision()
{
    QFETCH(BoxPose, A);
    QFETCH(BoxPose, B);
    QFETCH(int, axis);
    QFETCH(int, feature);
    QFETCH(double, depth);
    QFETCH(Vec3, n);
    QFETCH(Vec3, p);
    QFETCH(double, tol);

    const std::optional<ContactGeometry> hit = rbw::collideBoxBoxSAT(A, B);
    QVERIFY2(hit.has_value(), "expected a collision");
    QCOMPARE(hit->axis, axis);
    QCOMPARE(static_cast<int>(hit->feature), feature);
    RBW_COMPARE_NEAR(hit->depth, depth, tol);
    QVERIFY2(hit->depth >= 0.0, "depth must not be negative");
    QVERIFY2(near(hit->n_W, n, tol), qPrintable(QStringLiteral("n %1, expected %2").arg(vecText(hit->n_W), vecText(n))));
    QVERIFY2(near(hit->p_W, p, tol), qPrintable(QStringLiteral("p %1, expected %2").arg(vecText(hit->p_W), vecText(p))));
    // n is a unit vector and points from B to A: n . (c_A - c_B) > 0.
    RBW_COMPARE_NEAR(hit->n_W.norm(), 1.0, 1e-12);
    const Vec3 BtoA = A.c_W - B.c_W;
    QVERIFY2(hit->n_W.dot(BtoA) > 0.0, "n must point from B to A");

    // The hand claim "this axis wins", checked by the independent projection.
    QString overlaps;
    double minOverlap = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 15; ++k) {
        const double o = independentOverlap(A, B, k);
        overlaps += QStringLiteral(" %1:%2").arg(k).arg(o, 0, 'g', 6);
        minOverlap = std::min(minOverlap, o);
    }
    const double own = independentOverlap(A, B, axis);
    RBW_COMPARE_NEAR(own, depth, std::max(tol, 1e-12), overlaps);
    QVERIFY2(own <= minOverlap + 1e-12, qPrintable(QStringLiteral("not the smallest:") + overlaps));
    for (int k = 0; k < axis; ++k) {
        QVERIFY2(independentOverlap(A, B, k) > own + 1e-12,
                 qPrintable(QStringLiteral("an earlier axis %1 ties or wins:").arg(k) + overlaps));
    }
}

QTEST_APPLESS_MAIN(TestSat)
#include "tst_sat.moc"
