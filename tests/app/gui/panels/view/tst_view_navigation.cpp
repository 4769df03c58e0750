// The 3D view's navigation aids under Xvfb (issue 20): keys 1-3 switch to the front,
// top and side views and frame the bodies, hovering names the body under the mouse
// and N names them all, and the world axes and grid are drawn in a floating scene.
//
// Set RBW_VIEW_PNG_DIR to a folder to keep the rendered images (view_<name>.png).
#include "app/scene/scene_loader.h"
#include "app/gui/panels/view/scene_view.h"
#include "physics/engine/world.h"
#include "tests/test_support.h"
#include "tests/app/gui/panels/view/view_test_support.h"

#include <QAction>
#include <QVector3D>
#include <QtTest>

#include <cmath>
#include <memory>

using namespace rbw;

namespace {

using rbw::test::lessonScene;

using rbw::test::Stepped;
using rbw::test::stepLesson;
using rbw::test::showView;

QPoint pixelOf(const QPointF& p) { return QPoint(int(std::floor(p.x())), int(std::floor(p.y()))); }

void savePng(const QImage& img, const QString& name)
{
    const QString dir = qEnvironmentVariable("RBW_VIEW_PNG_DIR");
    if (!dir.isEmpty()) img.save(dir + "/view_" + name + ".png");
}

} // namespace

class TestViewNavigation : public QObject {
    Q_OBJECT
private slots:
    void keysSwitchStandardViews_data();
    void keysSwitchStandardViews();
    void hoverNamesTheBody();
    void worldReferenceIsDrawn();
};

void TestViewNavigation::keysSwitchStandardViews_data()
{
    // Keys 1-3 (orbit_camera.h, StandardView): where the eye is, and which world
    // direction appears to the right of and above the origin on screen.
    QTest::addColumn<int>("key");
    QTest::addColumn<QVector3D>("eyeDir");
    QTest::addColumn<QVector3D>("right");
    QTest::addColumn<QVector3D>("up");
    QTest::newRow("1 front, from +z") << int(Qt::Key_1) << QVector3D(0, 0, 1) << QVector3D(1, 0, 0) << QVector3D(0, 1, 0);
    QTest::newRow("2 top, from +y") << int(Qt::Key_2) << QVector3D(0, 1, 0) << QVector3D(1, 0, 0) << QVector3D(0, 0, -1);
    QTest::newRow("3 side, from +x") << int(Qt::Key_3) << QVector3D(1, 0, 0) << QVector3D(0, 0, -1) << QVector3D(0, 1, 0);
}

void TestViewNavigation::keysSwitchStandardViews()
{
    QFETCH(int, key);
    QFETCH(QVector3D, eyeDir);
    QFETCH(QVector3D, right);
    QFETCH(QVector3D, up);
    auto v3 = [](const QVector3D& q) { return Vec3(q.x(), q.y(), q.z()); };
    const Stepped s = stepLesson("01-one-step", 0);
    SceneView view;
    showView(view);
    view.setSnapshot(s.snapshot());
    view.orbitBy(37, -21);   // away from every standard view
    view.setFocus();
    QTest::keyClick(&view, Qt::Key(key));
    // The eye sits on the axis, seen from its + side, and the view frames the box (the
    // target is the box's centre).
    const Vec3 toEye = (view.camera().eye() - view.camera().target()).normalized();
    QVERIFY2((toEye - v3(eyeDir)).norm() < 1e-9, qPrintable(QString("eye direction (%1, %2, %3)").arg(toEye.x()).arg(toEye.y()).arg(toEye.z())));
    const Vec3 c = view.camera().target();
    // A point one metre to the world's `right` appears to the right of the target
    // on screen, at the same height; one metre `up` appears above it (smaller y).
    const QPointF o = view.projectToWidget(c);
    const QPointF r = view.projectToWidget(c + v3(right));
    const QPointF u = view.projectToWidget(c + v3(up));
    QVERIFY(r.x() > o.x() + 10);
    QVERIFY(std::abs(r.y() - o.y()) < 1e-6);
    QVERIFY(u.y() < o.y() - 10);
    QVERIFY(std::abs(u.x() - o.x()) < 1e-6);
    // The box fits the view: its centre is the widget's centre and its corners are on screen.
    QVERIFY(std::abs(o.x() - 320) < 1e-6 && std::abs(o.y() - 240) < 1e-6);
    for (int k = 0; k < 8; ++k) {
        const Vec3 corner = s.snapshot().bodies[0].x_W +
                            0.5 * Vec3((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1).cwiseProduct(s.snapshot().bodies[0].size);
        QVERIFY(view.rect().contains(pixelOf(view.projectToWidget(corner))));
    }
    // The View-menu actions carry the same keys.
    bool found = false;
    for (QAction* a : view.viewActions()) found = found || a->shortcut() == QKeySequence(key);
    QVERIFY(found);
}

void TestViewNavigation::hoverNamesTheBody()
{
    // Lesson 7: four bodies "particle", "rigid", "elastic-1", "elastic-0.7" over a ground.
    const Stepped s = stepLesson("07-bounce", 0);
    const ViewSnapshot snap = s.snapshot();
    SceneView view;
    showView(view);
    view.setSnapshot(snap);
    QTest::keyClick(&view, Qt::Key_1);   // front view: no body hides another
    view.grabFramebuffer();
    for (int b = 0; b < int(snap.bodies.size()); ++b) {
        QTest::mouseMove(&view, pixelOf(view.projectToWidget(snap.bodies[b].x_W)));
        QCOMPARE(view.hoveredBody(), b);
    }
    QCOMPARE(snap.bodies[0].name, std::string("particle"));
    // Over the sky (top left corner, above everything in the front view): no body.
    QTest::mouseMove(&view, QPoint(3, 3));
    QCOMPARE(view.hoveredBody(), -1);
    // The name is written on the image: hovering changes pixels near the body.
    QTest::mouseMove(&view, pixelOf(view.projectToWidget(snap.bodies[3].x_W)));
    const QImage named = view.grabFramebuffer();
    QTest::mouseMove(&view, QPoint(3, 3));
    const QImage plain = view.grabFramebuffer();
    QVERIFY(named != plain);
    // N writes every name; a second N hides them again.
    QVERIFY(!view.bodyNamesVisible());
    QTest::keyClick(&view, Qt::Key_N);
    QVERIFY(view.bodyNamesVisible());
    QVERIFY(view.grabFramebuffer() != plain);
    QTest::keyClick(&view, Qt::Key_N);
    QVERIFY(!view.bodyNamesVisible());
}

void TestViewNavigation::worldReferenceIsDrawn()
{
    // Lesson 2 floats (no gravity, no plane): the world axes and the grid are drawn
    // all the same, the grid under the box (its bottom is at y = -0.3).
    const Stepped s = stepLesson("02-single-body", 0);
    SceneView view;
    showView(view);
    view.setSnapshot(s.snapshot());
    const QImage img = view.grabFramebuffer();
    savePng(img, "02_world_reference");
    const view::WorldReference& w = view.worldReference();
    QVERIFY(w.shown);
    QVERIFY(w.lineCount > 4);
    QVERIFY(w.y0 <= -0.3);
    int worldLabels = 0;
    int bodyLabels = 0;
    for (const view::SceneLabel& l : view.labels()) {
        (l.kind == view::SceneLabel::Kind::WorldAxis ? worldLabels : bodyLabels)++;
    }
    QCOMPARE(worldLabels, 3);
    QCOMPARE(bodyLabels, 3);
    // In the front view the world x label lies right of the origin and y above it.
    QTest::keyClick(&view, Qt::Key_1);
    view.grabFramebuffer();
    const QPointF o = view.projectToWidget(Vec3::Zero());
    for (const view::SceneLabel& l : view.labels()) {
        if (l.kind != view::SceneLabel::Kind::WorldAxis) continue;
        const QPointF p = view.projectToWidget(l.at_W);
        if (l.axis == 0) QVERIFY(p.x() > o.x() + 10);
        if (l.axis == 1) QVERIFY(p.y() < o.y() - 10);
    }
}

QTEST_MAIN(TestViewNavigation)
#include "tst_view_navigation.moc"
