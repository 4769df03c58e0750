// No non-finite number is ever printed (docs/cli.md, "Blow-up"; physics/engine/stages/checks.h).
// Through the real rbw binary: a corpus of scenes at the edge of the double range, each
// in JSON and CSV with --trace all, last and none, must exit with the stated status and
// message and print only finite numbers (the JSON parses, every number in it is finite
// and null stands only for a body; every CSV cell of a data row is a finite number).
// The same scanner passes on normal lesson runs and catches a doctored number (negative
// controls). And --trace all is streamed: 2000 steps give one valid document whose first
// steps equal, bit for bit, the trace of a short run that printed only its last step.
#include "physics/engine/stages/checks.h"
#include "physics/engine/world.h"
#include "tests/test_support.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <string>

namespace {

using rbw::test::runRbw;
using Run = rbw::test::RbwRun;

const QString kLesson3 = QStringLiteral(RBW_SOURCE_DIR "/lessons/03-two-box-collision/scene.json");

// The first problem in a JSON value: a number that is not finite, or a null anywhere but
// under "body" (a world-level quantity, or a blow-up of the time, names no body). Empty if none.
QString jsonProblem(const QJsonValue& v, const QString& path, const QString& key)
{
    if (v.isDouble() && !std::isfinite(v.toDouble())) return path + " = " + QString::number(v.toDouble());
    if (v.isNull() && key != QLatin1String("body")) return path + " = null";
    if (v.isArray()) {
        const QJsonArray a = v.toArray();
        for (qsizetype i = 0; i < a.size(); ++i) {
            // an array's elements belong to the key that holds it ("bodies": [A, null] never
            // happens: a contact's B side is a plane's name)
            const QString bad = jsonProblem(a.at(i), path + '[' + QString::number(i) + ']', key);
            if (!bad.isEmpty()) return bad;
        }
    }
    if (v.isObject()) {
        const QJsonObject o = v.toObject();
        for (auto it = o.begin(); it != o.end(); ++it) {
            const QString bad = jsonProblem(it.value(), path + '.' + it.key(), it.key());
            if (!bad.isEmpty()) return bad;
        }
    }
    return {};
}

// The whole of rbw's JSON output: it parses as one document, and jsonProblem finds nothing.
QString jsonOutputProblem(const QByteArray& out, QJsonObject* doc = nullptr)
{
    QJsonParseError error;
    const QJsonDocument d = QJsonDocument::fromJson(out, &error);
    if (error.error != QJsonParseError::NoError) return "does not parse: " + error.errorString();
    if (!d.isObject()) return QStringLiteral("not an object");
    if (doc != nullptr) *doc = d.object();
    return jsonProblem(d.object(), QStringLiteral("$"), QString());
}

// rbw's CSV output: every cell of every row after the header is a finite number (and no
// cell spells nan or inf in any case).
QString csvOutputProblem(const QByteArray& out)
{
    const QStringList lines = QString::fromUtf8(out).split('\n', Qt::SkipEmptyParts);
    for (qsizetype i = 1; i < lines.size(); ++i) {
        for (const QString& cell : lines[i].split(',')) {
            bool ok = false;
            const double x = cell.toDouble(&ok);
            if (!ok || !std::isfinite(x) || cell.contains(QLatin1String("nan"), Qt::CaseInsensitive) ||
                cell.contains(QLatin1String("inf"), Qt::CaseInsensitive)) {
                return QStringLiteral("line %1: cell \"%2\"").arg(i + 1).arg(cell);
            }
        }
    }
    return {};
}

int lineCount(const QByteArray& out) { return static_cast<int>(QString::fromUtf8(out).split('\n', Qt::SkipEmptyParts).size()); }

// A run's result (everything but the trace), for comparing two runs.
QJsonObject withoutTrace(QJsonObject o)
{
    o.remove("trace");
    return o;
}

QByteArray compact(const QJsonObject& o) { return QJsonDocument(o).toJson(QJsonDocument::Compact); }

// validate()'s problems with a scene, one "path: reason" per line; empty when it is valid.
std::string validationText(const rbw::SceneDef& scene)
{
    std::string text;
    for (const rbw::SceneIssue& issue : rbw::validate(scene)) {
        text += issue.path + ": " + issue.reason + "\n";
    }
    return text;
}

} // namespace

class TestOutputSafety : public QObject {
    Q_OBJECT

private slots:
    void extremeScene_data();
    void extremeScene();
    void scannerPassesLessons_data();
    void scannerPassesLessons();
    void scannerCatchesDoctoredOutput();
    void traceAllIsStreamed();
    void traceEntriesAreChecked();
    void initialStateCheckStopsTheWorld();
    void timeOverflowIsABlowUp();

private:
    QTemporaryDir dir_;
};

// The corpus. Each scene is derived by hand (DBL_MAX = 1.797e308; a unit cube of mass M
// has I0 = M/6 on every axis); the edge rule is physics/engine/stages/checks.h's:
//   "omega 1e308": I0 = 1/6, L0 = 1.67e307 and omega = 1e308 are finite, but
//     T_rot = 1/2 omega.L = 8.3e614 overflows in the initial state -> exit 3 before any
//     output, "|ω0| = 1e308 (bodies[0].angular_velocity)".
//   "v 1e308": T_trans = 1/2 * 1 * (1e308)^2 overflows in the initial state, "|v0| = 1e308".
//   "mass 1e-308": I0 = 1.67e-309, so I0^-1 = 6e308 overflows in the initial state
//     (inverse_inertia_body, "M = 1e-308"); scene validation may refuse the mass (exit 2).
//   "force 1e300": h F / M = 1e298 m/s after step 0 is finite, 1/2 M v^2 = 5e595 is not:
//     step 0, kinetic_energy_translational; no input is at the edge (a load's effect
//     scales with h), so the dt suggestion. CSV: header and the initial row were printed.
//   "energy overflow, two bodies": each body has T = 1/2 * 2 * (1e154)^2 = 1e308 (finite),
//     their sum 2e308 is not: a world-level total in the initial state, named by its
//     largest part (body "a", the first of two equal parts).
//   "size 1e200": I0 = (1e400 + 1)/12 overflows (validation may refuse the size, exit 2).
//   "size 9e153, spinning": I0_zz = (8.1e307 + 8.1e307)/12 = 1.35e307 is finite, L0_z =
//     100 I0_zz = 1.35e309 is not: angular_momentum in the initial state, "edge = 9e153".
//   "dt 1e308" (the file's 1 step, run for 3 with --steps; the validation may refuse
//     steps * dt overflowing): a body at rest stays at rest (every update adds h * 0 = 0);
//     t_1 = 1e308 is finite, t_2 = 2e308 is not: step 1, "time", body null, "h = 1e308 (dt)";
//     the trace of step 0 and the CSV rows of t = 0 and t = 1e308 are printed.
//   "constant force 1e153 N" (h = 1 s, M = 1 kg, acting in steps 0..99): v after step k
//     is (k+1)e153, so
//     T = 1/2 v^2 with v^2 = 1.69e308 after step 12 and 1.96e308 > DBL_MAX after step 13:
//     step 13, kinetic_energy_translational, not at the edge; 13 traced steps and 14 CSV
//     rows come first. (The energy-jump bound never fires: T_{k+1} = T_k + W_k exactly,
//     the work of a constant force, and the bound is 10 (T_k + W_k).)
void TestOutputSafety::extremeScene_data()
{
    QTest::addColumn<QByteArray>("scene");
    QTest::addColumn<QStringList>("extraArgs");  // after run FILE --format F --trace T
    QTest::addColumn<QString>("refusedField");   // validation may refuse it: exit 2 naming this
                                                 // (alternatives separated by |)
    QTest::addColumn<QStringList>("words");      // in the blow-up message (exit 3)
    QTest::addColumn<long>("step");
    QTest::addColumn<QString>("quantity");
    QTest::addColumn<QString>("body");           // empty: null
    QTest::addColumn<bool>("initial");
    QTest::addColumn<bool>("atEdge");
    QTest::addColumn<int>("completedSteps");     // steps taken before the blow-up

    struct Case {
        const char* name;
        QByteArray scene;
        QStringList extraArgs;
        const char* refusedField;
        QStringList words;
        long step;
        const char* quantity;
        const char* body;
        bool initial;
        bool atEdge;
        int completed;
    };
    const QString cannotStart = QStringLiteral("simulation cannot start: ");
    const QString edge = QStringLiteral("the inputs are at the edge of the double range");
    const QString smallerDt = QStringLiteral("Try a smaller dt or another integrator");
    const Case cases[] = {
        {"omega 1e308",
         R"({"dt": 0.01, "steps": 3, "bodies": [{"name": "box", "size": [1, 1, 1], "mass": 1, "angular_velocity": [1e308, 0, 0]}]})",
         {},
         "bodies[0].angular_velocity",
         {cannotStart + "kinetic_energy_rotational of body \"box\" is not finite in the initial state", edge,
          "the double range: |ω0| = 1e308 (bodies[0].angular_velocity); reduce them."},
         0, "kinetic_energy_rotational", "box", true, true, 0},
        {"v 1e308",
         R"({"dt": 0.01, "steps": 3, "bodies": [{"name": "box", "size": [1, 1, 1], "mass": 1, "linear_velocity": [1e308, 0, 0]}]})",
         {},
         "bodies[0].linear_velocity",
         {cannotStart + "kinetic_energy_translational of body \"box\" is not finite in the initial state", edge,
          "the double range: |v0| = 1e308 (bodies[0].linear_velocity); reduce them."},
         0, "kinetic_energy_translational", "box", true, true, 0},
        {"mass 1e-308",
         R"({"dt": 0.01, "steps": 3, "bodies": [{"name": "box", "size": [1, 1, 1], "mass": 1e-308}]})",
         {},
         "bodies[0].mass",
         {cannotStart + "inverse_inertia_body of body \"box\" is not finite in the initial state", edge,
          "the double range: M = 1e-308 (bodies[0].mass); increase them."},
         0, "inverse_inertia_body", "box", true, true, 0},
        {"force 1e300",
         R"({"dt": 0.01, "steps": 3, "bodies": [{"name": "box", "size": [1, 1, 1], "mass": 1}],
             "forces": [{"body": "box", "point": [0, 0, 0], "force": [1e300, 0, 0]}]})",
         {},
         "forces[0].force",
         {"simulation blew up in step 0: kinetic_energy_translational of body \"box\" is not finite", smallerDt,
          "or smaller forces"},
         0, "kinetic_energy_translational", "box", false, false, 0},
        {"energy overflow, two bodies",
         R"({"dt": 0.01, "steps": 3, "bodies": [
               {"name": "a", "size": [1, 1, 1], "mass": 2, "linear_velocity": [1e154, 0, 0]},
               {"name": "b", "size": [1, 1, 1], "mass": 2, "position": [5, 0, 0], "linear_velocity": [1e154, 0, 0]}]})",
         {},
         "bodies[0].linear_velocity",
         {cannotStart + "kinetic_energy_translational of the world (the largest part is body \"a\") is not finite", edge,
          "the double range: |v0| = 1e154 (bodies[0].linear_velocity), |v0| = 1e154 (bodies[1].linear_velocity); "
          "reduce them."},
         0, "kinetic_energy_translational", "a", true, true, 0},
        {"size 1e200",
         R"({"dt": 0.01, "steps": 3, "bodies": [{"name": "slab", "size": [1e200, 1, 1], "mass": 1}]})",
         {},
         "bodies[0].size",
         {cannotStart + "inertia_body of body \"slab\" is not finite in the initial state", edge, "edge = 1e200 (bodies[0].size)"},
         0, "inertia_body", "slab", true, true, 0},
        {"size 9e153, spinning",
         R"({"dt": 0.01, "steps": 3, "bodies": [{"name": "slab", "size": [9e153, 9e153, 1], "mass": 1, "angular_velocity": [0, 0, 100]}]})",
         {},
         "bodies[0]",
         {cannotStart + "angular_momentum of body \"slab\" is not finite in the initial state", edge,
          "the double range: edge = 9e153 (bodies[0].size); reduce them."},
         0, "angular_momentum", "slab", true, true, 0},
        {"dt 1e308",
         R"({"dt": 1e308, "steps": 1, "bodies": [{"name": "box", "size": [1, 1, 1], "mass": 1}]})",
         {"--steps", "3"},
         "dt|--steps",
         {"simulation blew up in step 1: time is not finite", edge, "the double range: h = 1e308 (dt); reduce them."},
         1, "time", "", false, true, 1},
        {"constant force 1e153 N",
         R"({"dt": 1, "steps": 20, "bodies": [{"name": "box", "size": [1, 1, 1], "mass": 1}],
             "forces": [{"body": "box", "point": [0, 0, 0], "force": [1e153, 0, 0], "to_step": 100}]})",
         {},
         "forces[0].force",
         {"simulation blew up in step 13: kinetic_energy_translational of body \"box\" is not finite", smallerDt,
          "or smaller forces"},
         13, "kinetic_energy_translational", "box", false, false, 13},
    };
    for (const Case& c : cases) {
        for (const char* format : {"json", "csv"}) {
            for (const char* trace : {"all", "last", "none"}) {
                QTest::addRow("%s | %s | trace %s", c.name, format, trace)
                    << c.scene << c.extraArgs << QString::fromLatin1(c.refusedField) << c.words << c.step
                    << QString::fromLatin1(c.quantity) << QString::fromLatin1(c.body) << c.initial << c.atEdge
                    << c.completed;
            }
        }
    }
}

void TestOutputSafety::extremeScene()
{
    QFETCH(QByteArray, scene);
    QFETCH(QStringList, extraArgs);
    QFETCH(QString, refusedField);
    QFETCH(QStringList, words);
    QFETCH(long, step);
    QFETCH(QString, quantity);
    QFETCH(QString, body);
    QFETCH(bool, initial);
    QFETCH(bool, atEdge);
    QFETCH(int, completedSteps);
    const QStringList tag = QString::fromLatin1(QTest::currentDataTag()).split(QStringLiteral(" | "));
    const QString format = tag[1];
    const QString trace = tag[2].mid(6);

    QVERIFY(dir_.isValid());
    const QString path = dir_.filePath(QString::number(qHash(scene)) + ".json");
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(scene);
    f.close();

    const Run r = runRbw(QStringList{"run", path, "--format", format, "--trace", trace} + extraArgs);
    // Whatever happens, nothing non-finite is printed.
    if (format == "json" && !r.out.isEmpty()) {
        const QString bad = jsonOutputProblem(r.out);
        QVERIFY2(bad.isEmpty(), qPrintable(bad));
    }
    if (format == "csv") {
        const QString bad = csvOutputProblem(r.out);
        QVERIFY2(bad.isEmpty(), qPrintable(bad));
    }
    if (r.exitCode == 2) {
        // Refused by the scene validation instead: it names the file and the field, and
        // nothing is printed on standard output.
        bool named = false;
        for (const QString& field : refusedField.split('|')) {
            named = named || r.err.contains(path + ": " + field) || r.err.contains("rbw: " + field + ": ");
        }
        QVERIFY2(named, qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
        qInfo("refused as bad input (exit 2): %s", qPrintable(r.err.trimmed()));
        return;
    }
    QVERIFY2(r.exitCode == 3, qPrintable(QStringLiteral("exit %1: %2").arg(r.exitCode).arg(r.err)));
    for (const QString& w : words) QVERIFY2(r.err.contains(w), qPrintable(r.err + "\nlacks: " + w));
    QCOMPARE(r.err.contains(QStringLiteral("edge of the double range")), atEdge);
    QCOMPARE(r.err.contains(QStringLiteral("Try a smaller dt")), !atEdge);

    if (format == "csv") {
        // Nothing before the initial check; then the header, the initial row and one row
        // per completed step stay printed.
        QCOMPARE(lineCount(r.out), initial ? 0 : 1 + 1 + completedSteps);
        return;
    }
    QJsonObject doc;
    QVERIFY(jsonOutputProblem(r.out, &doc).isEmpty());
    QCOMPARE(doc.value("status").toString(), QStringLiteral("blow-up"));
    QCOMPARE(doc.value("kind").toString(), QStringLiteral("non-finite"));
    QCOMPARE(doc.value("step").toInteger(), static_cast<qint64>(step));
    QCOMPARE(doc.value("quantity").toString(), quantity);
    if (body.isEmpty()) {
        QVERIFY(doc.value("body").isNull());
    } else {
        QCOMPARE(doc.value("body").toString(), body);
    }
    QCOMPARE(doc.value("initial_state").toBool(), initial);
    QCOMPARE(doc.value("inputs_at_edge").toBool(), atEdge);
    QCOMPARE(doc.value("message").toString(), r.err.trimmed().section(QStringLiteral(": "), 2));
    QCOMPARE(doc.value("file").toString(), path);
    QVERIFY(!doc.contains("bodies") && !doc.contains("diagnostics"));   // a blown-up state is no result
    // The trace holds the steps printed before the blow-up: every completed step with
    // --trace all, none otherwise.
    const QJsonArray steps = doc.value("trace").toArray();
    QCOMPARE(steps.size(), trace == "all" ? completedSteps : 0);
    for (qsizetype k = 0; k < steps.size(); ++k) QCOMPARE(steps[k].toObject().value("step").toInteger(), k);
}

// Negative control for the scanner: normal lesson runs pass it, in every mode.
void TestOutputSafety::scannerPassesLessons_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::addColumn<QString>("format");
    QTest::addColumn<QString>("trace");
    for (const char* lesson : {"01-one-step/scene.json", "03-two-box-collision/scene.json", "04-many-boxes/scene.json",
                               "07-bounce/scene.json", "09-tennis-racket/scene.json"}) {
        for (const char* format : {"json", "csv"}) {
            for (const char* trace : {"all", "last", "none"}) {
                QTest::addRow("%s | %s | %s", lesson, format, trace)
                    << QString::fromLatin1(lesson) << QString::fromLatin1(format) << QString::fromLatin1(trace);
            }
        }
    }
}

void TestOutputSafety::scannerPassesLessons()
{
    QFETCH(QString, lesson);
    QFETCH(QString, format);
    QFETCH(QString, trace);
    const Run r = runRbw({"run", QStringLiteral(RBW_SOURCE_DIR "/lessons/") + lesson, "--steps", "60", "--format", format,
                          "--trace", trace});
    QCOMPARE(r.exitCode, 0);
    QVERIFY(r.err.isEmpty());
    if (format == "csv") {
        QCOMPARE(lineCount(r.out), 1 + 1 + 60);
        const QString bad = csvOutputProblem(r.out);
        QVERIFY2(bad.isEmpty(), qPrintable(bad));
        return;
    }
    QJsonObject doc;
    const QString bad = jsonOutputProblem(r.out, &doc);
    QVERIFY2(bad.isEmpty(), qPrintable(bad));
    QCOMPARE(doc.value("status").toString(), QStringLiteral("ok"));
    QCOMPARE(doc.value("steps").toInteger(), 60);
    QCOMPARE(doc.value("trace").toArray().size(), trace == "all" ? 60 : trace == "last" ? 1 : 0);
}

// Negative control: the scanner is not vacuous. A lesson's output with one number
// replaced by null, NaN or infinity (the forms a non-finite double used to take) is caught.
void TestOutputSafety::scannerCatchesDoctoredOutput()
{
    const Run json = runRbw({"run", kLesson3, "--trace", "last"});
    QCOMPARE(json.exitCode, 0);
    QVERIFY(jsonOutputProblem(json.out).isEmpty());
    // "total_energy": <number> -> null; and a value inside a vector -> null
    QByteArray doctored = json.out;
    const qsizetype at = doctored.indexOf("\"total_energy\": ");
    QVERIFY(at >= 0);
    const qsizetype from = at + qsizetype(strlen("\"total_energy\": "));
    qsizetype to = doctored.indexOf('\n', from);   // one value per line; a comma may end it
    if (doctored[to - 1] == ',') --to;
    doctored.replace(from, to - from, "null");
    QVERIFY(jsonOutputProblem(doctored).contains("total_energy = null"));
    // a bare NaN is no JSON at all; 1e999 reads back as infinity (or does not parse)
    for (const char* number : {"NaN", "1e999"}) {
        const QByteArray broken = QByteArray(json.out).replace("\"dt\": 0.01", QByteArray("\"dt\": ") + number);
        QVERIFY(broken != json.out);
        QVERIFY2(!jsonOutputProblem(broken).isEmpty(), number);
    }

    const Run csv = runRbw({"run", kLesson3, "--format", "csv"});
    QCOMPARE(csv.exitCode, 0);
    QVERIFY(csvOutputProblem(csv.out).isEmpty());
    QList<QByteArray> lines = csv.out.split('\n');
    QVERIFY(lines.size() > 2);
    for (const QByteArray& bad : {QByteArray("nan"), QByteArray("inf"), QByteArray("-inf"), QByteArray("")}) {
        QList<QByteArray> cells = lines[2].split(',');
        cells[3] = bad;
        QList<QByteArray> copy = lines;
        copy[2] = cells.join(',');
        QVERIFY2(!csvOutputProblem(copy.join('\n')).isEmpty(), bad.constData());
    }
}

// --trace all is written while the run goes. 2000 steps of lesson 3 (its collision is in
// step 2) give one valid document with 2000 trace elements, numbered 0..1999; the first
// steps equal, bit for bit (the doubles compared as parsed), the one trace element of a
// run of k+1 steps with --trace last, which prints after its last step; and the final
// result equals that of the same run with --trace none (tracing changes no number).
void TestOutputSafety::traceAllIsStreamed()
{
    const Run all = runRbw({"run", kLesson3, "--steps", "2000", "--trace", "all"});
    QCOMPARE(all.exitCode, 0);
    QJsonObject doc;
    const QString bad = jsonOutputProblem(all.out, &doc);
    QVERIFY2(bad.isEmpty(), qPrintable(bad));
    const QJsonArray trace = doc.value("trace").toArray();
    QCOMPARE(trace.size(), 2000);
    for (qsizetype k = 0; k < trace.size(); ++k) QCOMPARE(trace[k].toObject().value("step").toInteger(), k);
    // the collision step has its contact (lesson 3: step 2, t = 0.03)
    QCOMPARE(trace[2].toObject().value("contacts").toArray().size(), 1);

    for (int k : {0, 1, 2, 3, 10}) {
        const Run last = runRbw({"run", kLesson3, "--steps", QString::number(k + 1), "--trace", "last"});
        QCOMPARE(last.exitCode, 0);
        const QJsonArray one = QJsonDocument::fromJson(last.out).object().value("trace").toArray();
        QCOMPARE(one.size(), 1);
        QCOMPARE(compact(trace[k].toObject()), compact(one[0].toObject()));
    }
    const Run none = runRbw({"run", kLesson3, "--steps", "2000", "--trace", "none"});
    QCOMPARE(none.exitCode, 0);
    const QJsonObject result = QJsonDocument::fromJson(none.out).object();
    QCOMPARE(result.value("trace").toArray().size(), 0);
    QCOMPARE(compact(withoutTrace(doc)), compact(withoutTrace(result)));
    // The same keys as a whole document written at once (runToJson): the shape is kept.
    QStringList keys = doc.keys();
    QCOMPARE(keys, (QStringList{"bodies", "diagnostics", "dt", "file", "inertia_convention", "integrator", "probes",
                                "scene", "status", "steps", "time", "trace"}));
}

// Every trace entry is checked, contact numbers included: the step-2 trace of lesson 3
// (one contact between A and B) is finite; with its impulse J made infinite, checkTrace
// names the impulse, contact 0 and its body A; made NaN, the same. The unchanged trace
// passes (negative control).
void TestOutputSafety::traceEntriesAreChecked()
{
    const rbw::SceneDef scene = rbw::test::lessonScene("03-two-box-collision/scene.json");
    rbw::World world(scene);
    rbw::StepTrace trace;
    for (int k = 0; k < 3; ++k) QVERIFY(world.step(&trace).ok);
    QCOMPARE(trace.contacts.size(), size_t(1));
    std::vector<rbw::InertiaConvention> conventions;
    for (int b = 0; b < static_cast<int>(scene.bodies.size()); ++b) conventions.push_back(world.conventionOf(b));
    const std::vector<rbw::Vec3> probeOffsets(scene.probes.size(), rbw::Vec3::Zero());
    const rbw::CheckScope scope{world.scene(), world.massProperties(), conventions, probeOffsets};
    const rbw::CheckPoint at{2, false};
    QVERIFY(rbw::checkTrace(scope, trace, at).ok);

    for (double bad : {double(INFINITY), double(NAN)}) {
        rbw::StepTrace broken = trace;
        bool found = false;
        for (rbw::TraceEntry& e : broken.entries) {
            if (std::string_view(e.info->id) == "impulse") {
                e.value = bad;
                found = true;
            }
        }
        QVERIFY(found);
        const rbw::StepStatus st = rbw::checkTrace(scope, broken, at);
        QVERIFY(!st.ok);
        QCOMPARE(QString::fromStdString(st.quantity), QStringLiteral("impulse"));
        QCOMPARE(st.index, 0);
        QCOMPARE(QString::fromStdString(st.indexKind), QStringLiteral("contact"));
        QCOMPARE(QString::fromStdString(st.bodyName), QStringLiteral("A"));
        const QString m = QString::fromStdString(st.message);
        QVERIFY2(m.contains("blew up in step 2: impulse (contact 0) of body \"A\" is not finite"), qPrintable(m));
    }
}

// World::checkOutputs() before the first step checks the initial state: for omega0 =
// 1e308 (T_rot overflows, see the corpus) it fails, names the initial state, and the world
// then refuses to step. The same body with omega0 = 1e3 passes (negative control).
void TestOutputSafety::initialStateCheckStopsTheWorld()
{
    for (double omega : {1e3, 1e308}) {
        rbw::SceneDef scene;
        scene.bodies.push_back(rbw::test::boxDef("box", rbw::Vec3(1, 1, 1), 1.0, rbw::Vec3::Zero(), rbw::Quat::Identity(),
                                                 rbw::Vec3::Zero(), rbw::Vec3(omega, 0, 0)));
        // The precondition: validate() accepts the scene, so that the world's own check is
        // what is tested here. A stricter validation fails this loudly rather than skipping
        // the test; then move the case to the extremeScene rows (bad input).
        const std::string issues = validationText(scene);
        QVERIFY2(issues.empty(), issues.c_str());
        rbw::World world(scene);
        const rbw::StepStatus st = world.checkOutputs();
        if (omega < 1e150) {
            QVERIFY2(st.ok, st.message.c_str());
            QVERIFY(world.step().ok);
            continue;
        }
        QVERIFY(!st.ok);
        QVERIFY(st.initialState);
        QVERIFY(st.inputsAtEdge);
        QCOMPARE(QString::fromStdString(st.quantity), QStringLiteral("kinetic_energy_rotational"));
        QCOMPARE(QString::fromStdString(st.edgeInputs), QStringLiteral("|ω0| = 1e308 (bodies[0].angular_velocity)"));
        const rbw::StepStatus again = world.step();
        QVERIFY(!again.ok);
        QCOMPARE(again.message, st.message);
        QCOMPARE(world.stepIndex(), 0L);
    }
}

// The time is checked by every step, traced or not: a body at rest with h = 1e308 s
// (every update adds h * 0 = 0) is at t_1 = 1e308 after step 0, and t_2 = 2e308 > DBL_MAX
// after step 1 is a blow-up of step 1 naming the time and dt. With h = 1e307 s
// (negative control) t_3 = 3e307 is finite and the three steps run.
void TestOutputSafety::timeOverflowIsABlowUp()
{
    for (double dt : {1e307, 1e308}) {
        rbw::SceneDef scene;
        scene.dt = dt;
        scene.bodies.push_back(rbw::test::boxDef("box", rbw::Vec3(1, 1, 1), 1.0, rbw::Vec3::Zero()));
        // The precondition, as above: validate() accepts dt = 1e308, so the time check is tested.
        const std::string issues = validationText(scene);
        QVERIFY2(issues.empty(), issues.c_str());
        rbw::World world(scene);
        QVERIFY(world.checkOutputs().ok);
        QVERIFY(world.step().ok);
        QCOMPARE(world.time(), dt);
        const rbw::StepStatus st = world.step();
        if (dt < 1e308) {
            QVERIFY2(st.ok, st.message.c_str());
            QVERIFY(world.step().ok);
            QCOMPARE(world.time(), 3 * dt);
            continue;
        }
        QVERIFY(!st.ok);
        QCOMPARE(st.step, 1L);
        QCOMPARE(QString::fromStdString(st.quantity), QStringLiteral("time"));
        QCOMPARE(st.body, -1);
        QVERIFY(st.inputsAtEdge);
        QCOMPARE(QString::fromStdString(st.edgeInputs), QStringLiteral("h = 1e308 (dt)"));
        QVERIFY2(QString::fromStdString(st.message).startsWith("simulation blew up in step 1: time is not finite"),
                 st.message.c_str());
    }
}

QTEST_GUILESS_MAIN(TestOutputSafety)
#include "tst_output_safety.moc"
