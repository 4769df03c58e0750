// The 3D view's geometry, without GL: the snapshot built from a world and its trace
// (lessons 1 and 3 against their hand derivations), the ray casts used for picking,
// the plane patches and the orbit camera.
#include "app/scene/scene_loader.h"
#include "app/gui/panels/view/frame_geometry.h"
#include "app/gui/panels/view/orbit_camera.h"
#include "app/gui/panels/view/plane_patch.h"
#include "app/gui/panels/view/ray_pick.h"
#include "app/gui/panels/view/view_snapshot.h"
#include "physics/engine/quantities.h"
#include "physics/engine/world.h"
#include "tests/test_support.h"

#include <QtTest>

#include <cmath>
#include <limits>

using namespace rbw;

namespace {

using rbw::test::lessonScene;   // a lesson's scene from the source tree (tests/test_support.h)

bool near(const Vec3& a, const Vec3& b, double tol) { return (a - b).cwiseAbs().maxCoeff() <= tol; }

QString text(const Vec3& v) { return QStringLiteral("(%1, %2, %3)").arg(v.x(), 0, 'g', 17).arg(v.y(), 0, 'g', 17).arg(v.z(), 0, 'g', 17); }

Mat3 rotationZ(double degrees)
{
    return Eigen::AngleAxisd(degrees * M_PI / 180.0, Vec3::UnitZ()).toRotationMatrix();
}

// Polygon area by the shoelace formula on its (u, v) coordinates in a plane with unit normal n:
// A = 1/2 |sum_k (p_k x p_{k+1}) . n|.
double area(const std::vector<Vec3>& polygon, const Vec3& n)
{
    Vec3 sum = Vec3::Zero();
    for (size_t k = 0; k < polygon.size(); ++k) sum += polygon[k].cross(polygon[(k + 1) % polygon.size()]);
    return 0.5 * std::abs(sum.dot(n));
}

} // namespace

class TestViewGeometry : public QObject {
    Q_OBJECT
private slots:
    void lesson1ForceArrowIsTheTracesForce();
    void lesson1WithoutTraceHasProbesButNoArrows();
    void lesson3ContactAtItsCollisionStep();
    void lesson4GravityArrowsAtTheCentres();
    void impulseArrowsAreTheTracesImpulses();
    void manifoldPointsAreDrawnWithBothImpulses();
    void stateArrowsAreTheState();
    void badTraceEntriesAreSkipped();
    void rayBoxHit_data();
    void rayBoxHit();
    void pickTakesTheNearestBody();
    void rayPlaneHit();
    void planePatchOfLesson4Room();
    void cameraProjectsTargetToCentre();
    void cameraRayRoundTrip();
    void arrowScaleLongestIsOneBox();
    void lesson5TorqueIsDrawnAtTheCentre();
    void lesson7BoxesOutgrowTheirGravity();
};

void TestViewGeometry::lesson1ForceArrowIsTheTracesForce()
{
    // Table 2.1: f = (1, 1, 0) at p = (0.3, 0.5, 0.25), one step h = 2, no gravity.
    World w(lessonScene("01-one-step/scene.json"));
    StepTrace t;
    QVERIFY(w.step(&t).ok);
    const ViewSnapshot s = makeViewSnapshot(w, &t);

    QVERIFY(s.hasTrace);
    QCOMPARE(s.step, 0L);
    QCOMPARE(int(s.bodies.size()), 1);
    // x stays at the origin after the first explicit Euler step (old v = 0); R = Rz(90 deg).
    QVERIFY(near(s.bodies[0].x_W, Vec3::Zero(), 0.0));
    QVERIFY((s.bodies[0].R_WB - rotationZ(90)).cwiseAbs().maxCoeff() < 1e-12);
    QVERIFY(near(s.bodies[0].size, Vec3(1, 0.6, 0.5), 0.0));

    QCOMPARE(int(s.forces.size()), 1);   // the one applied force; g = 0, so no gravity arrow
    const ViewSnapshot::Force& f = s.forces[0];
    QCOMPARE(int(f.kind), int(ViewSnapshot::ForceKind::Applied));
    QCOMPARE(f.body, 0);
    QCOMPARE(f.index, 0);
    // Exactly the trace's numbers (the view copies, it does not recompute).
    const TraceEntry* fTrace = t.find("applied_force", 0, 0);
    const TraceEntry* pTrace = t.find("application_point", 0, 0);
    QVERIFY(fTrace && pTrace);
    QVERIFY(f.f_W == std::get<Vec3>(fTrace->value));
    QVERIFY(f.origin_W == std::get<Vec3>(pTrace->value));
    // ... which are the scene file's f and p.
    QVERIFY(near(f.f_W, Vec3(1, 1, 0), 0.0));
    QVERIFY(near(f.origin_W, Vec3(0.3, 0.5, 0.25), 0.0));

    // The probes come from the trace: v_p of (-0.3, -0.5, -0.25) = (-1.111861, 0.929412, 2.675410)
    // (docs/references.md §1, Table 2.1).
    QCOMPARE(int(s.probes.size()), 2);
    QVERIFY(near(s.probes[0].p_W, Vec3(-0.3, -0.5, -0.25), 1e-12));
    QVERIFY2(near(s.probes[0].v_W, Vec3(-1.111861, 0.929412, 2.675410), 1e-6), qPrintable(text(s.probes[0].v_W)));
    QVERIFY2(near(s.probes[1].v_W, Vec3(3.111861, 1.070588, -2.675410), 1e-6), qPrintable(text(s.probes[1].v_W)));
    QVERIFY(s.contacts.empty());   // lesson 1 has no collision stage
}

void TestViewGeometry::lesson1WithoutTraceHasProbesButNoArrows()
{
    // Before the first step: no trace; the force of step 0 is drawn before the step
    // that applies it, as the scene defines it (f = (1, 1, 0) N at p = (0.3, 0.5,
    // 0.25) m, lessons/01-one-step/scene.json); the probes come from World::probe()
    // at rest, p = p0 and v_p = 0.
    World w(lessonScene("01-one-step/scene.json"));
    const ViewSnapshot s = makeViewSnapshot(w, nullptr);
    QVERIFY(!s.hasTrace);
    QCOMPARE(s.nextStep, 0L);
    QCOMPARE(int(s.forces.size()), 1);
    QVERIFY(s.forces[0].upcoming);
    QVERIFY(s.forces[0].f_W == w.scene().forces[0].f_W);
    QVERIFY(near(s.forces[0].f_W, Vec3(1, 1, 0), 0.0));
    QVERIFY(near(s.forces[0].origin_W, Vec3(0.3, 0.5, 0.25), 0.0));
    // After the step the force acted and does not act again: it is the trace's, done.
    StepTrace t;
    QVERIFY(w.step(&t).ok);
    const ViewSnapshot after = makeViewSnapshot(w, &t);
    QCOMPARE(int(after.forces.size()), 1);
    QVERIFY(!after.forces[0].upcoming);
    QVERIFY(after.forces[0].f_W == std::get<Vec3>(t.find("applied_force", 0, 0)->value));
    QVERIFY(s.contacts.empty());
    QCOMPARE(int(s.probes.size()), 2);
    QVERIFY(near(s.probes[1].p_W, Vec3(0.3, 0.5, 0.25), 1e-12));
    QVERIFY(near(s.probes[1].v_W, Vec3::Zero(), 0.0));
}

void TestViewGeometry::lesson3ContactAtItsCollisionStep()
{
    // lessons/03-two-box-collision/lesson.md (and tst_collision_lessons): the boxes
    // close at 2 m/s across a 0.05 m gap, so step k = 2 has the one contact:
    // p = (1.02, 0.5, 0), n = (-1, 0, 0), J = 4 / (1/2 + 1 + 3/16) = 64/27.
    World w(lessonScene("03-two-box-collision/scene.json"));
    StepTrace t;
    for (int k = 0; k < 2; ++k) {
        QVERIFY(w.step(&t).ok);
        // Negative control: no contact in the trace, none in the snapshot.
        QVERIFY(makeViewSnapshot(w, &t).contacts.empty());
    }
    QVERIFY(w.step(&t).ok);
    QCOMPARE(int(t.contacts.size()), 1);
    const ViewSnapshot s = makeViewSnapshot(w, &t);
    QCOMPARE(int(s.contacts.size()), 1);
    const ViewSnapshot::Contact& c = s.contacts[0];
    QCOMPARE(c.bodyA, 0);
    QCOMPARE(c.bodyB, 1);
    QCOMPARE(c.plane, -1);
    QVERIFY(!c.separating);
    QVERIFY(c.p_W == std::get<Vec3>(t.find("point", 0, 0)->value));
    QVERIFY(c.n_W == std::get<Vec3>(t.find("normal", 0, 0)->value));
    QVERIFY(near(c.p_W, Vec3(1.02, 0.5, 0), 1e-12));
    QVERIFY(near(c.n_W, Vec3(-1, 0, 0), 1e-15));
    RBW_COMPARE_NEAR_STRICT(c.J, 64.0 / 27, 1e-12);
    // The impulse on A: J n = (-64/27, 0, 0).
    QVERIFY2(near(c.impulse_W, Vec3(-64.0 / 27, 0, 0), 1e-12), qPrintable(text(c.impulse_W)));
}

void TestViewGeometry::lesson4GravityArrowsAtTheCentres()
{
    // Lesson 4: six movable boxes under g = (0, -9.81, 0); each gets M g at its x.
    World w(lessonScene("04-many-boxes/scene.json"));
    StepTrace t;
    QVERIFY(w.step(&t).ok);
    const ViewSnapshot s = makeViewSnapshot(w, &t);
    QCOMPARE(int(s.planes.size()), 5);
    QCOMPARE(int(s.forces.size()), 6);
    for (const ViewSnapshot::Force& f : s.forces) {
        QCOMPARE(int(f.kind), int(ViewSnapshot::ForceKind::Gravity));
        const double M = w.scene().bodies[f.body].mass;
        QVERIFY(near(f.f_W, Vec3(0, -9.81 * M, 0), 1e-12));
        QVERIFY(f.origin_W == w.states()[f.body].x_W);
    }
}

// Lesson 7's friction box (c 0.6, mu 0.5 against the ground): at its first contact
// with an impulse, the view's arrows are the trace's numbers. J n is the trace's J
// times its n; the friction impulse J_t t is the trace's row; the total is their
// sum, which is what impulse.cpp applies to A, so M_A times the trace's Δv_A gives it
// back (to round-off). Each arrow ends at p, is scaled like the others of its unit,
// and the normal starts at p and points into A.
void TestViewGeometry::impulseArrowsAreTheTracesImpulses()
{
    World w(lessonScene("07-bounce/scene.json"));
    int frictionBody = -1;
    for (int b = 0; b < int(w.scene().bodies.size()); ++b) {
        if (w.scene().bodies[b].name == "friction") frictionBody = b;
    }
    QVERIFY(frictionBody >= 0);
    StepTrace t;
    int contact = -1;
    for (int k = 0; k < 3000 && contact < 0; ++k) {
        QVERIFY(w.step(&t).ok);
        for (int c = 0; c < int(t.contacts.size()); ++c) {
            const TraceEntry* f = t.find("friction_impulse", frictionBody, c);
            if (f != nullptr && std::get<Vec3>(f->value).norm() > 0.0 && !t.contacts[c].separating) contact = c;
        }
    }
    QVERIFY2(contact >= 0, "the friction box never slid on the ground");
    const ViewSnapshot s = makeViewSnapshot(w, &t);
    const ViewSnapshot::Contact* c = nullptr;
    for (const ViewSnapshot::Contact& x : s.contacts) {
        if (x.index == contact) c = &x;
    }
    QVERIFY(c != nullptr);
    QCOMPARE(c->bodyA, frictionBody);
    const double J = std::get<double>(t.find("impulse", frictionBody, contact)->value);
    const Vec3 n = std::get<Vec3>(t.find("normal", frictionBody, contact)->value);
    const Vec3 Jt = std::get<Vec3>(t.find("friction_impulse", frictionBody, contact)->value);
    const Vec3 dv = std::get<Vec3>(t.find("delta_v_a", frictionBody, contact)->value);
    QVERIFY(c->hasFriction);
    QVERIFY(c->J == J);
    QVERIFY(c->impulse_W == Vec3(J * n));
    QVERIFY(c->friction_W == Jt);
    QVERIFY(c->total_W == Vec3(J * n + Jt));
    // Independent: what A's velocity changed by in this contact, times M_A.
    const double M = w.scene().bodies[frictionBody].mass;
    RBW_COMPARE_NEAR(M * dv, c->total_W, 1e-12 * c->total_W.norm());
    // Negative control: the normal impulse alone is not what was applied.
    QVERIFY((M * dv - c->impulse_W).norm() > 1e-6 * c->total_W.norm());

    const view::FrameGeometry g = view::buildFrameGeometry(s, {}, view::FrameOptions{});
    const double scale = view::arrowScale(g.scales.maxImpulse, g.scales.refLength);
    int seen = 0;
    for (const view::ArrowRecord& a : g.arrows) {
        if (a.index != contact || a.body != frictionBody) continue;
        switch (a.kind) {
        case view::ArrowKind::NormalImpulse:
            QVERIFY(a.value == c->impulse_W);
            break;
        case view::ArrowKind::FrictionImpulse:
            QVERIFY(a.value == c->friction_W);
            break;
        case view::ArrowKind::TotalImpulse:
            QVERIFY(a.value == c->total_W);
            break;
        case view::ArrowKind::Normal:
            QVERIFY(a.from_W == c->p_W);
            QVERIFY((a.to_W - a.from_W).normalized().dot(n) > 1.0 - 1e-12);
            ++seen;
            continue;
        default:
            continue;
        }
        ++seen;
        QVERIFY(a.to_W == c->p_W);   // the impulse ends at the contact point
        QVERIFY(near(a.to_W - a.from_W, scale * a.value, 1e-12 * g.scales.refLength));
    }
    QCOMPARE(seen, 4);   // n, J n, J_t t and their sum
}

// Lesson 11 (contact_model "manifold"): every manifold point of the step is drawn, with
// the solver's accumulated impulses. Independent check: the solver hands each body the
// sum of its points' impulses as a load, F_c = P / h (manifold_contact_stage.cpp), with
// P = sum over the points where the body is A of (lambda_n n + lambda_t) minus the same
// sum where it is B. So sum(total_W) over a body's points must be F_c h.
void TestViewGeometry::manifoldPointsAreDrawnWithBothImpulses()
{
    World w(lessonScene("11-resting-contact/scene.json"));
    StepTrace t;
    // Step 10 (t = 0.17 s): the slider slides (friction), the stack rests on the
    // ground and on itself, nothing sleeps yet.
    for (int k = 0; k <= 10; ++k) QVERIFY(w.step(&t).ok);
    const ViewSnapshot s = makeViewSnapshot(w, &t);
    const TraceEntry* count = t.find(q::manifold_points.id, -1, -1);
    QVERIFY(count != nullptr);
    QCOMPARE(int(s.contacts.size()), int(std::get<double>(count->value)));
    QVERIFY(s.contacts.size() >= 12);   // 4 corners of each box on the ground or on another box

    const double h = w.scene().dt;
    int boxBox = 0;
    int checked = 0;
    for (int b = 0; b < int(w.scene().bodies.size()); ++b) {
        const TraceEntry* F = t.find(q::contact_force.id, b, -1);
        if (F == nullptr) continue;
        Vec3 P = Vec3::Zero();
        Vec3 Pn = Vec3::Zero();
        for (const ViewSnapshot::Contact& c : s.contacts) {
            // Each drawn point is the trace's point, with its n, lambda_n and lambda_t.
            const TraceEntry* p = t.find(q::manifold_point.id, c.bodyA, c.index);
            const TraceEntry* n = t.find(q::manifold_normal.id, c.bodyA, c.index);
            const TraceEntry* ln = t.find(q::normal_impulse.id, c.bodyA, c.index);
            const TraceEntry* lt = t.find(q::tangent_impulse.id, c.bodyA, c.index);
            QVERIFY2(p != nullptr && n != nullptr && ln != nullptr && lt != nullptr,
                     qPrintable(QStringLiteral("contact %1 of body %2").arg(c.index).arg(c.bodyA)));
            QVERIFY(c.p_W == std::get<Vec3>(p->value));
            QVERIFY(c.n_W == std::get<Vec3>(n->value));
            QVERIFY(c.J == std::get<double>(ln->value));
            QVERIFY(c.friction_W == std::get<Vec3>(lt->value));
            QVERIFY(c.total_W == Vec3(c.J * c.n_W + c.friction_W));
            const double sign = c.bodyA == b ? 1.0 : (c.bodyB == b ? -1.0 : 0.0);
            P += sign * c.total_W;
            Pn += sign * c.impulse_W;
            if (sign != 0.0 && c.bodyB >= 0) ++boxBox;
        }
        const Vec3 expected = h * std::get<Vec3>(F->value);
        RBW_COMPARE_NEAR(P, expected, 1e-12 * expected.norm());
        if (w.scene().bodies[b].name == "slider") {
            // Negative control: the sliding box's friction impulse is part of what was applied.
            QVERIFY((Pn - expected).norm() > 1e-3 * expected.norm());
        }
        ++checked;
    }
    QVERIFY(checked >= 4);   // the slider and the three boxes of the stack
    QVERIFY(boxBox > 0);     // and the stack's box-box points among them

    // Each point is drawn as n, J n, the friction impulse and their sum, like a course contact.
    const view::FrameGeometry g = view::buildFrameGeometry(s, {}, view::FrameOptions{});
    int normals = 0;
    for (const view::ArrowRecord& a : g.arrows) normals += a.kind == view::ArrowKind::Normal ? 1 : 0;
    QCOMPARE(normals, int(s.contacts.size()));
}

// The v, ω and L arrows are the world's state at each body's centre, drawn only when
// asked for (View menu), and each kind's longest is one reference length.
void TestViewGeometry::stateArrowsAreTheState()
{
    World w(lessonScene("05-spinning/scene.json"));
    StepTrace t;
    for (int k = 0; k < 10; ++k) QVERIFY(w.step(&t).ok);
    const ViewSnapshot s = makeViewSnapshot(w, &t);
    view::FrameOptions off;
    for (const view::ArrowRecord& a : view::buildFrameGeometry(s, {}, off).arrows) {
        QVERIFY(a.kind != view::ArrowKind::Velocity && a.kind != view::ArrowKind::AngularVelocity &&
                a.kind != view::ArrowKind::AngularMomentum);
    }
    view::FrameOptions on;
    on.velocity = on.angularVelocity = on.angularMomentum = true;
    const view::FrameGeometry g = view::buildFrameGeometry(s, {}, on);
    int omegaArrows = 0;
    double longest = 0.0;
    for (const view::ArrowRecord& a : g.arrows) {
        if (a.kind != view::ArrowKind::AngularVelocity && a.kind != view::ArrowKind::AngularMomentum) continue;
        const BodyState& st = w.states()[a.body];
        QVERIFY(a.from_W == st.x_W);
        QVERIFY(a.value == (a.kind == view::ArrowKind::AngularVelocity ? st.omega_W : st.L_W));
        if (a.kind == view::ArrowKind::AngularVelocity) {
            ++omegaArrows;
            longest = std::max(longest, (a.to_W - a.from_W).norm());
        }
    }
    QCOMPARE(omegaArrows, 2);   // both cubes spin (lessons/05-spinning)
    RBW_COMPARE_NEAR(longest, g.scales.refLength, 1e-12 * g.scales.refLength);
}

void TestViewGeometry::badTraceEntriesAreSkipped()
{
    // A hand-made trace: a NaN force, a force on a body that does not exist, a
    // force without its point, and a contact whose header is missing. None of them
    // may reach the view; the one good force does.
    World w(lessonScene("01-one-step/scene.json"));
    StepTrace t;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    t.add(q::applied_force, 0, Vec3(nan, 0, 0), 0);
    t.add(q::application_point, 0, Vec3(0, 0, 0), 0);
    t.add(q::applied_force, 7, Vec3(1, 0, 0), 0);
    t.add(q::application_point, 7, Vec3(0, 0, 0), 0);
    t.add(q::applied_force, 0, Vec3(0, 2, 0), 1);   // no point for force 1
    t.add(q::applied_force, 0, Vec3(0, 0, 3), 2);
    t.add(q::application_point, 0, Vec3(1, 0, 0), 2);
    t.add(q::contact_point, 0, Vec3(0, 0, 0), 0);   // no ContactHeader 0
    t.add(q::probe_position, 0, Vec3(nan, 0, 0), 0);
    t.add(q::point_velocity, 0, Vec3(0, 0, 0), 0);
    const ViewSnapshot s = makeViewSnapshot(w, &t);
    // The scene's own force of step 0 (upcoming: the world has not stepped) and the
    // one good trace force.
    QCOMPARE(int(s.forces.size()), 2);
    QVERIFY(s.forces[0].upcoming);
    QVERIFY(!s.forces[1].upcoming);
    QCOMPARE(s.forces[1].index, 2);
    QVERIFY(near(s.forces[1].f_W, Vec3(0, 0, 3), 0.0));
    QVERIFY(s.contacts.empty());
    for (const ViewSnapshot::Probe& p : s.probes) QVERIFY(isFinite(p.p_W) && isFinite(p.v_W));
    QCOMPARE(int(s.probes.size()), 0);   // probe 0 had a NaN position, probe 1 nothing
}

void TestViewGeometry::rayBoxHit_data()
{
    QTest::addColumn<Vec3>("origin");
    QTest::addColumn<Vec3>("dir");
    QTest::addColumn<double>("rotZDegrees");
    QTest::addColumn<bool>("hits");
    QTest::addColumn<double>("expectedT");
    // Unit cube at the origin (h = 0.5).
    // From (0,0,5) straight down -z: enters the face z = 0.5 at t = 5 - 0.5 = 4.5.
    QTest::newRow("axis-aligned face") << Vec3(0, 0, 5) << Vec3(0, 0, -1) << 0.0 << true << 4.5;
    // Turned 45 deg about z, a corner points along +x at distance sqrt(2)/2: t = 5 - 0.70710678.
    QTest::newRow("45 deg, edge first") << Vec3(5, 0, 0) << Vec3(-1, 0, 0) << 45.0 << true << 5.0 - std::sqrt(0.5);
    // Inside the box the ray starts at t = 0.
    QTest::newRow("from inside") << Vec3(0.1, 0.2, 0.3) << Vec3(1, 0, 0) << 0.0 << true << 0.0;
    // The turned cube is |x + y| <= sqrt(2)/2, |y - x| <= sqrt(2)/2 (times 1/sqrt(2): h = 0.5).
    // At y = 0.6 the ray enters where x + 0.6 = sqrt(2)/2, x = 0.10711: t = 5 - 0.10711.
    // Negative controls: at y = 0.8 > sqrt(2)/2 the turned cube is missed; at y = 0.6 > 0.5
    // the unturned one is.
    QTest::newRow("45 deg, above the corner: miss") << Vec3(5, 0.8, 0) << Vec3(-1, 0, 0) << 45.0 << false << 0.0;
    QTest::newRow("45 deg, y = 0.6: hit") << Vec3(5, 0.6, 0) << Vec3(-1, 0, 0) << 45.0 << true << 5.0 - (std::sqrt(0.5) - 0.6);
    QTest::newRow("unturned, y = 0.6: miss") << Vec3(5, 0.6, 0) << Vec3(-1, 0, 0) << 0.0 << false << 0.0;
    QTest::newRow("pointing away: miss") << Vec3(0, 0, 5) << Vec3(0, 0, 1) << 0.0 << false << 0.0;
}

void TestViewGeometry::rayBoxHit()
{
    QFETCH(Vec3, origin);
    QFETCH(Vec3, dir);
    QFETCH(double, rotZDegrees);
    QFETCH(bool, hits);
    QFETCH(double, expectedT);
    const std::optional<double> t = rbw::rayBoxHit(Ray{origin, dir.normalized()}, Vec3::Zero(), rotationZ(rotZDegrees),
                                                   Vec3::Constant(0.5));
    QCOMPARE(t.has_value(), hits);
    if (hits) RBW_COMPARE_NEAR_STRICT(*t, expectedT, 1e-12);
}

void TestViewGeometry::pickTakesTheNearestBody()
{
    // Two unit cubes on the z axis at z = 0 and z = 2; a ray from z = 10 down -z hits
    // body 1 first (t = 10 - 2.5 = 7.5) at (0, 0, 2.5).
    ViewSnapshot s;
    s.bodies.resize(2);
    s.bodies[0].x_W = Vec3(0, 0, 0);
    s.bodies[1].x_W = Vec3(0, 0, 2);
    const std::optional<BoxHit> hit = pickBody(Ray{Vec3(0, 0, 10), Vec3(0, 0, -1)}, s);
    QVERIFY(hit);
    QCOMPARE(hit->body, 1);
    QVERIFY(near(hit->hit_W, Vec3(0, 0, 2.5), 1e-12));
    // A non-finite body is not pickable: then body 0 is hit at z = 0.5.
    s.bodies[1].finite = false;
    const std::optional<BoxHit> hit0 = pickBody(Ray{Vec3(0, 0, 10), Vec3(0, 0, -1)}, s);
    QVERIFY(hit0);
    QCOMPARE(hit0->body, 0);
    QVERIFY(!pickBody(Ray{Vec3(3, 0, 10), Vec3(0, 0, -1)}, s));   // beside both: nothing
}

void TestViewGeometry::rayPlaneHit()
{
    // Ray from (0, 5, 0) down -y meets the ground y = 0 at t = 5; upwards it never does.
    const std::optional<double> t = rbw::rayPlaneHit(Ray{Vec3(0, 5, 0), Vec3(0, -1, 0)}, Vec3::Zero(), Vec3::UnitY());
    QVERIFY(t);
    QCOMPARE(*t, 5.0);
    QVERIFY(!rbw::rayPlaneHit(Ray{Vec3(0, 5, 0), Vec3(0, 1, 0)}, Vec3::Zero(), Vec3::UnitY()));
    QVERIFY(!rbw::rayPlaneHit(Ray{Vec3(0, 5, 0), Vec3(1, 0, 0)}, Vec3::Zero(), Vec3::UnitY()));
}

void TestViewGeometry::planePatchOfLesson4Room()
{
    // Lesson 4: ground y = 0 and walls x = -3, x = 3, z = -3, z = 3 facing inwards.
    // In a box [-10, 10]^3 the ground patch is the square [-3, 3]^2 (area 36) and
    // each wall the rectangle 6 wide from y = 0 to y = 10 (area 60).
    const SceneDef scene = lessonScene("04-many-boxes/scene.json");
    std::vector<ViewSnapshot::Plane> planes;
    for (const PlaneDef& p : scene.planes) planes.push_back({p.name, p.point_W, p.n_W});
    const Vec3 lo = Vec3::Constant(-10);
    const Vec3 hi = Vec3::Constant(10);
    const std::vector<Vec3> ground = view::planePatch(planes, 0, lo, hi);
    QVERIFY(ground.size() >= 4);
    RBW_COMPARE_NEAR_STRICT(area(ground, Vec3::UnitY()), 36.0, 1e-9);
    for (const Vec3& p : ground) {
        RBW_COMPARE_NEAR_STRICT(p.y(), 0.0, 1e-12);
        QVERIFY(std::abs(p.x()) <= 3 + 1e-12 && std::abs(p.z()) <= 3 + 1e-12);   // inside the box
    }
    const std::vector<Vec3> west = view::planePatch(planes, 1, lo, hi);
    RBW_COMPARE_NEAR_STRICT(area(west, Vec3::UnitX()), 60.0, 1e-9);
    // Negative control: a box entirely below the ground leaves no wall at all.
    QVERIFY(view::planePatch(planes, 1, Vec3::Constant(-10), Vec3(10, -1, 10)).empty());
}

void TestViewGeometry::cameraProjectsTargetToCentre()
{
    // The target lies on the optical axis: P V [target; 1] has x = y = 0 in ndc, and
    // the eye is `distance` away from it.
    OrbitCamera cam;
    cam.setTarget(Vec3(1, 2, 3));
    cam.setDistance(7);
    cam.setAngles(30, 20);
    const Eigen::Vector4d clip = cam.projectionMatrix(1.5) * cam.viewMatrix() * Eigen::Vector4d(1, 2, 3, 1);
    RBW_COMPARE_NEAR_STRICT(clip.x() / clip.w(), 0.0, 1e-12);
    RBW_COMPARE_NEAR_STRICT(clip.y() / clip.w(), 0.0, 1e-12);
    RBW_COMPARE_NEAR_STRICT((cam.eye() - Vec3(1, 2, 3)).norm(), 7.0, 1e-12);
    // yaw 30, pitch 20: eye - target = 7 (cos20 sin30, sin20, cos20 cos30).
    const double c = std::cos(20 * M_PI / 180);
    QVERIFY(near(cam.eye() - Vec3(1, 2, 3), 7.0 * Vec3(c * 0.5, std::sin(20 * M_PI / 180), c * std::sqrt(3.0) / 2), 1e-12));
    // The camera's up has a positive y: the scene is seen from slightly above, upright.
    QVERIFY(cam.up().y() > 0);
}

void TestViewGeometry::cameraRayRoundTrip()
{
    // A ray through ndc (x, y) passes through points that project back to (x, y).
    OrbitCamera cam;
    cam.setAngles(-50, 35);
    cam.setDistance(4);
    const double aspect = 16.0 / 9.0;
    for (const auto& [x, y] : {std::pair{0.3, -0.4}, std::pair{-0.9, 0.8}, std::pair{0.0, 0.0}}) {
        const Ray r = cam.rayThroughNdc(x, y, aspect);
        const Vec3 p = r.origin_W + 3.0 * r.dir_W;
        const Eigen::Vector4d clip = cam.projectionMatrix(aspect) * cam.viewMatrix() * Eigen::Vector4d(p.x(), p.y(), p.z(), 1);
        RBW_COMPARE_NEAR_STRICT(clip.x() / clip.w(), x, 1e-12);
        RBW_COMPARE_NEAR_STRICT(clip.y() / clip.w(), y, 1e-12);
    }
}

void TestViewGeometry::arrowScaleLongestIsOneBox()
{
    // Lesson 1 after its step: one force |f| = sqrt(2); the box's longest edge is 1 m,
    // so the force's scale is 1/sqrt(2) m/N and its arrow is drawn 1 m long.
    World w(lessonScene("01-one-step/scene.json"));
    StepTrace t;
    QVERIFY(w.step(&t).ok);
    const ViewSnapshot s = makeViewSnapshot(w, &t);
    view::FrameOptions noWorld;
    noWorld.worldReference = false;   // the world axes would add three arrows to `lit`
    const view::FrameGeometry g = view::buildFrameGeometry(s, {}, noWorld);
    QCOMPARE(g.scales.refLength, 1.0);
    RBW_COMPARE_NEAR_STRICT(g.scales.maxForce, std::sqrt(2.0), 1e-15);
    RBW_COMPARE_NEAR_STRICT(view::arrowScale(g.scales.maxForce, g.scales.refLength) * std::sqrt(2.0), 1.0, 1e-15);
    QCOMPARE(view::arrowScale(0.0, 1.0), 0.0);   // nothing to draw
    // One box = 12 triangles = 36 vertices; the force, the probes and their velocities
    // are arrows and balls in the overlay.
    QCOMPARE(int(g.lit.size()), 36);
    QVERIFY(!g.overlay.empty());
    // Every vertex is finite (the view never draws NaN).
    for (const std::vector<view::LitVertex>* part : {&g.lit, &g.overlay}) {
        for (const view::LitVertex& v : *part) QVERIFY(std::isfinite(v.p[0]) && std::isfinite(v.p[1]) && std::isfinite(v.p[2]));
    }
}

void TestViewGeometry::lesson5TorqueIsDrawnAtTheCentre()
{
    // Lesson 5: the body "accelerated" (index 1, a 1 m cube at x = (1.5, 0, 0)) has
    // the couple q_0 = (0, 0.05, 0) N m. After one step the trace's applied_torque
    // row is drawn from x along +y, one box (1 m) long since it is the only torque.
    World w(lessonScene("05-spinning/scene.json"));
    StepTrace t;
    QVERIFY(w.step(&t).ok);
    const TraceEntry* qTrace = t.find("applied_torque", 1, 0);
    QVERIFY(qTrace != nullptr);
    const ViewSnapshot s = makeViewSnapshot(w, &t);
    QCOMPARE(int(s.torques.size()), 1);
    QVERIFY(s.torques[0].q_W == std::get<Vec3>(qTrace->value));
    const view::FrameGeometry g = view::buildFrameGeometry(s, {}, view::FrameOptions{});
    int torques = 0;
    for (const view::ArrowRecord& a : g.arrows) {
        if (a.kind != view::ArrowKind::Torque) continue;
        ++torques;
        QCOMPARE(a.body, 1);
        QVERIFY(a.from_W == s.bodies[1].x_W);
        QVERIFY(near(a.to_W - a.from_W, Vec3(0, 1, 0), 1e-12));
        QVERIFY(a.value == Vec3(0, 0.05, 0));
    }
    QCOMPARE(torques, 1);
    QVERIFY(g.scales.hasTorque);
    RBW_COMPARE_NEAR_STRICT(g.scales.maxTorque, 0.05, 1e-15);
    // Negative control: before the first step there is no trace and no torque arrow.
    const ViewSnapshot before = makeViewSnapshot(World(lessonScene("05-spinning/scene.json")), nullptr);
    QVERIFY(before.torques.empty());
}

// Lesson 7: boxes 1 × 2 × 1 (1 kg) beside cuboids 2 × 6 × 2 (2 kg). The longest
// gravity arrow (2 kg · 9.81) is the smallest box's longest edge, 2 m, so every box is
// at least as long as its own gravity arrow (with the mean edge, 4.4 m, the 1 kg boxes
// got 2.2 m arrows).
void TestViewGeometry::lesson7BoxesOutgrowTheirGravity()
{
    World w(lessonScene("07-bounce/scene.json"));
    StepTrace t;
    QVERIFY(w.step(&t).ok);
    const view::FrameGeometry g = view::buildFrameGeometry(makeViewSnapshot(w, &t), {}, view::FrameOptions{});
    QCOMPARE(g.scales.refLength, 2.0);
    int gravity = 0;
    for (const view::ArrowRecord& a : g.arrows) {
        if (a.kind != view::ArrowKind::Gravity) continue;
        ++gravity;
        const double edge = w.scene().bodies[static_cast<std::size_t>(a.body)].size.maxCoeff();
        QVERIFY2((a.to_W - a.from_W).norm() <= edge * (1.0 + 1e-12), qPrintable(QString::number(a.body)));
    }
    QCOMPARE(gravity, 5);
}

QTEST_GUILESS_MAIN(TestViewGeometry)
#include "tst_view_geometry.moc"
