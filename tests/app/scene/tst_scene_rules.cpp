// The loader and validate() in process: the raw scan for repeated keys, what a message
// shows of a name (messageText), names resolved through one hash map, a limit a
// message prints loads, and the rules in one place.
//
// The rules live in one place, physics' validate(); the loader only checks the file's
// structure. sameRuleInCodeAndFile proves it: each row breaks one rule once in the
// scene file and once in a SceneDef built in code, and both routes must report exactly
// the same "path: reason" lines. codeOnlyRules: the rules only a scene built in code
// can break. Bad files through the real rbw binary are tst_scene_validation.
#include "physics/engine/integrator_registry.h"
#include "tests/app/scene/validation_base.h"
#include "tests/test_support.h"

#include <QtTest>

#include <limits>
#include <numbers>

namespace {

using rbw::Vec3;
using validation_base::codeBase;
using validation_base::kBase;
using validation_base::lines;
using validation_base::pair;
using validation_base::plane;

} // namespace

class TestSceneRules : public QObject {
    Q_OBJECT
private slots:
    void duplicateKeys_data();
    void duplicateKeys();
    void messageText_data();
    void messageText();
    void manyNamesResolve();
    void limitLoads();
    void codeBaseIsFileBase();
    void sameRuleInCodeAndFile_data();
    void sameRuleInCodeAndFile();
    void codeOnlyRules_data();
    void codeOnlyRules();
};

// The raw scan through parseScene: the first error line (empty: the text loads). It
// must find a repeated key at any depth, and only there: not the same key in two
// objects, not text inside a string.
void TestSceneRules::duplicateKeys_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("expected");
    const QByteArray body = R"({"name": "a", "size": [1, 1, 1], "mass": 1})";
    QTest::newRow("same key in two objects") << QByteArray(R"({"dt": 1, "bodies": [)" + body + "," +
                                                           R"({"name": "b", "size": [1, 1, 1], "mass": 1}]})")
                                             << QString();
    QTest::newRow("key-like text in a string") << QByteArray(R"({"dt": 1, "name": "{\"dt\": 1, \"dt\": 2}", "bodies": [)" + body + "]}")
                                               << QString();
    QTest::newRow("key and value equal") << QByteArray(R"({"dt": 1, "name": "dt", "bodies": [)" + body + "]}") << QString();
    QTest::newRow("top level") << QByteArray(R"({"dt": 1, "bodies": [)" + body + R"(], "dt": 2})")
                               << R"(s.json: dt: duplicate key "dt" (first at line 1, column 2, again at line 1, column 68); a key may appear only once in an object)";
    QTest::newRow("escaped quote in a key") << QByteArray(R"({"dt": 1, "a\"b": 1, "a\"b": 2, "bodies": [)" + body + "]}")
                                            << R"(s.json: a\"b: duplicate key "a\"b" (first at line 1, column 11, again at line 1, column 22); a key may appear only once in an object)";
    QTest::newRow("in an unknown object") << QByteArray(R"({"dt": 1, "zz": {"q": [{}, {"k": 1, "k": 2}]}, "bodies": [)" + body + "]}")
                                          << R"(s.json: zz.q[1].k: duplicate key "k" (first at line 1, column 29, again at line 1, column 37); a key may appear only once in an object)";
    // QJsonDocument skips a UTF-8 byte order mark; the scan must too (columns count bytes).
    QTest::newRow("after a byte order mark") << QByteArray("\xef\xbb\xbf{\"dt\": 1, \"dt\": 2, \"bodies\": [" + body + "]}")
                                             << R"(s.json: dt: duplicate key "dt" (first at line 1, column 5, again at line 1, column 14); a key may appear only once in an object)";
    QTest::newRow("across lines") << QByteArray("{\"dt\": 1,\n \"bodies\": [" + body + "],\n\n   \"bodies\": []}")
                                  << R"(s.json: bodies: duplicate key "bodies" (first at line 2, column 2, again at line 4, column 4); a key may appear only once in an object)";
}

void TestSceneRules::duplicateKeys()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, expected);
    const rbw::SceneLoadResult r = rbw::parseScene(json, "s.json");
    QCOMPARE(r.errors.isEmpty() ? QString() : r.errors.first(), expected);
    QCOMPARE(r.ok(), expected.isEmpty());
}

// physics' messageText(): what a message shows of a name or key.
void TestSceneRules::messageText_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QByteArray>("shown");
    QTest::newRow("plain") << QByteArray("box") << QByteArray("box");
    QTest::newRow("NUL") << QByteArray("a\0b", 3) << QByteArray("a\\u0000b");
    QTest::newRow("ESC, tab, newline, DEL") << QByteArray("\x1b[1m\t\n\x7f") << QByteArray("\\u001b[1m\\u0009\\u000a\\u007f");
    QTest::newRow("quote, backslash") << QByteArray("a\"b\\") << QByteArray("a\\\"b\\\\");
    QTest::newRow("C1 control U+0085") << QByteArray("a\xc2\x85") << QByteArray("a\\u0085");
    QTest::newRow("line separator U+2028") << QByteArray("a\xe2\x80\xa8") << QByteArray("a\\u2028");
    QTest::newRow("bidi override U+202E") << QByteArray("\xe2\x80\xae") << QByteArray("\\u202e");
    QTest::newRow("not UTF-8") << QByteArray("a\xff") << QByteArray("a\\xff");
    QTest::newRow("truncated UTF-8") << QByteArray("a\xc3") << QByteArray("a\\xc3");
    QTest::newRow("letters kept") << QByteArray("\xc3\xa9\xe2\x86\x92\xf0\x9f\x99\x82") << QByteArray("\xc3\xa9\xe2\x86\x92\xf0\x9f\x99\x82");
    QTest::newRow("40 characters kept") << QByteArray(40, 'x') << QByteArray(40, 'x');
    QTest::newRow("41 cut to 40") << QByteArray(41, 'x') << QByteArray(40, 'x') + "\xe2\x80\xa6";
    // Counted in characters, not bytes: 41 two-byte letters are cut after the 40th.
    QByteArray e41;
    for (int i = 0; i < 41; ++i) e41 += "\xc3\xa9";
    QTest::newRow("41 letters é") << e41 << e41.left(80) + "\xe2\x80\xa6";
}

void TestSceneRules::messageText()
{
    QFETCH(QByteArray, text);
    QFETCH(QByteArray, shown);
    QCOMPARE(QByteArray::fromStdString(rbw::messageText(std::string(text.constData(), text.size()))), shown);
}

// A limit a message prints is itself allowed: loaded (not run) through parseScene.
void TestSceneRules::limitLoads()
{
    QString text = QString::fromUtf8(kBase);
    text.replace(R"("size": [1, 1, 1], "mass": 1, "position": [3, 0, 0])",
                 R"("size": [1e153, 1e153, 1e153], "mass": 60, "position": [3, 0, 0], "angular_velocity": [0, 0, 2.9])");
    const rbw::SceneLoadResult r = rbw::parseScene(text.toUtf8(), "limit.json");
    QVERIFY2(r.ok(), qPrintable(r.errors.join('\n')));
    // L0 = I0 omega0 = 1e307 * 2.9, finite (hand value 2.9e307, to the rounding of I0).
    const rbw::MassProperties mp = rbw::massProperties(r.scene->bodies[1]);
    const rbw::BodyState s0 = rbw::initialState(r.scene->bodies[1], mp, rbw::InertiaConvention::Standard);
    QVERIFY(std::abs(s0.L_W.z() / 2.9e307 - 1.0) < 1e-12);
}

// Names resolve through one hash map (SceneNames): 5000 bodies, each force naming the
// body at the other end of the list, a pair per plane; a name used twice resolves to
// its first body, as SceneDef::bodyIndex() does.
void TestSceneRules::manyNamesResolve()
{
    constexpr int n = 5000;
    QByteArray text = R"({"dt": 0.01, "box_collisions": false, "bodies": [)";
    for (int i = 0; i < n; ++i) {
        text += (i ? "," : "") + QByteArray(R"({"name": "b)") + QByteArray::number(i) +
                R"(", "size": [1, 1, 1], "mass": 1})";
    }
    text += R"(], "planes": [)";
    for (int i = 0; i < n; ++i) {
        text += (i ? "," : "") + QByteArray(R"({"name": "p)") + QByteArray::number(i) +
                R"(", "point": [0, -10, 0], "normal": [0, 1, 0]})";
    }
    text += R"(], "forces": [)";
    for (int i = 0; i < n; ++i) {
        text += (i ? "," : "") + QByteArray(R"({"body": "b)") + QByteArray::number(n - 1 - i) +
                R"(", "point": [0, 0, 0], "force": [1, 0, 0]})";
    }
    text += R"(], "pairs": [)";
    for (int i = 0; i < n; ++i) {
        text += (i ? "," : "") + QByteArray(R"({"bodies": ["b)") + QByteArray::number(i) + R"(", "p)" +
                QByteArray::number(n - 1 - i) + R"("], "friction": 0.5})";
    }
    text += "]}";
    const rbw::SceneLoadResult r = rbw::parseScene(text, "many.json");
    QVERIFY2(r.ok(), qPrintable(r.errors.join('\n')));
    for (int i = 0; i < n; ++i) {
        QCOMPARE(r.scene->forces[i].body, n - 1 - i);
        QCOMPARE(r.scene->pairs[i].bodyA, i);
        QCOMPARE(r.scene->pairs[i].planeB, n - 1 - i);
    }
    // A name used twice: SceneNames and bodyIndex() both give the first.
    rbw::SceneDef s = codeBase();
    s.bodies.push_back(s.bodies[0]);   // a second "a", index 2
    QCOMPARE(rbw::SceneNames(s).body("a"), 0);
    QCOMPARE(s.bodyIndex("a"), 0);
    QCOMPARE(rbw::SceneNames(s).body("zz"), -1);
    QCOMPARE(rbw::SceneNames(s).plane("a"), -1);
}

// The code-built base is the file's base: both valid, the same numbers.
void TestSceneRules::codeBaseIsFileBase()
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

void TestSceneRules::sameRuleInCodeAndFile_data()
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

    // Limits and derived quantities (the hand derivations are at strictInput_data).
    QTest::newRow("steps above 10^9") << R"("steps": 2)" << R"("steps": 9e15)"
        << SceneEdit([](SceneDef& s) { s.steps = 9'000'000'000'000'000L; })
        << QStringList{"steps: must be at most 1000000000 (10^9), got 9000000000000000"};
    QTest::newRow("end time overflows") << R"("dt": 0.1, "steps": 2)" << R"("dt": 1e300, "steps": 1000000000)"
        << SceneEdit([](SceneDef& s) { s.dt = 1e300; s.steps = 1'000'000'000L; })
        << QStringList{"dt: 1e+300 s makes the end time steps \u00b7 h overflow; for 1000000000 steps h must be at most 8.9e+298 s"};
    QTest::newRow("empty bodies") << R"("bodies": [)" << R"("bodies": [], "unused": [)"
        << SceneEdit([](SceneDef& s) { s.bodies.clear(); })   // the force and probe still name bodies 0 and 1
        << QStringList{"bodies: must list at least one body; a scene without a body has nothing to simulate"};
    QTest::newRow("mass whose I0^-1 overflows") << R"("mass": 2,)" << R"("mass": 1e-308,)"
        << SceneEdit([](SceneDef& s) { s.bodies[0].mass = 1e-308; })
        << QStringList{"bodies[0].mass: 1e-308 makes I0^-1 overflow (I0 = M/12 (b\u00b2 + c\u00b2) = 5.08e-310, too small for its "
                       "inverse to be a finite double); for this size the mass must be at least 1.1e-307 kg"};
    QTest::newRow("mass whose I0 overflows") << R"("size": [1, 0.6, 0.5], "mass": 2,)" << R"("size": [1e10, 0.6, 0.5], "mass": 1e308,)"
        << SceneEdit([](SceneDef& s) { s.bodies[0].size = Vec3(1e10, 0.6, 0.5); s.bodies[0].mass = 1e308; })
        << QStringList{"bodies[0].mass: 1e+308 makes I0 overflow (I0 = M/12 (a\u00b2 + c\u00b2) exceeds the largest double); "
                       "for this size the mass must be at most 2.1e+289 kg"};
    QTest::newRow("size whose squares overflow") << "[1, 0.6, 0.5]" << "[1e200, 0.6, 0.5]"
        << SceneEdit([](SceneDef& s) { s.bodies[0].size = Vec3(1e200, 0.6, 0.5); })
        << QStringList{"bodies[0].size: edges [1e+200, 0.6, 0.5] make a\u00b2 + c\u00b2 overflow, so I0 cannot be computed; "
                       "every edge must be at most 9.4e+153 m"};
    QTest::newRow("angular velocity whose L0 overflows") << R"("size": [1, 1, 1], "mass": 1, "position": [3, 0, 0])"
        << R"("size": [1e153, 1e153, 1e153], "mass": 60, "position": [3, 0, 0], "angular_velocity": [0, 0, 100])"
        << SceneEdit([](SceneDef& s) {
               s.bodies[1].size = Vec3::Constant(1e153);
               s.bodies[1].mass = 60;
               s.bodies[1].omega0_W = Vec3(0, 0, 100);
           })
        << QStringList{"bodies[1].angular_velocity: L0 = I(r0) \u03c90 overflows (|\u03c90| = 100 rad/s, I0 up to 1e+307 kg m\u00b2); "
                       "for this body |\u03c90| must be at most 2.9 rad/s"};

    // Several problems at once, each named.
    QTest::newRow("all at once") << R"("dt": 0.1, "steps": 2)" << R"("dt": -1, "steps": 2, "friction": -1, "restitution_threshold": -1)"
        << SceneEdit([](SceneDef& s) { s.dt = -1; s.friction = -1; s.restitutionThreshold = -1; })
        << QStringList{"dt: must be a finite number > 0, got -1", "friction: must be a finite number >= 0, got -1",
                       "restitution_threshold: must be a finite number >= 0, got -1"};
}

void TestSceneRules::sameRuleInCodeAndFile()
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
void TestSceneRules::codeOnlyRules_data()
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
    // An enumeration cast from an integer outside its words (a scene built in code):
    // the message lists the words the file format spells (physics/engine/scene_words.h).
    QTest::newRow("inertia convention out of range")
        << SceneEdit([](SceneDef& s) { s.inertiaConvention = static_cast<rbw::InertiaConvention>(7); })
        << QStringList{"inertia_convention: must be \"standard\" or \"course-template\""};
    QTest::newRow("body's inertia convention out of range")
        << SceneEdit([](SceneDef& s) { s.bodies[1].inertiaConvention = static_cast<rbw::InertiaConvention>(2); })
        << QStringList{"bodies[1].inertia_convention: must be \"standard\" or \"course-template\""};
    QTest::newRow("plane contacts out of range")
        << SceneEdit([](SceneDef& s) { s.planeContacts = static_cast<rbw::PlaneContactMode>(2); })
        << QStringList{"plane_contacts: must be \"per-point\" or \"average\""};
    QTest::newRow("no pushes") << SceneEdit([](SceneDef& s) { s.push.magnitude = -1; })   // ignored: no push body
                               << QStringList{};
    // initialState() normalises r0 by |q|: |q|^2 must neither overflow nor round to 0
    // (the loader gives a unit quaternion, and refuses these itself).
    QTest::newRow("quaternion length overflows") << SceneEdit([](SceneDef& s) { s.bodies[0].q0_WB = rbw::Quat(1e200, 0, 0, 1e200); })
        << QStringList{"bodies[0].orientation: the quaternion's length overflows (|q|^2 exceeds the largest double), "
                       "so it cannot be normalised; give it a length near 1"};
    QTest::newRow("quaternion length underflows") << SceneEdit([](SceneDef& s) { s.bodies[0].q0_WB = rbw::Quat(1e-200, 0, 0, 0); })
        << QStringList{"bodies[0].orientation: the quaternion's length underflows (|q|^2 rounds to 0), so it cannot "
                       "be normalised; give it a length near 1"};
    // The same message as strictInput's "probe offset overflows" row from a file.
    QTest::newRow("probe offset overflows") << SceneEdit([](SceneDef& s) {
                                                   s.bodies[1].x0_W = Vec3(1e308, 0, 0);
                                                   s.probes[0].p0_W = Vec3(-1e308, 0, 0);
                                               })
        << QStringList{"probes[0].point: its offset p0 \u2212 x0 from the centre of body \"b\" overflows "
                       "(p0 = [-1e+308, 0, 0], x0 = [1e+308, 0, 0]); give a point nearer the body"};
    // A name with a control byte, 51 characters long: escaped, cut after 40.
    QTest::newRow("control byte in a long name") << SceneEdit([](SceneDef& s) {
                                                        s.bodies[0].name = std::string(1, '\x01') + std::string(50, 'x');
                                                        s.bodies[1].name = s.bodies[0].name;
                                                    })
        << QStringList{"bodies[1].name: duplicate body name \"\\u0001" + QString(39, QLatin1Char('x')) + "\u2026\""};
    // A message lists at most 10 names, then the count.
    QTest::newRow("long list of bodies") << SceneEdit([](SceneDef& s) {
                                                for (int i = 0; i < 20; ++i) {
                                                    rbw::BodyDef b;
                                                    b.name = "c";
                                                    b.name += std::to_string(i);   // not "c" + ...: g++ 12 -Wrestrict
                                                    s.bodies.push_back(b);
                                                }
                                                s.forces[0].body = 99;
                                            })
        << QStringList{"forces[0].body: names no body of the scene (index 99; bodies: a, b, c0, c1, c2, c3, c4, c5, c6, "
                       "c7, \u2026 (22 in all))"};
}

void TestSceneRules::codeOnlyRules()
{
    QFETCH(SceneEdit, edit);
    QFETCH(QStringList, expected);
    rbw::SceneDef scene = codeBase();
    edit(scene);
    QCOMPARE(lines(rbw::validate(scene)), expected);
}

QTEST_GUILESS_MAIN(TestSceneRules)
#include "tst_scene_rules.moc"
