// The view's world reference and camera presets, without GL (issue 20): the
// standard views (front from +z, top from +y, side from +x) project known points
// where the convention in orbit_camera.h says, the ground grid lies under the bodies
// with a 1-2-5 spacing, the world axes are labelled at their tips, and the body
// axes reach beyond the faces.
#include "app/gui/panels/view/frame_geometry.h"
#include "app/gui/panels/view/orbit_camera.h"
#include "app/gui/panels/view/view_snapshot.h"
#include "tests/test_support.h"

#include <QtTest>

#include <cmath>

using namespace rbw;

// Vec3 columns in the data tables (QtGui's QVector3D is not registered in a GUI-less test).
Q_DECLARE_METATYPE(rbw::Vec3)

namespace {

bool near(const Vec3& a, const Vec3& b, double tol) { return (a - b).cwiseAbs().maxCoeff() <= tol; }

QString text(const Vec3& v) { return QStringLiteral("(%1, %2, %3)").arg(v.x(), 0, 'g', 17).arg(v.y(), 0, 'g', 17).arg(v.z(), 0, 'g', 17); }

Mat3 rotationZ(double degrees)
{
    return Eigen::AngleAxisd(degrees * M_PI / 180.0, Vec3::UnitZ()).toRotationMatrix();
}

} // namespace

class TestWorldReference : public QObject {
    Q_OBJECT
private slots:
    void standardViews_data();
    void standardViews();
    void niceGridSpacing_data();
    void niceGridSpacing();
    void worldReferenceUnderTheBodies_data();
    void worldReferenceUnderTheBodies();
    void bodyAxesReachBeyondTheFaces();
    void gridOnTheBottomOfARoundedBox();
};

void TestWorldReference::standardViews_data()
{
    // Where known points land in ndc for each standard view, camera at distance d = 5
    // from the origin, aspect 1. A point at view coordinates (X, Y, -d) projects to
    // ndc (f X / d, f Y / d) with f = cot(fovY / 2) = cot(20°).
    //   Front: seen from +z, right +x, up +y:  (1,0,0) -> (f/5, 0), (0,1,0) -> (0, f/5)
    //   Top:   seen from +y, right +x, up -z:  (1,0,0) -> (f/5, 0), (0,0,-1) -> (0, f/5)
    //   Side:  seen from +x, right -z, up +y:  (0,0,-1) -> (f/5, 0), (0,1,0) -> (0, f/5)
    QTest::addColumn<int>("view");
    QTest::addColumn<Vec3>("rightPointQ");   // expected at (f/5, 0)
    QTest::addColumn<Vec3>("upPointQ");      // expected at (0, f/5)
    QTest::addColumn<Vec3>("eyeDirQ");       // the unit vector from the target to the eye
    QTest::newRow("front (from +z)") << int(StandardView::Front) << Vec3(1, 0, 0) << Vec3(0, 1, 0) << Vec3(0, 0, 1);
    QTest::newRow("top (from +y)") << int(StandardView::Top) << Vec3(1, 0, 0) << Vec3(0, 0, -1) << Vec3(0, 1, 0);
    QTest::newRow("side (from +x)") << int(StandardView::Side) << Vec3(0, 0, -1) << Vec3(0, 1, 0) << Vec3(1, 0, 0);
}

void TestWorldReference::standardViews()
{
    QFETCH(int, view);
    QFETCH(Vec3, rightPointQ);
    QFETCH(Vec3, upPointQ);
    QFETCH(Vec3, eyeDirQ);
    const Vec3 rightPoint = Vec3(rightPointQ);
    const Vec3 upPoint = Vec3(upPointQ);
    const Vec3 eyeDir = Vec3(eyeDirQ);
    OrbitCamera cam;
    cam.setAngles(-123, 45);   // anything else first: the view sets both angles
    cam.setDistance(5);
    cam.setStandardView(static_cast<StandardView>(view));
    QVERIFY2(near(cam.eye(), 5.0 * eyeDir, 1e-12), qPrintable(text(cam.eye())));
    const double f = 1.0 / std::tan(20 * M_PI / 180);
    auto ndc = [&](const Vec3& p) {
        const Eigen::Vector4d clip = cam.projectionMatrix(1.0) * cam.viewMatrix() * Eigen::Vector4d(p.x(), p.y(), p.z(), 1);
        return Eigen::Vector2d(clip.x() / clip.w(), clip.y() / clip.w());
    };
    RBW_COMPARE_NEAR_STRICT(ndc(rightPoint).x(), f / 5, 1e-12);
    RBW_COMPARE_NEAR_STRICT(ndc(rightPoint).y(), 0.0, 1e-12);
    RBW_COMPARE_NEAR_STRICT(ndc(upPoint).x(), 0.0, 1e-12);
    RBW_COMPARE_NEAR_STRICT(ndc(upPoint).y(), f / 5, 1e-12);
    // Negative control: the opposite points land on the opposite sides.
    QVERIFY(ndc(-rightPoint).x() < -0.5 * f / 5);
    QVERIFY(ndc(-upPoint).y() < -0.5 * f / 5);
    // The camera axes stay orthonormal, also at the pole (the top view).
    RBW_COMPARE_NEAR_STRICT(cam.right().dot(cam.up()), 0.0, 1e-12);
    RBW_COMPARE_NEAR_STRICT(cam.right().dot(cam.forward()), 0.0, 1e-12);
    RBW_COMPARE_NEAR_STRICT(cam.up().norm(), 1.0, 1e-12);
}

void TestWorldReference::niceGridSpacing_data()
{
    // extent / 10 rounded up to 1, 2 or 5 times a power of ten.
    QTest::addColumn<double>("extent");
    QTest::addColumn<double>("spacing");
    QTest::newRow("7 m -> 0.7 -> 1") << 7.0 << 1.0;
    QTest::newRow("3 m -> 0.3 -> 0.5") << 3.0 << 0.5;
    QTest::newRow("12 m -> 1.2 -> 2") << 12.0 << 2.0;
    QTest::newRow("10 m -> 1 exactly") << 10.0 << 1.0;
    QTest::newRow("0.05 m -> 0.005") << 0.05 << 0.005;
    QTest::newRow("60 m -> 6 -> 10") << 60.0 << 10.0;
    QTest::newRow("zero -> 1") << 0.0 << 1.0;
}

void TestWorldReference::niceGridSpacing()
{
    QFETCH(double, extent);
    QFETCH(double, spacing);
    RBW_COMPARE_NEAR_STRICT(view::niceGridSpacing(extent), spacing, 1e-12 * spacing);
}

void TestWorldReference::worldReferenceUnderTheBodies_data()
{
    // A 1 m cube. At the origin it reaches y = -0.5, so the grid lies on the first
    // grid line at or below -0.5 (within one spacing); raised to y = 2 (bottom at
    // y = 1.5) the grid lies at y = 0.
    QTest::addColumn<Vec3>("xQ");
    QTest::addColumn<bool>("below");   // grid below y = 0
    QTest::newRow("cube at the origin") << Vec3(0, 0, 0) << true;
    QTest::newRow("cube above the floor") << Vec3(3, 2, -1) << false;
}

void TestWorldReference::worldReferenceUnderTheBodies()
{
    QFETCH(Vec3, xQ);
    const Vec3 x = Vec3(xQ);
    QFETCH(bool, below);
    ViewSnapshot s;
    ViewSnapshot::Body b;
    b.name = "particle";
    b.x_W = x;
    s.bodies.push_back(b);
    const view::FrameGeometry g = view::buildFrameGeometry(s, {}, view::FrameOptions{});
    QVERIFY(g.world.shown);
    // The grid never cuts the cube: y0 <= the cube's lowest point, and within one spacing of it (or 0).
    QVERIFY(g.world.y0 <= x.y() - 0.5 + 1e-12);
    if (below) {
        QVERIFY(g.world.y0 > x.y() - 0.5 - g.world.spacing - 1e-12);
        // y0 is a whole number of spacings.
        RBW_COMPARE_NEAR_STRICT(g.world.y0 / g.world.spacing, std::round(g.world.y0 / g.world.spacing), 1e-9);
    } else {
        QCOMPARE(g.world.y0, 0.0);
    }
    // The grid spans the cube's and the origin's x and z.
    QVERIFY(g.world.min_W.x() <= std::min(0.0, x.x() - 0.5) && g.world.max_W.x() >= std::max(0.0, x.x() + 0.5));
    QVERIFY(g.world.min_W.z() <= std::min(0.0, x.z() - 0.5) && g.world.max_W.z() >= std::max(0.0, x.z() + 0.5));
    QVERIFY(g.world.lineCount > 4);
    // Its lines are in the line list, on y = y0.
    int onGrid = 0;
    for (const view::LineVertex& v : g.lines) {
        if (v.c[0] == view::kGrid.r && v.c[1] == view::kGrid.g && std::abs(v.p[1] - g.world.y0) < 1e-6) ++onGrid;
    }
    QCOMPARE(onGrid, 2 * g.world.lineCount);
    // The world axes: labels x, y, z just beyond the tips on the world axes.
    int worldLabels = 0;
    for (const view::SceneLabel& l : g.labels) {
        if (l.kind != view::SceneLabel::Kind::WorldAxis) continue;
        ++worldLabels;
        QCOMPARE(QString::fromStdString(l.text), QString("xyz").mid(l.axis, 1));
        QVERIFY(near(l.at_W.normalized(), Vec3::Unit(l.axis), 1e-12));
        QVERIFY(l.at_W.norm() > g.world.axisLength);
    }
    QCOMPARE(worldLabels, 3);
    // Negative control: switched off, no grid and no world labels.
    view::FrameOptions off;
    off.worldReference = false;
    const view::FrameGeometry g0 = view::buildFrameGeometry(s, {}, off);
    QVERIFY(!g0.world.shown);
    for (const view::SceneLabel& l : g0.labels) QVERIFY(l.kind != view::SceneLabel::Kind::WorldAxis);
}

void TestWorldReference::bodyAxesReachBeyondTheFaces()
{
    // A 2 x 6 x 2 box (lesson 7's) turned 30° about z: each body-axis label sits
    // outside the box, on its own body axis, beyond the face by more than
    // kBodyAxisPoke times the longest edge (6 m): |local_j| > a_j / 2 + 0.35 * 6.
    ViewSnapshot s;
    ViewSnapshot::Body b;
    b.name = "template";
    b.size = Vec3(2, 6, 2);
    b.x_W = Vec3(1, 4, 0);
    b.R_WB = rotationZ(30);
    s.bodies.push_back(b);
    const view::FrameGeometry g = view::buildFrameGeometry(s, {}, view::FrameOptions{});
    int bodyLabels = 0;
    for (const view::SceneLabel& l : g.labels) {
        if (l.kind != view::SceneLabel::Kind::BodyAxis) continue;
        ++bodyLabels;
        const Vec3 local = b.R_WB.transpose() * (l.at_W - b.x_W);
        QVERIFY2(local[l.axis] > 0.5 * b.size[l.axis] + view::kBodyAxisPoke * 6.0, qPrintable(text(local)));
        RBW_COMPARE_NEAR_STRICT(local[(l.axis + 1) % 3], 0.0, 1e-12);
        RBW_COMPARE_NEAR_STRICT(local[(l.axis + 2) % 3], 0.0, 1e-12);
        QCOMPARE(QString::fromStdString(l.text), QString("xyz").mid(l.axis, 1) + "_B");
    }
    QCOMPARE(bodyLabels, 3);
    // Many bodies (more than kMaxLabelledBodies): no body-axis labels (their names show on hover).
    for (int k = 0; k < view::kMaxLabelledBodies; ++k) s.bodies.push_back(b);
    const view::FrameGeometry many = view::buildFrameGeometry(s, {}, view::FrameOptions{});
    for (const view::SceneLabel& l : many.labels) QVERIFY(l.kind != view::SceneLabel::Kind::BodyAxis);
}

void TestWorldReference::gridOnTheBottomOfARoundedBox()
{
    // A 1 m cube whose centre is at y = -1e-16 (round-off, as a pose from a quaternion
    // has): its bottom is -0.5 - 1e-16, which is -0.5000000000000001 in doubles. The
    // area spans 1 m, so the spacing is 1/10 = 0.1 m, and the grid lies on the line
    // y = -5 * 0.1 = -0.5, not a cell lower at -0.6.
    ViewSnapshot s;
    ViewSnapshot::Body b;
    b.x_W = Vec3(0, -1e-16, 0);
    s.bodies.push_back(b);
    QVERIFY(view::bodyBounds(s).min_W.y() < -0.5);   // the round-off is there
    const view::FrameGeometry g = view::buildFrameGeometry(s, {}, view::FrameOptions{});
    RBW_COMPARE_NEAR_STRICT(g.world.spacing, 0.1, 1e-15);
    RBW_COMPARE_NEAR_STRICT(g.world.y0, -0.5, 1e-12);
}

QTEST_GUILESS_MAIN(TestWorldReference)
#include "tst_world_reference.moc"
