// Every bad scene input is refused before anything runs: rbw exits with status 2 and
// its message names the file, the JSON path of the field and the reason
// (docs/scene-format.md). One data row per kind of bad input, run through the real
// rbw binary, plus a negative control: the valid base scene runs with status 0.
//
// strictInput (issue 13) covers what the loader once let through or reported badly:
// duplicate keys (with their JSON path), the steps limit, long names and control
// bytes in messages, an empty bodies list, NaN literals, and inputs whose derived
// quantities overflow (I0^-1, I0, the sums of squares, L0, a probe offset, the end
// time). Its positive rows (status 0) load the edge values the messages name.
//
// What the loader and validate() say in process (the raw scan, messageText, the code
// route beside the file route) is tst_scene_rules.
#include <QProcess>
#include <QTemporaryDir>
#include "tests/app/scene/validation_base.h"
#include "tests/test_support.h"

#include <QtTest>

#include <limits>

namespace {

using Run = rbw::test::RbwRun;
using rbw::test::runRbw;
using validation_base::kBase;

} // namespace

class TestSceneValidation : public QObject {
    Q_OBJECT
private slots:
    void validBaseRuns();
    void badScene_data();
    void badScene();
    void strictInput_data();
    void strictInput();
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
                                       << "friction: must be a finite number >= 0, got -0.1";
    QTest::newRow("zero plane normal") << R"("gravity": [0, -9.81, 0],)"
                                       << R"("gravity": [0, -9.81, 0], "planes": [{"name": "ground", "point": [0,0,0], "normal": [0,0,0]}],)"
                                       << "planes[0].normal: must not be the zero vector";
    QTest::newRow("pair with one body twice") << R"("probes")" << R"("pairs": [{"bodies": ["a", "a"], "restitution": 0.5}], "probes")"
                                              << R"(pairs[0].bodies: names "a" twice)";
    QTest::newRow("pair listed twice") << R"("probes")"
                                       << R"("pairs": [{"bodies": ["a", "b"], "friction": 0.5}, {"bodies": ["b", "a"], "restitution": 0.2}], "probes")"
                                       << "pairs[1].bodies: this pair is already listed as pairs[0]; give each pair once";
    QTest::newRow("pair without coefficients") << R"("probes")" << R"("pairs": [{"bodies": ["a", "b"]}], "probes")"
                                               << R"(pairs[0]: give "restitution", "friction" or both)";
    QTest::newRow("fixed body moving") << R"("mass": 1, "position": [3, 0, 0])"
                                       << R"("fixed": true, "position": [3, 0, 0], "angular_velocity": [0, 0, 1])"
                                       << "bodies[1].angular_velocity: a fixed body cannot have a velocity";
    QTest::newRow("energy jump factor below 1") << R"("probes")" << R"("energy_jump": {"factor": 0.5}, "probes")"
                                                << "energy_jump.factor: must be 0 (off) or a finite number >= 1, got 0.5";
    QTest::newRow("plane named like a body") << R"("probes")"
                                             << R"("planes": [{"name": "b", "point": [0, 0, 0], "normal": [0, 1, 0]}], "probes")"
                                             << R"(planes[0].name: duplicate name "b" (bodies and planes share names))";
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

// Rows: edits of kBase (pairs from, to), extra options, the exit status, words the
// message must contain and text it must not (a name cut at 40 characters never shows
// 41 of them). Every message is short, whatever the input.
void TestSceneValidation::strictInput_data()
{
    QTest::addColumn<QStringList>("edits");      // from1, to1, from2, to2, ...
    QTest::addColumn<QStringList>("options");    // after "run FILE"
    QTest::addColumn<int>("status");
    QTest::addColumn<QStringList>("words");
    QTest::addColumn<QStringList>("absent");

    const QStringList none;
    const QString massA = R"("mass": 2,)";
    const QString tail = R"("probes")";   // insert top-level keys before "probes"
    const QString forceBody = R"({ "body": "a", "point")";

    // Duplicate keys: QJsonDocument keeps the last silently; the raw scan names the
    // path of the second. Line and column counted in kBase after the edit (line 6 is
    // body a's first line; "mass": -1 starts at column 43, "mass": 2 at 55).
    QTest::newRow("duplicate key") << QStringList{massA, R"("mass": -1, "mass": 2,)"} << none << 2
        << QStringList{R"(bodies[0].mass: duplicate key "mass" (first at line 6, column 43, again at line 6, column 55); a key may appear only once in an object)"}
        << none;
    QTest::newRow("duplicate top-level key") << QStringList{R"("dt": 0.1,)", R"("dt": 0.1, "dt": -5,)"} << none << 2
        << QStringList{R"(dt: duplicate key "dt" (first at line 3, column 3, again at line 3, column 14))"} << none;
    QTest::newRow("duplicate key, nested") << QStringList{R"("degrees": 90)", R"("degrees": 90, "degrees": 45)"} << none << 2
        << QStringList{R"(bodies[0].orientation.degrees: duplicate key "degrees")"} << none;
    QTest::newRow("duplicate key in an array element") << QStringList{R"("force": [1, 1, 0] })", R"("force": [1, 1, 0], "force": [0, 0, 0] })"}
        << none << 2 << QStringList{R"(forces[0].force: duplicate key "force")"} << none;
    // "m\u0061ss" is "mass" once unescaped, as QJsonDocument reads it.
    QTest::newRow("duplicate key, escaped") << QStringList{massA, R"("mass": 2, "m\u0061ss": 3,)"} << none << 2
        << QStringList{R"(bodies[0].mass: duplicate key "mass")"} << none;

    // steps: at most 10^9; 9e15 once ran for ever.
    QTest::newRow("steps above 10^9") << QStringList{R"("steps": 2)", R"("steps": 1000000001)"} << none << 2
        << QStringList{"steps: must be at most 1000000000 (10^9), got 1000000001"} << none;
    QTest::newRow("steps 9e15") << QStringList{R"("steps": 2)", R"("steps": 9e15)"} << none << 2
        << QStringList{"steps: must be at most 1000000000 (10^9), got 9000000000000000"} << none;
    QTest::newRow("steps beyond whole doubles") << QStringList{R"("steps": 2)", R"("steps": 1e16)"} << none << 2
        << QStringList{"steps: must be a whole number from -9e15 to 9e15, got 1e+16"} << none;
    // Negative control: 10^9 itself loads (--steps 0 runs none of them).
    QTest::newRow("steps 10^9 loads") << QStringList{R"("steps": 2)", R"("steps": 1000000000)"}
        << QStringList{"--steps", "0"} << 0 << none << none;
    // Qt's default formatting printed 2.0000001 as "2".
    QTest::newRow("steps nearly whole") << QStringList{R"("steps": 2)", R"("steps": 2.0000001)"} << none << 2
        << QStringList{"steps: must be a whole number, got 2.0000001"} << none;

    // Long names and control bytes: cut after 40 characters with "…", escaped as \u0000.
    const QString k100k(100000, QLatin1Char('k'));
    QTest::newRow("100 000-character unknown key") << QStringList{R"("dt": 0.1,)", R"("dt": 0.1, ")" + k100k + R"(": 1,)"}
        << none << 2 << QStringList{": unknown key (allowed:", QString(40, QLatin1Char('k')) + QStringLiteral("\u2026")}
        << QStringList{QString(41, QLatin1Char('k'))};
    const QString x1000(1000, QLatin1Char('x'));
    QTest::newRow("long name in a message") << QStringList{forceBody, R"({ "body": ")" + x1000 + R"(", "point")"}
        << none << 2 << QStringList{R"(forces[0].body: no body named ")" + QString(40, QLatin1Char('x')) + QStringLiteral("\u2026\" (bodies: a, b)")}
        << QStringList{QString(41, QLatin1Char('x'))};
    QTest::newRow("NUL and ESC in a name") << QStringList{forceBody, R"({ "body": "a\u0000b\u001b[31m", "point")"}
        << none << 2 << QStringList{R"(forces[0].body: no body named "a\u0000b\u001b[31m")"} << none;
    QTest::newRow("quote and backslash in a name") << QStringList{forceBody, R"({ "body": "a\"b\\c", "point")"}
        << none << 2 << QStringList{R"(no body named "a\"b\\c")"} << none;
    QTest::newRow("bidi override in a name") << QStringList{forceBody, R"({ "body": "\u202eevil", "point")"}
        << none << 2 << QStringList{R"(no body named "\u202eevil")"} << none;
    QTest::newRow("long word echoed") << QStringList{tail, R"("plane_contacts": ")" + QString(500, QLatin1Char('y')) + R"(", "probes")"}
        << none << 2 << QStringList{R"(plane_contacts: must be "per-point" or "average", got ")" + QString(40, QLatin1Char('y')) + QStringLiteral("\u2026\"")}
        << QStringList{QString(41, QLatin1Char('y'))};
    QTest::newRow("duplicate of a long key") << QStringList{R"("dt": 0.1,)", R"("dt": 0.1, ")" + x1000 + R"(": 1, ")" + x1000 + R"(": 2,)"}
        << none << 2 << QStringList{QString(40, QLatin1Char('x')) + QStringLiteral("\u2026: duplicate key")}
        << QStringList{QString(41, QLatin1Char('x'))};

    // An empty bodies list is said first and alone: not the unknown key after it, and
    // not the force and probe that name bodies.
    QTest::newRow("empty bodies") << QStringList{R"("bodies": [)", R"("bodies": [], "unused": [)"} << none << 2
        << QStringList{"bodies: must list at least one body; a scene without a body has nothing to simulate"}
        << QStringList{"unused", "forces[0]", "probes[0]"};

    // NaN and other non-numbers: the first one's field is named, however many follow.
    QTest::newRow("two NaN literals") << QStringList{massA, R"("mass": NaN, "linear_velocity": [NaN, 0, 0],)"} << none << 2
        << QStringList{"bodies[0].mass: must be a finite number, got NaN (not a JSON number"} << none;
    QTest::newRow("NaN in an array") << QStringList{"[0, -9.81, 0]", "[0, NaN, NaN]"} << none << 2
        << QStringList{"gravity[1]: must be a finite number, got NaN"} << none;
    QTest::newRow("lower-case nan") << QStringList{massA, R"("mass": nan,)"} << none << 2
        << QStringList{"bodies[0].mass: must be a finite number, got nan"} << none;
    QTest::newRow("number that rounds to 0") << QStringList{R"("dt": 0.1)", R"("dt": 1e-400)"} << none << 2
        << QStringList{"dt: must be a number a double can hold, got 1e-400 (nearer to 0 than any double but 0"} << none;
    QTest::newRow("number too large, beyond a long double too") << QStringList{massA, R"("mass": -1.5E5000,)"} << none << 2
        << QStringList{"bodies[0].mass: must be a finite number, got -1.5E5000 (too large for a double"} << none;
    QTest::newRow("number too small, beyond a long double too") << QStringList{massA, R"("mass": 2.5e-5000,)"} << none << 2
        << QStringList{"bodies[0].mass: must be a number a double can hold, got 2.5e-5000 (nearer to 0"} << none;
    // Negative control: a syntax error before the NaN is the message, with its place.
    QTest::newRow("syntax error before a NaN") << QStringList{massA, R"("mass": 2,, "x": NaN,)"} << none << 2
        << QStringList{"malformed JSON at line 6, column"} << QStringList{"NaN"};

    // Derived quantities (validate()). Body a: size [1, 0.6, 0.5], so the sums of squares
    // of I0 = M/12 diag(b² + c², a² + c², a² + b²) are (0.61, 1.25, 1.36).
    //   M = 1e-308: I0xx = 1e-308/12 * 0.61 = 5.08e-310 < 1/DBL_MAX = 5.56e-309, so
    //   1/I0xx = 1.97e309 overflows. Least M: 12 / (0.61 * 1.797e308) = 1.094e-307,
    //   printed rounded up: 1.1e-307, which itself loads (I0xx = 5.59e-309).
    QTest::newRow("mass whose I0^-1 overflows") << QStringList{massA, R"("mass": 1e-308,)"} << none << 2
        << QStringList{"bodies[0].mass: 1e-308 makes I0^-1 overflow (I0 = M/12 (b\u00b2 + c\u00b2) = 5.08e-310, too small",
                       "for this size the mass must be at least 1.1e-307 kg"} << none;
    QTest::newRow("mass at the printed limit loads") << QStringList{massA, R"("mass": 1.1e-307,)"}
        << QStringList{"--steps", "0"} << 0 << none << none;
    //   M = 1e-309: 1/M = 1e309 overflows; least M = 1/DBL_MAX = 5.56e-309, rounded up.
    QTest::newRow("mass whose 1/M overflows") << QStringList{massA, R"("mass": 1e-309,)"} << none << 2
        << QStringList{"bodies[0].mass: 1e-309 makes 1/M overflow; must be at least 5.6e-309 kg"} << none;
    //   size [1e10, 0.6, 0.5], M = 1e308: a² + c² = 1e20 + 0.25, I0yy = 1e308/12 * 1e20
    //   overflows. Most M: 12 * DBL_MAX / (1e20 + 0.36) = 2.157e289, rounded down.
    QTest::newRow("mass whose I0 overflows") << QStringList{R"("size": [1, 0.6, 0.5], "mass": 2,)", R"("size": [1e10, 0.6, 0.5], "mass": 1e308,)"}
        << none << 2 << QStringList{"bodies[0].mass: 1e+308 makes I0 overflow (I0 = M/12 (a\u00b2 + c\u00b2) exceeds the largest double); "
                                    "for this size the mass must be at most 2.1e+289 kg"} << none;
    //   a = 1e200: a² = 1e400 overflows; every edge <= sqrt(DBL_MAX / 2) = 9.48e153.
    QTest::newRow("size whose squares overflow") << QStringList{"[1, 0.6, 0.5]", "[1e200, 0.6, 0.5]"} << none << 2
        << QStringList{"bodies[0].size: edges [1e+200, 0.6, 0.5] make a\u00b2 + c\u00b2 overflow, so I0 cannot be computed; "
                       "every edge must be at most 9.4e+153 m"} << none;
    //   b = 1e-200, c = 1e-170: b² and c² both round to 0 (below 4.9e-324).
    QTest::newRow("size whose squares underflow") << QStringList{"[1, 0.6, 0.5]", "[1, 1e-200, 1e-170]"} << none << 2
        << QStringList{"bodies[0].size: edges [1, 1e-200, 1e-170] make b\u00b2 + c\u00b2 underflow to 0, so I0 would have a zero "
                       "entry; one of those two edges must be at least 1.5e-154 m"} << none;
    //   Body b as a cube of edge 1e153 and M = 60: I0 = 60/12 (1e306 + 1e306) = 1e307 on
    //   the diagonal, so L0 = 1e307 * 100 overflows. Most |omega0|: DBL_MAX / (6 * 1e307)
    //   = 2.996, rounded down: 2.9, which loads (L0 = 2.9e307; limitLoads, since the run
    //   itself then stops at t = 0: |L0|^2 of the diagnostics overflows, exit 3).
    const QString bodyB = R"("size": [1, 1, 1], "mass": 1, "position": [3, 0, 0])";
    QTest::newRow("angular velocity whose L0 overflows")
        << QStringList{bodyB, R"("size": [1e153, 1e153, 1e153], "mass": 60, "position": [3, 0, 0], "angular_velocity": [0, 0, 100])"}
        << none << 2 << QStringList{"bodies[1].angular_velocity: L0 = I(r0) \u03c90 overflows (|\u03c90| = 100 rad/s, I0 up to 1e+307 kg m\u00b2); "
                                    "for this body |\u03c90| must be at most 2.9 rad/s"} << none;
    //   p0 - x0 = -1e308 - 1e308 = -2e308 overflows.
    QTest::newRow("probe offset overflows")
        << QStringList{R"("mass": 1, "position": [3, 0, 0])", R"("mass": 1, "position": [1e308, 0, 0])", R"("point": [3.5, 0, 0])", R"("point": [-1e308, 0, 0])"}
        << none << 2 << QStringList{"probes[0].point: its offset p0 \u2212 x0 from the centre of body \"b\" overflows (p0 = [-1e+308, 0, 0], x0 = [1e+308, 0, 0])"}
        << none;
    //   t = steps h = 1e9 * 1e300 = 1e309 overflows; most h: DBL_MAX / 2 / 1e9 = 8.99e298.
    QTest::newRow("end time overflows") << QStringList{R"("dt": 0.1, "steps": 2)", R"("dt": 1e300, "steps": 1000000000)"} << none << 2
        << QStringList{"dt: 1e+300 s makes the end time steps \u00b7 h overflow; for 1000000000 steps h must be at most 8.9e+298 s"} << none;
    // Orientation and normals: normalised by their length, which must neither overflow
    // (the axis [1e308, 1e308, 0] once became the identity) nor round to 0.
    QTest::newRow("axis whose length overflows") << QStringList{"[0, 0, 1]", "[1e308, 1e308, 0]"} << none << 2
        << QStringList{"bodies[0].orientation.axis: its length overflows (the sum of the squares exceeds the largest double), so it cannot be normalised"}
        << none;
    QTest::newRow("axis whose length underflows") << QStringList{"[0, 0, 1]", "[1e-200, 0, 0]"} << none << 2
        << QStringList{"bodies[0].orientation.axis: its length underflows (the sum of the squares rounds to 0)"} << none;
    // Negative control: 1e-150 squares to 1e-300, a normal double; [1e150, 0, 0] likewise.
    QTest::newRow("small axis loads") << QStringList{"[0, 0, 1]", "[0, 0, 1e-150]"} << none << 0 << none << none;
    QTest::newRow("large axis loads") << QStringList{"[0, 0, 1]", "[0, 0, 1e150]"} << none << 0 << none << none;
    QTest::newRow("quaternion whose length overflows")
        << QStringList{R"("axis": [0, 0, 1], "degrees": 90)", R"("quaternion": [1e200, 0, 0, 1e200])"} << none << 2
        << QStringList{"bodies[0].orientation.quaternion: its length overflows"} << none;
    QTest::newRow("degrees that overflow in radians") << QStringList{R"("degrees": 90)", R"("degrees": 1e308)"} << none << 2
        << QStringList{"bodies[0].orientation.degrees: overflows in the conversion to radians"} << none;
    QTest::newRow("plane normal whose length overflows")
        << QStringList{tail, R"("planes": [{"name": "g", "point": [0, -5, 0], "normal": [0, 1e300, 0]}], "probes")"} << none << 2
        << QStringList{"planes[0].normal: its length overflows"} << none;
}

void TestSceneValidation::strictInput()
{
    QFETCH(QStringList, edits);
    QFETCH(QStringList, options);
    QFETCH(int, status);
    QFETCH(QStringList, words);
    QFETCH(QStringList, absent);

    QString text = QString::fromUtf8(kBase);
    QVERIFY(edits.size() % 2 == 0);
    for (int i = 0; i < edits.size(); i += 2) {
        QVERIFY2(text.count(edits[i]) == 1, qPrintable("row edit must match once: " + edits[i]));
        text.replace(edits[i], edits[i + 1]);
    }
    const QString path = write(text.toUtf8());
    const Run r = runRbw(QStringList{"run", path} + options);
    const QString& err = r.err;
    QVERIFY2(r.exitCode == status, qPrintable(QStringLiteral("exit %1, expected %2: %3").arg(r.exitCode).arg(status).arg(err.left(2000))));
    if (status == 2) {
        QVERIFY2(r.out.isEmpty(), "nothing may be printed as a result");
        QVERIFY2(err.startsWith("rbw: " + path + ": "), qPrintable(err.left(2000)));
    } else {
        QVERIFY2(err.isEmpty(), qPrintable(err.left(2000)));
    }
    // However long the input, a message is a few lines of text.
    QVERIFY2(err.size() < 1000, qPrintable(QStringLiteral("%1 characters on stderr").arg(err.size())));
    for (const QString& w : words) {
        QVERIFY2(err.contains(w), qPrintable("expected \"" + w + "\" in: " + err));
    }
    for (const QString& w : absent) {
        QVERIFY2(!err.contains(w), qPrintable("did not expect \"" + w.left(60) + "\" in: " + err));
    }
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
