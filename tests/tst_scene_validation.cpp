// Every bad scene input is refused before anything runs: rbw exits with status 2 and
// its message names the file, the JSON path of the field and the reason
// (docs/scene-format.md). One data row per kind of bad input, run through the real
// rbw binary, plus a negative control: the valid base scene runs with status 0.
#include <QProcess>
#include <QTemporaryDir>
#include "tests/test_support.h"

#include <QtTest>

namespace {

// A valid scene; rows replace one fragment of it to make it invalid.
const char* const kBase = R"({
  "name": "validation base",
  "dt": 0.1, "steps": 2, "integrator": "explicit-euler",
  "gravity": [0, -9.81, 0],
  "bodies": [
    { "name": "a", "size": [1, 0.6, 0.5], "mass": 2,
      "orientation": { "axis": [0, 0, 1], "degrees": 90 } },
    { "name": "b", "size": [1, 1, 1], "mass": 1, "position": [3, 0, 0] }
  ],
  "forces": [ { "body": "a", "point": [0.3, 0.5, 0.25], "force": [1, 1, 0] } ],
  "probes": [ { "body": "b", "point": [3.5, 0, 0] } ]
})";

using Run = rbw::test::RbwRun;
using rbw::test::runRbw;

} // namespace

class TestSceneValidation : public QObject {
    Q_OBJECT
private slots:
    void validBaseRuns();
    void badScene_data();
    void badScene();
    void badOption_data();
    void badOption();

private:
    QTemporaryDir dir_;
    QString write(const QByteArray& text);
};

QString TestSceneValidation::write(const QByteArray& text)
{
    static int n = 0;
    const QString path = dir_.filePath(QStringLiteral("scene-%1.json").arg(++n));
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) qFatal("cannot write %s", qPrintable(path));
    f.write(text);
    return path;
}

void TestSceneValidation::validBaseRuns()
{
    // Negative control: the base scene is valid, so the rows below fail for their edit alone.
    const Run r = runRbw({"run", write(kBase)});
    QCOMPARE(r.exitCode, 0);
    QVERIFY2(r.err.isEmpty(), qPrintable(r.err));
}

void TestSceneValidation::badScene_data()
{
    QTest::addColumn<QString>("from");      // fragment of kBase to replace
    QTest::addColumn<QString>("to");
    QTest::addColumn<QString>("message");   // expected "path: reason" text

    QTest::newRow("malformed JSON") << R"("mass": 2,)" << R"("mass": 2,,)"
                                    << "malformed JSON at line 6, column";
    QTest::newRow("unknown key (typo)") << R"("mass": 2,)" << R"("masss": 2,)"
                                        << R"(bodies[0].masss: unknown key (did you mean "mass"?))";
    QTest::newRow("unknown top-level key") << R"("gravity")" << R"("gravty")"
                                           << R"(gravty: unknown key (did you mean "gravity"?))";
    QTest::newRow("missing dt") << R"("dt": 0.1,)" << ""
                                << "dt: required field is missing";
    QTest::newRow("missing size") << R"("size": [1, 1, 1],)" << ""
                                  << "bodies[1].size: required field is missing";
    QTest::newRow("missing mass") << R"(, "mass": 1)" << ""
                                  << "bodies[1].mass: required field is missing";
    QTest::newRow("mass zero") << R"("mass": 2,)" << R"("mass": 0,)"
                               << "bodies[0].mass: must be a finite number > 0, got 0";
    QTest::newRow("mass negative") << R"("mass": 2,)" << R"("mass": -1,)"
                                   << "bodies[0].mass: must be a finite number > 0, got -1";
    QTest::newRow("size zero") << "[1, 0.6, 0.5]" << "[1, 0, 0.5]"
                               << "bodies[0].size: every edge length must be a finite number > 0, got 0 at index 1";
    QTest::newRow("size negative") << "[1, 0.6, 0.5]" << "[-1, 0.6, 0.5]"
                                   << "bodies[0].size: every edge length must be a finite number > 0, got -1 at index 0";
    QTest::newRow("NaN") << R"("mass": 2,)" << R"("mass": NaN,)"
                         << "bodies[0].mass: must be a finite number, got NaN";
    QTest::newRow("infinity") << "[0, -9.81, 0]" << "[0, -Infinity, 0]"
                              << "gravity[1]: must be a finite number, got -Infinity";
    QTest::newRow("overflow to infinity") << R"("position": [3, 0, 0])" << R"("position": [3, 1e999, 0])"
                                          << "bodies[1].position[1]: must be a finite number, got 1e999";
    QTest::newRow("zero rotation axis") << R"("axis": [0, 0, 1])" << R"("axis": [0, 0, 0])"
                                        << "bodies[0].orientation.axis: rotation axis must not be zero";
    QTest::newRow("zero quaternion") << R"("axis": [0, 0, 1], "degrees": 90)" << R"("quaternion": [0, 0, 0, 0])"
                                     << "bodies[0].orientation.quaternion: must not be the zero quaternion";
    QTest::newRow("duplicate body name") << R"("name": "b")" << R"("name": "a")"
                                         << R"(bodies[1].name: duplicate body name "a")";
    QTest::newRow("force on unknown body") << R"({ "body": "a", "point")" << R"({ "body": "ghost", "point")"
                                           << R"(forces[0].body: no body named "ghost" (bodies: a, b))";
    QTest::newRow("probe on unknown body") << R"({ "body": "b", "point")" << R"({ "body": "c", "point")"
                                           << R"(probes[0].body: no body named "c")";
    QTest::newRow("dt zero") << R"("dt": 0.1)" << R"("dt": 0)"
                             << "dt: must be a finite number > 0, got 0";
    QTest::newRow("dt negative") << R"("dt": 0.1)" << R"("dt": -0.1)"
                                 << "dt: must be a finite number > 0, got -0.1";
    QTest::newRow("unknown integrator") << R"("explicit-euler")" << R"("rk5")"
                                        << R"(integrator: unknown integrator "rk5"; known: explicit-euler)";
    QTest::newRow("wrong type") << R"("steps": 2)" << R"("steps": "two")"
                                << "steps: must be a number, got a string";
    QTest::newRow("vector of 2") << "[0, -9.81, 0]" << "[0, -9.81]"
                                 << "gravity: must be an array of 3 numbers, got 2 elements";
    QTest::newRow("restitution above 1") << R"("integrator": "explicit-euler",)" << R"("integrator": "explicit-euler", "restitution": 1.5,)"
                                         << "restitution: must be a number from 0 to 1, got 1.5";
    QTest::newRow("negative friction") << R"("integrator": "explicit-euler",)" << R"("integrator": "explicit-euler", "friction": -0.1,)"
                                       << "friction: must be >= 0, got -0.1";
    QTest::newRow("zero plane normal") << R"("gravity": [0, -9.81, 0],)"
                                       << R"("gravity": [0, -9.81, 0], "planes": [{"name": "ground", "point": [0,0,0], "normal": [0,0,0]}],)"
                                       << "planes[0].normal: must not be the zero vector";
    QTest::newRow("pair with one body twice") << R"("probes")" << R"("pairs": [{"bodies": ["a", "a"], "restitution": 0.5}], "probes")"
                                              << R"(pairs[0].bodies: names "a" twice)";
    QTest::newRow("pair listed twice") << R"("probes")"
                                       << R"("pairs": [{"bodies": ["a", "b"], "friction": 0.5}, {"bodies": ["b", "a"], "restitution": 0.2}], "probes")"
                                       << "pairs[1].bodies: this pair is already listed";
    QTest::newRow("unknown plane mode") << R"("integrator": "explicit-euler",)" << R"("integrator": "explicit-euler", "plane_contacts": "mean",)"
                                        << R"(plane_contacts: must be "per-point" or "average", got "mean")";
    QTest::newRow("torque on unknown body") << R"("probes")" << R"("torques": [{"body": "z", "torque": [0, 1, 0]}], "probes")"
                                            << R"(torques[0].body: no body named "z")";
    QTest::newRow("torque missing") << R"("probes")" << R"("torques": [{"body": "a"}], "probes")"
                                    << R"(torques[0].torque: required field is missing)";
    QTest::newRow("torque NaN") << R"("probes")" << R"("torques": [{"body": "a", "torque": [0, NaN, 0]}], "probes")"
                                << R"(torques[0].torque)";
    QTest::newRow("torque typo") << R"("probes")" << R"("torques": [{"body": "a", "torqe": [0, 1, 0]}], "probes")"
                                 << R"(torques[0].torqe: unknown key)";
    QTest::newRow("push force negative") << R"("probes")" << R"("push": {"body": "a", "force": -5}, "probes")"
                                         << "push.force: must be a finite number > 0, got -5";
    QTest::newRow("push on unknown body") << R"("probes")" << R"("push": {"body": "q"}, "probes")"
                                          << R"(push.body: no body named "q")";
    QTest::newRow("force window empty") << R"("force": [1, 1, 0] })" << R"("force": [1, 1, 0], "from_step": 3, "to_step": 3 })"
                                        << "forces[0].to_step: must be greater than from_step";
}

void TestSceneValidation::badScene()
{
    QFETCH(QString, from);
    QFETCH(QString, to);
    QFETCH(QString, message);

    QString text = QString::fromUtf8(kBase);
    QVERIFY2(text.count(from) == 1, qPrintable("row edit must match once: " + from));
    text.replace(from, to);
    const QString path = write(text.toUtf8());

    const Run r = runRbw({"run", path});
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.out.isEmpty(), "nothing may be printed as a result");
    // "rbw: FILE: path: reason"
    QVERIFY2(r.err.startsWith("rbw: " + path + ": "), qPrintable(r.err));
    QVERIFY2(r.err.contains(message), qPrintable("expected \"" + message + "\" in: " + r.err));
}

void TestSceneValidation::badOption_data()
{
    QTest::addColumn<QStringList>("options");
    QTest::addColumn<QString>("message");
    QTest::newRow("--dt zero") << QStringList{"--dt", "0"} << "--dt: must be a finite number > 0";
    QTest::newRow("--dt text") << QStringList{"--dt", "fast"} << "--dt: must be a finite number > 0";
    QTest::newRow("--integrator unknown") << QStringList{"--integrator", "verlet9"}
                                          << R"(--integrator: unknown integrator "verlet9")";
    QTest::newRow("--steps negative") << QStringList{"--steps", "-3"} << "--steps: must be a whole number >= 0";
    QTest::newRow("--trace bad") << QStringList{"--trace", "some"} << "--trace: must be none, last or all";
    QTest::newRow("--format bad") << QStringList{"--format", "xml"} << "--format: must be json or csv";
    QTest::newRow("unknown option") << QStringList{"--stepz", "3"} << "Unknown option 'stepz'";
}

void TestSceneValidation::badOption()
{
    QFETCH(QStringList, options);
    QFETCH(QString, message);
    const Run r = runRbw(QStringList{"run", write(kBase)} + options);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.out.isEmpty(), r.out.constData());
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
}

QTEST_GUILESS_MAIN(TestSceneValidation)
#include "tst_scene_validation.moc"
