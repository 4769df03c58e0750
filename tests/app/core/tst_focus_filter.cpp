// The derivation of a many-body scene follows one body: which body (the one last
// grabbed, else the first movable, and only above six bodies), and which rows of a
// trace it writes out (the body's own, the world-level ones, and the contacts it takes
// part in, renumbered). The trace here is built by hand so each row's expectation can
// be read off the list below.
#include "app/core/focus_filter.h"

#include <QtTest>

using namespace rbw;

namespace {

// Test-local catalogue entries: the filter looks only at the stage, never the id.
QuantityInfo info(const char* id, Stage stage)
{
    QuantityInfo q{};
    q.id = id;
    q.stage = stage;
    q.symbol = q.text = q.formula = q.unit = "";
    return q;
}
const QuantityInfo kForce = info("force", Stage::Forces);
const QuantityInfo kPosition = info("position", Stage::Integration);
const QuantityInfo kPairsTested = info("pairs_tested", Stage::Collision);
const QuantityInfo kImpulse = info("impulse", Stage::Collision);
const QuantityInfo kCorrection = info("correction_a", Stage::Correction);
const QuantityInfo kProbe = info("probe_position", Stage::Probes);

// Bodies 0..7; contact 0: box 0 with box 2, contact 1: box 1 on plane 0, contact 2:
// box 1 with box 2. A contact's rows carry body A and the contact's number.
StepTrace handTrace()
{
    StepTrace t;
    t.step = 41;
    t.time = 0.42;
    t.diagnostics.total = 7.5;
    t.add(kForce, 0, Vec3(0, -1, 0));
    t.add(kForce, 1, Vec3(0, -2, 0));
    t.add(kForce, 2, Vec3(0, -3, 0));
    t.add(kPosition, 1, Vec3(1, 0, 0));
    t.add(kPosition, 2, Vec3(2, 0, 0));
    t.add(kPairsTested, -1, 3.0);
    t.contacts.push_back(ContactHeader{0, 2, -1, "vertex-face", "single-point", 1, false, {}});
    t.add(kImpulse, 0, 1.5, 0);
    t.contacts.push_back(ContactHeader{1, -1, 0, "vertex-plane", "average", 4, false, {}});
    t.add(kImpulse, 1, 2.5, 1);
    t.contacts.push_back(ContactHeader{1, 2, -1, "edge-edge", "single-point", 1, false, {}});
    t.add(kImpulse, 1, 3.5, 2);
    t.add(kCorrection, 2, Vec3(0, 0.01, 0), 0);
    t.add(kProbe, 1, Vec3(0, 1, 0), 0);
    // The state when the step began: body b at x = (b, 0.5, 0).
    t.start.bodies.resize(8);
    for (int b = 0; b < 8; ++b) t.start.bodies[static_cast<size_t>(b)].x_W = Vec3(b, 0.5, 0);
    return t;
}

// "id/body/index=value" for scalars, "id/body/index" otherwise.
QStringList rows(const StepTrace& t)
{
    QStringList out;
    for (const TraceEntry& e : t.entries) {
        QString row = QStringLiteral("%1/%2/%3").arg(QString::fromLatin1(e.info->id)).arg(e.body).arg(e.index);
        if (const double* v = std::get_if<double>(&e.value)) row += QStringLiteral("=%1").arg(*v);
        out << row;
    }
    return out;
}

// "A-B" for a box pair, "A-p0" for a box on plane 0.
QStringList contacts(const StepTrace& t)
{
    QStringList out;
    for (const ContactHeader& c : t.contacts) {
        out << (c.plane >= 0 ? QStringLiteral("%1-p%2").arg(c.bodyA).arg(c.plane)
                             : QStringLiteral("%1-%2").arg(c.bodyA).arg(c.bodyB));
    }
    return out;
}

SceneDef sceneOf(int bodies, int fixedFirst)
{
    SceneDef s;
    s.bodies.resize(bodies);
    for (int i = 0; i < bodies; ++i) {
        s.bodies[i].name = "box" + std::to_string(i);
        s.bodies[i].fixed = i < fixedFirst;
    }
    return s;
}

} // namespace

class TestFocusFilter : public QObject {
    Q_OBJECT
private slots:
    void focusTraceSelects_data();
    void focusTraceSelects();
    void focusTraceKeepsTheStep();
    void focusTraceIsIdempotent();
    void focusContactsNumbersInTheWholeTrace();
    void focusBody_data();
    void focusBody();
};

void TestFocusFilter::focusTraceSelects_data()
{
    QTest::addColumn<int>("body");
    QTest::addColumn<QStringList>("expectedRows");
    QTest::addColumn<QStringList>("expectedContacts");

    // Body 0: its force, the world-level count, and contact 0 (with box 2) as contact 0.
    QTest::newRow("body 0") << 0 << QStringList{"force/0/-1", "pairs_tested/-1/-1=3", "impulse/0/0=1.5"}
                            << QStringList{"0-2"};
    // Body 1: contacts 1 and 2 become 0 and 1; its probe keeps its own numbering.
    QTest::newRow("body 1") << 1
                            << QStringList{"force/1/-1", "position/1/-1", "pairs_tested/-1/-1=3", "impulse/1/0=2.5",
                                           "impulse/1/1=3.5", "probe_position/1/0"}
                            << QStringList{"1-p0", "1-2"};
    // Body 2: B in contacts 0 and 2, whose rows carry body A (0 and 1) and are kept;
    // its correction keeps its own numbering.
    QTest::newRow("body 2") << 2
                            << QStringList{"force/2/-1", "position/2/-1", "pairs_tested/-1/-1=3", "impulse/0/0=1.5",
                                           "impulse/1/1=3.5", "correction_a/2/0"}
                            << QStringList{"0-2", "1-2"};
    // A body with no rows and no contacts: only the world-level row.
    QTest::newRow("body 5") << 5 << QStringList{"pairs_tested/-1/-1=3"} << QStringList{};
}

void TestFocusFilter::focusTraceSelects()
{
    QFETCH(int, body);
    QFETCH(QStringList, expectedRows);
    QFETCH(QStringList, expectedContacts);
    const StepTrace focused = focusTrace(handTrace(), body);
    QCOMPARE(rows(focused), expectedRows);
    QCOMPARE(contacts(focused), expectedContacts);
}

void TestFocusFilter::focusTraceKeepsTheStep()
{
    const StepTrace focused = focusTrace(handTrace(), 1);
    QCOMPARE(focused.step, 41L);
    QCOMPARE(focused.time, 0.42);
    QCOMPARE(focused.diagnostics.total, 7.5);
    // The state when the step began, for every body (the derivation's {{start:...}}).
    QCOMPARE(int(focused.start.bodies.size()), 8);
    TraceValue x;
    QVERIFY(startValue(focused, "position", 1, -1, &x));
    QVERIFY(std::get<Vec3>(x) == Vec3(1.0, 0.5, 0.0));
    // The headers travel with their contacts.
    QCOMPARE(QString::fromLatin1(focused.contacts[0].feature), QString("vertex-plane"));
    QCOMPARE(focused.contacts[0].pointCount, 4);
    QCOMPARE(QString::fromLatin1(focused.contacts[1].feature), QString("edge-edge"));
}

void TestFocusFilter::focusTraceIsIdempotent()
{
    const StepTrace once = focusTrace(handTrace(), 2);
    const StepTrace twice = focusTrace(once, 2);
    QCOMPARE(rows(twice), rows(once));
    QCOMPARE(contacts(twice), contacts(once));
}

void TestFocusFilter::focusContactsNumbersInTheWholeTrace()
{
    // Body 1 takes part in contacts 1 (plane) and 2 (with box 2); body 2 in 0 and 2;
    // body 5 in none. Contact c of the selection is contact focusContacts()[c] of the trace.
    const StepTrace t = handTrace();
    QCOMPARE(focusContacts(t, 1), (std::vector<int>{1, 2}));
    QCOMPARE(focusContacts(t, 2), (std::vector<int>{0, 2}));
    QVERIFY(focusContacts(t, 5).empty());
    const StepTrace focused = focusTrace(t, 2);
    const std::vector<int> inWhole = focusContacts(t, 2);
    QCOMPARE(focused.contacts.size(), inWhole.size());
    for (size_t c = 0; c < inWhole.size(); ++c) {
        QCOMPARE(focused.contacts[c].bodyA, t.contacts[static_cast<size_t>(inWhole[c])].bodyA);
        QCOMPARE(focused.contacts[c].bodyB, t.contacts[static_cast<size_t>(inWhole[c])].bodyB);
    }
}

void TestFocusFilter::focusBody_data()
{
    QTest::addColumn<int>("bodies");
    QTest::addColumn<int>("fixedFirst");   // bodies 0 .. fixedFirst-1 are fixed
    QTest::addColumn<int>("wanted");       // the body last grabbed, -1 none
    QTest::addColumn<int>("expected");

    QTest::newRow("6 bodies: every body") << 6 << 0 << 3 << -1;
    QTest::newRow("7 bodies: the grabbed one") << 7 << 0 << 3 << 3;
    QTest::newRow("7 bodies, none grabbed: the first") << 7 << 0 << -1 << 0;
    QTest::newRow("first two fixed: the first movable") << 7 << 2 << -1 << 2;
    QTest::newRow("grabbed out of range: the first movable") << 7 << 1 << 7 << 1;
    QTest::newRow("all fixed: the last") << 7 << 7 << -1 << 6;
}

void TestFocusFilter::focusBody()
{
    QFETCH(int, bodies);
    QFETCH(int, fixedFirst);
    QFETCH(int, wanted);
    QFETCH(int, expected);
    QCOMPARE(derivationFocusBody(sceneOf(bodies, fixedFirst), wanted), expected);
}

QTEST_GUILESS_MAIN(TestFocusFilter)
#include "tst_focus_filter.moc"
