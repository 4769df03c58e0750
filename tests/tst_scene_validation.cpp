// Every bad scene input is refused before anything runs: rbw exits with status 2 and
// its message names the file, the JSON path of the field and the reason
// (docs/scene-format.md). One data row per kind of bad input, run through the real
// rbw binary, plus a negative control: the valid base scene runs with status 0.
//
// The rules live in one place, physics' validate(); the loader only checks the file's
// structure. sameRuleInCodeAndFile proves it: each row breaks one rule once in the
// scene file and once in a SceneDef built in code, and both routes must report exactly
// the same "path: reason" lines.
#include <QProcess>
#include <QTemporaryDir>
#include "physics/integrator_registry.h"
#include "tests/test_support.h"

#include <QtTest>

#include <functional>
#include <limits>
#include <numbers>

// Breaks one rule in a SceneDef built in code.
using SceneEdit = std::function<void(rbw::SceneDef&)>;
Q_DECLARE_METATYPE(SceneEdit)

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
using rbw::Vec3;

// kBase, built in code.
rbw::SceneDef codeBase()
{
    rbw::SceneDef s;
    s.name = "validation base";
    s.dt = 0.1;
    s.steps = 2;
    s.integrator = "explicit-euler";
    s.g_W = Vec3(0, -9.81, 0);
    rbw::BodyDef a;
    a.name = "a";
    a.size = Vec3(1, 0.6, 0.5);
    a.mass = 2;
    a.q0_WB = rbw::Quat(Eigen::AngleAxisd(std::numbers::pi / 2, Vec3::UnitZ()));
    rbw::BodyDef b;
    b.name = "b";
    b.size = Vec3(1, 1, 1);
    b.mass = 1;
    b.x0_W = Vec3(3, 0, 0);
    s.bodies = {a, b};
    rbw::ForceDef f;
    f.body = 0;
    f.p_W = Vec3(0.3, 0.5, 0.25);
    f.f_W = Vec3(1, 1, 0);
    s.forces = {f};
    rbw::ProbeDef p;
    p.body = 1;
    p.p0_W = Vec3(3.5, 0, 0);
    s.probes = {p};
    return s;
}

rbw::PlaneDef plane(const std::string& name, const Vec3& n = Vec3::UnitY())
{
    return rbw::PlaneDef{name, Vec3::Zero(), n};
}

// A pair as a scene built in code names it: by name, resolved as the loader does.
rbw::PairOverride pair(const rbw::SceneDef& s, const std::string& first, const std::string& second,
                       std::optional<double> c, std::optional<double> mu)
{
    rbw::PairOverride o;
    o.nameA = first;
    o.nameB = second;
    o.bodyA = s.bodyIndex(first);
    o.bodyB = s.bodyIndex(second);
    o.planeB = o.bodyB < 0 ? s.planeIndex(second) : -1;
    o.restitution = c;
    o.friction = mu;
    return o;
}

QStringList lines(const std::vector<rbw::SceneIssue>& issues)
{
    QStringList out;
    for (const rbw::SceneIssue& i : issues) out << QString::fromStdString(i.path + ": " + i.reason);
    return out;
}

} // namespace

class TestSceneValidation : public QObject {
    Q_OBJECT
private slots:
    void validBaseRuns();
    void badScene_data();
    void badScene();
    void badOption_data();
    void badOption();
    void codeBaseIsFileBase();
    void sameRuleInCodeAndFile_data();
    void sameRuleInCodeAndFile();
    void codeOnlyRules_data();
    void codeOnlyRules();

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

// The code-built base is the file's base: both valid, the same numbers.
void TestSceneValidation::codeBaseIsFileBase()
{
    const rbw::SceneLoadResult loaded = rbw::parseScene(kBase, "base.json");
    QVERIFY2(loaded.ok(), qPrintable(loaded.errors.join('\n')));
    const rbw::SceneDef code = codeBase();
    QVERIFY(rbw::validate(code).empty());
    const rbw::SceneDef& file = *loaded.scene;
    QCOMPARE(file.bodies.size(), code.bodies.size());
    for (size_t i = 0; i < code.bodies.size(); ++i) {
        QCOMPARE(file.bodies[i].name, code.bodies[i].name);
        QVERIFY(file.bodies[i].size == code.bodies[i].size && file.bodies[i].x0_W == code.bodies[i].x0_W);
        QVERIFY(file.bodies[i].q0_WB.isApprox(code.bodies[i].q0_WB, 1e-15));
    }
    QCOMPARE(file.forces.size(), code.forces.size());
    QCOMPARE(file.forces[0].body, code.forces[0].body);
    QCOMPARE(file.forces[0].toStep, code.forces[0].toStep);
    QCOMPARE(file.probes[0].body, code.probes[0].body);
}

void TestSceneValidation::sameRuleInCodeAndFile_data()
{
    using rbw::SceneDef;
    QTest::addColumn<QString>("from");          // fragment of kBase to replace
    QTest::addColumn<QString>("to");
    QTest::addColumn<SceneEdit>("edit");        // the same break in codeBase()
    QTest::addColumn<QStringList>("expected");  // every "path: reason", in order

    const QString known = QString::fromStdString(rbw::integratorNames());
    const char* const bodyB = R"("mass": 1, "position": [3, 0, 0])";
    const char* const tail = R"("probes")";     // insert top-level keys before "probes"

    // Names: unique among bodies and planes, and every name that refers to a body exists.
    QTest::newRow("body name twice") << "[3, 0, 0] }" << R"([3, 0, 0] }, { "name": "a", "size": [1, 1, 1], "mass": 1 })"
        << SceneEdit([](SceneDef& s) { rbw::BodyDef b; b.name = "a"; s.bodies.push_back(b); })
        << QStringList{R"(bodies[2].name: duplicate body name "a")"};
    QTest::newRow("plane named like a body") << tail << R"("planes": [{"name": "b", "point": [0, 0, 0], "normal": [0, 1, 0]}], "probes")"
        << SceneEdit([](SceneDef& s) { s.planes.push_back(plane("b")); })
        << QStringList{R"(planes[0].name: duplicate name "b" (bodies and planes share names))"};
    QTest::newRow("plane name twice") << tail
        << R"("planes": [{"name": "g", "point": [0, 0, 0], "normal": [0, 1, 0]}, {"name": "g", "point": [0, 0, 0], "normal": [1, 0, 0]}], "probes")"
        << SceneEdit([](SceneDef& s) { s.planes = {plane("g"), plane("g", Vec3::UnitX())}; })
        << QStringList{R"(planes[1].name: duplicate name "g" (bodies and planes share names))"};
    QTest::newRow("force on unknown body") << R"({ "body": "a", "point")" << R"({ "body": "ghost", "point")"
        << SceneEdit([](SceneDef& s) { s.forces[0].bodyName = "ghost"; s.forces[0].body = s.bodyIndex("ghost"); })
        << QStringList{R"(forces[0].body: no body named "ghost" (bodies: a, b))"};
    QTest::newRow("torque on unknown body") << tail << R"("torques": [{"body": "z", "torque": [0, 1, 0]}], "probes")"
        << SceneEdit([](SceneDef& s) {
               rbw::TorqueDef t;
               t.bodyName = "z";
               t.body = s.bodyIndex("z");
               t.q_W = Vec3(0, 1, 0);
               t.toStep = std::numeric_limits<long>::max();   // the file's default: for ever
               s.torques.push_back(t);
           })
        << QStringList{R"(torques[0].body: no body named "z" (bodies: a, b))"};
    QTest::newRow("push on unknown body") << tail << R"("push": {"body": "q"}, "probes")"
        << SceneEdit([](SceneDef& s) { s.push.bodyName = "q"; s.push.body = s.bodyIndex("q"); })
        << QStringList{R"(push.body: no body named "q" (bodies: a, b))"};
    QTest::newRow("probe on unknown body") << R"({ "body": "b", "point")" << R"({ "body": "c", "point")"
        << SceneEdit([](SceneDef& s) { s.probes[0].bodyName = "c"; s.probes[0].body = s.bodyIndex("c"); })
        << QStringList{R"(probes[0].body: no body named "c" (bodies: a, b))"};

    // A fixed body is at rest.
    QTest::newRow("fixed body with v") << bodyB << R"("fixed": true, "position": [3, 0, 0], "linear_velocity": [0, 1, 0])"
        << SceneEdit([](SceneDef& s) { s.bodies[1].fixed = true; s.bodies[1].v0_W = Vec3(0, 1, 0); })
        << QStringList{"bodies[1].linear_velocity: a fixed body cannot have a velocity; leave it out or give [0, 0, 0]"};
    QTest::newRow("fixed body with omega") << bodyB << R"("fixed": true, "position": [3, 0, 0], "angular_velocity": [0, 0, 1])"
        << SceneEdit([](SceneDef& s) { s.bodies[1].fixed = true; s.bodies[1].omega0_W = Vec3(0, 0, 1); })
        << QStringList{"bodies[1].angular_velocity: a fixed body cannot have a velocity; leave it out or give [0, 0, 0]"};

    // Coefficient ranges, scene-wide.
    QTest::newRow("restitution above 1") << tail << R"("restitution": 1.5, "probes")"
        << SceneEdit([](SceneDef& s) { s.restitution = 1.5; })
        << QStringList{"restitution: must be a number from 0 to 1, got 1.5"};
    QTest::newRow("restitution below 0") << tail << R"("restitution": -0.1, "probes")"
        << SceneEdit([](SceneDef& s) { s.restitution = -0.1; })
        << QStringList{"restitution: must be a number from 0 to 1, got -0.1"};
    QTest::newRow("friction below 0") << tail << R"("friction": -0.1, "probes")"
        << SceneEdit([](SceneDef& s) { s.friction = -0.1; })
        << QStringList{"friction: must be a finite number >= 0, got -0.1"};
    QTest::newRow("threshold below 0") << tail << R"("restitution_threshold": -2, "probes")"
        << SceneEdit([](SceneDef& s) { s.restitutionThreshold = -2; })
        << QStringList{"restitution_threshold: must be a finite number >= 0, got -2"};

    // Energy-jump settings.
    QTest::newRow("energy jump factor 0.5") << tail << R"("energy_jump": {"factor": 0.5}, "probes")"
        << SceneEdit([](SceneDef& s) { s.energyJumpFactor = 0.5; })
        << QStringList{"energy_jump.factor: must be 0 (off) or a finite number >= 1, got 0.5"};
    QTest::newRow("energy jump factor negative") << tail << R"("energy_jump": {"factor": -10}, "probes")"
        << SceneEdit([](SceneDef& s) { s.energyJumpFactor = -10; })
        << QStringList{"energy_jump.factor: must be 0 (off) or a finite number >= 1, got -10"};
    QTest::newRow("energy jump floor negative") << tail << R"("energy_jump": {"floor": -1e-9}, "probes")"
        << SceneEdit([](SceneDef& s) { s.energyJumpFloor = -1e-9; })
        << QStringList{"energy_jump.floor: must be a finite number >= 0, got -1e-09"};

    // Plane normals.
    QTest::newRow("zero plane normal") << tail << R"("planes": [{"name": "ground", "point": [0, 0, 0], "normal": [0, 0, 0]}], "probes")"
        << SceneEdit([](SceneDef& s) { s.planes.push_back(plane("ground", Vec3::Zero())); })
        << QStringList{"planes[0].normal: must not be the zero vector"};

    // Pairs: two different bodies (or a body and a plane) that exist, listed once,
    // overriding something within range.
    const char* const ground = R"("planes": [{"name": "ground", "point": [0, 0, 0], "normal": [0, 1, 0]}], )";
    QTest::newRow("pair first name unknown") << tail << R"("pairs": [{"bodies": ["zz", "b"], "friction": 0.5}], "probes")"
        << SceneEdit([](SceneDef& s) { s.pairs.push_back(pair(s, "zz", "b", {}, 0.5)); })
        << QStringList{R"(pairs[0].bodies[0]: no body named "zz" (bodies: a, b))"};
    QTest::newRow("pair plane first") << tail << QString(ground) + R"("pairs": [{"bodies": ["ground", "a"], "friction": 0.5}], "probes")"
        << SceneEdit([](SceneDef& s) { s.planes.push_back(plane("ground")); s.pairs.push_back(pair(s, "ground", "a", {}, 0.5)); })
        << QStringList{R"(pairs[0].bodies[0]: no body named "ground" (bodies: a, b); "ground" is a plane, and a plane comes second: ["body", "ground"])"};
    QTest::newRow("pair second name unknown") << tail << R"("pairs": [{"bodies": ["a", "zz"], "restitution": 0.5}], "probes")"
        << SceneEdit([](SceneDef& s) { s.pairs.push_back(pair(s, "a", "zz", 0.5, {})); })
        << QStringList{R"(pairs[0].bodies[1]: no body or plane named "zz" (bodies: a, b; planes: none))"};
    QTest::newRow("pair one body twice") << tail << R"("pairs": [{"bodies": ["a", "a"], "restitution": 0.5}], "probes")"
        << SceneEdit([](SceneDef& s) { s.pairs.push_back(pair(s, "a", "a", 0.5, {})); })
        << QStringList{R"(pairs[0].bodies: names "a" twice; a pair needs two different bodies)"};
    QTest::newRow("pair listed twice") << tail
        << R"("pairs": [{"bodies": ["a", "b"], "friction": 0.5}, {"bodies": ["b", "a"], "restitution": 0.2}], "probes")"
        << SceneEdit([](SceneDef& s) { s.pairs = {pair(s, "a", "b", {}, 0.5), pair(s, "b", "a", 0.2, {})}; })
        << QStringList{"pairs[1].bodies: this pair is already listed as pairs[0]; give each pair once"};
    QTest::newRow("body-plane pair listed twice") << tail
        << QString(ground) + R"("pairs": [{"bodies": ["b", "ground"], "friction": 0.5}, {"bodies": ["a", "ground"], "friction": 0.5}, {"bodies": ["b", "ground"], "restitution": 0}], "probes")"
        << SceneEdit([](SceneDef& s) {
               s.planes.push_back(plane("ground"));
               s.pairs = {pair(s, "b", "ground", {}, 0.5), pair(s, "a", "ground", {}, 0.5), pair(s, "b", "ground", 0.0, {})};
           })
        << QStringList{"pairs[2].bodies: this pair is already listed as pairs[0]; give each pair once"};
    QTest::newRow("pair without coefficients") << tail << R"("pairs": [{"bodies": ["a", "b"]}], "probes")"
        << SceneEdit([](SceneDef& s) { s.pairs.push_back(pair(s, "a", "b", {}, {})); })
        << QStringList{R"(pairs[0]: give "restitution", "friction" or both)"};
    QTest::newRow("pair restitution above 1") << tail << R"("pairs": [{"bodies": ["a", "b"], "restitution": 2}], "probes")"
        << SceneEdit([](SceneDef& s) { s.pairs.push_back(pair(s, "a", "b", 2.0, {})); })
        << QStringList{"pairs[0].restitution: must be a number from 0 to 1, got 2"};
    // -1 once meant "not overridden" inside PairOverride; from a file it is just out of range.
    QTest::newRow("pair restitution -1") << tail << R"("pairs": [{"bodies": ["a", "b"], "restitution": -1, "friction": 0.1}], "probes")"
        << SceneEdit([](SceneDef& s) { s.pairs.push_back(pair(s, "a", "b", -1.0, 0.1)); })
        << QStringList{"pairs[0].restitution: must be a number from 0 to 1, got -1"};
    QTest::newRow("pair friction below 0") << tail << R"("pairs": [{"bodies": ["a", "b"], "friction": -0.5}], "probes")"
        << SceneEdit([](SceneDef& s) { s.pairs.push_back(pair(s, "a", "b", {}, -0.5)); })
        << QStringList{"pairs[0].friction: must be a finite number >= 0, got -0.5"};

    // Integrator names, the scene's and a body's own.
    QTest::newRow("unknown integrator") << R"("integrator": "explicit-euler")" << R"("integrator": "rk5")"
        << SceneEdit([](SceneDef& s) { s.integrator = "rk5"; })
        << QStringList{R"(integrator: unknown integrator "rk5"; known: )" + known};
    QTest::newRow("unknown body integrator") << bodyB << R"("mass": 1, "position": [3, 0, 0], "integrator": "rk5")"
        << SceneEdit([](SceneDef& s) { s.bodies[1].integrator = "rk5"; })
        << QStringList{R"(bodies[1].integrator: unknown integrator "rk5"; known: )" + known};

    // Several problems at once, each named.
    QTest::newRow("all at once") << R"("dt": 0.1, "steps": 2)" << R"("dt": -1, "steps": 2, "friction": -1, "restitution_threshold": -1)"
        << SceneEdit([](SceneDef& s) { s.dt = -1; s.friction = -1; s.restitutionThreshold = -1; })
        << QStringList{"dt: must be a finite number > 0, got -1", "friction: must be a finite number >= 0, got -1",
                       "restitution_threshold: must be a finite number >= 0, got -1"};
}

void TestSceneValidation::sameRuleInCodeAndFile()
{
    QFETCH(QString, from);
    QFETCH(QString, to);
    QFETCH(SceneEdit, edit);
    QFETCH(QStringList, expected);

    // The file route: the loader, then validate().
    QString text = QString::fromUtf8(kBase);
    QVERIFY2(text.count(from) == 1, qPrintable("row edit must match once: " + from));
    text.replace(from, to);
    const rbw::SceneLoadResult loaded = rbw::parseScene(text.toUtf8(), "scene.json");
    QVERIFY(!loaded.ok());
    QStringList fromFile;
    for (const QString& e : loaded.errors) {
        QVERIFY2(e.startsWith("scene.json: "), qPrintable(e));
        fromFile << e.mid(QString("scene.json: ").size());
    }
    QCOMPARE(fromFile, expected);

    // The code route: validate() alone.
    rbw::SceneDef scene = codeBase();
    edit(scene);
    QCOMPARE(lines(rbw::validate(scene)), expected);
}

// Rules a file cannot break, because the loader never builds such a SceneDef, but a
// scene built in code can.
void TestSceneValidation::codeOnlyRules_data()
{
    using rbw::SceneDef;
    QTest::addColumn<SceneEdit>("edit");
    QTest::addColumn<QStringList>("expected");
    QTest::newRow("force body index") << SceneEdit([](SceneDef& s) { s.forces[0].body = 5; })
                                      << QStringList{"forces[0].body: names no body of the scene (index 5; bodies: a, b)"};
    QTest::newRow("probe body -1") << SceneEdit([](SceneDef& s) { s.probes[0].body = -1; })
                                   << QStringList{"probes[0].body: names no body of the scene (index -1; bodies: a, b)"};
    QTest::newRow("push body index") << SceneEdit([](SceneDef& s) { s.push.body = 2; })
                                     << QStringList{"push.body: names no body of the scene (index 2; bodies: a, b)"};
    QTest::newRow("plane normal not unit") << SceneEdit([](SceneDef& s) { s.planes.push_back(plane("g", Vec3(0, 2, 0))); })
                                           << QStringList{"planes[0].normal: must be a unit vector, got length 2"};
    QTest::newRow("pair plane index") << SceneEdit([](SceneDef& s) {
                                             rbw::PairOverride o;
                                             o.bodyA = 0;
                                             o.planeB = 3;
                                             o.friction = 0.2;
                                             s.pairs.push_back(o);
                                         })
                                      << QStringList{"pairs[0].bodies[1]: names no plane of the scene (index 3; planes: none)"};
    QTest::newRow("no pushes") << SceneEdit([](SceneDef& s) { s.push.magnitude = -1; })   // ignored: no push body
                               << QStringList{};
}

void TestSceneValidation::codeOnlyRules()
{
    QFETCH(SceneEdit, edit);
    QFETCH(QStringList, expected);
    rbw::SceneDef scene = codeBase();
    edit(scene);
    QCOMPARE(lines(rbw::validate(scene)), expected);
}

QTEST_GUILESS_MAIN(TestSceneValidation)
#include "tst_scene_validation.moc"
