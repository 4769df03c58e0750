// rbw end to end: run it on lesson 1 and parse what it prints, the same way a grader
// script would. Expected numbers are Table 2.1's (docs/references.md §1), derived by
// hand in tst_table21.cpp; here they check that the JSON carries them unchanged.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include "tests/test_support.h"

#include <QSet>
#include <QtTest>

namespace {

using Run = rbw::test::RbwRun;
using rbw::test::runRbw;

const QString kLesson1 = QStringLiteral(RBW_SOURCE_DIR "/lessons/01-one-step/scene.json");

QJsonArray vec(double x, double y, double z) { return QJsonArray{x, y, z}; }

bool close(const QJsonValue& actual, const QJsonArray& expected, double tol)
{
    const QJsonArray a = actual.toArray();
    if (a.size() != expected.size()) return false;
    for (int i = 0; i < a.size(); ++i) {
        if (std::abs(a[i].toDouble() - expected[i].toDouble()) > tol) return false;
    }
    return true;
}

QJsonObject quantity(const QJsonObject& step, const QString& id, int index = -1)
{
    for (const QJsonValue& v : step.value("quantities").toArray()) {
        const QJsonObject q = v.toObject();
        if (q.value("id").toString() == id && q.value("index").toInt(-1) == index) return q;
    }
    return {};
}

} // namespace

class TestCli : public QObject {
    Q_OBJECT
private slots:
    void lesson1Json();
    void lesson1TraceFields();
    void doublesRoundTrip();
    void traceModes_data();
    void traceModes();
    void csv();
    void lessonsList();
    void blowUpExitsWith3();
};

void TestCli::lesson1Json()
{
    const Run r = runRbw({"run", kLesson1});
    QCOMPARE(r.exitCode, 0);
    QJsonParseError e;
    const QJsonObject doc = QJsonDocument::fromJson(r.out, &e).object();
    QCOMPARE(e.error, QJsonParseError::NoError);
    QCOMPARE(doc.value("time").toDouble(), 2.0);

    const QJsonObject box = doc.value("bodies").toArray().at(0).toObject();
    QCOMPARE(box.value("name").toString(), QString("box"));
    // Table 2.1 after the step (6 decimals as the exercise prints them).
    QVERIFY(close(box.value("position"), vec(0, 0, 0), 0.0));
    QVERIFY(close(box.value("linear_velocity"), vec(1, 1, 0), 1e-15));
    QVERIFY(close(box.value("angular_velocity"), vec(-2.4, 4.918033, -1.764706), 5e-7));
    QVERIFY(close(box.value("angular_momentum"), vec(-0.5, 0.5, -0.4), 1e-15));
    QCOMPARE(box.value("inverse_inertia_world").toArray().size(), 3);

    const QJsonArray probes = doc.value("probes").toArray();
    QCOMPARE(probes.size(), 2);
    QVERIFY(close(probes[0].toObject().value("velocity"), vec(-1.111861, 0.929412, 2.675410), 5e-7));
    QVERIFY(close(probes[1].toObject().value("velocity"), vec(3.111861, 1.070588, -2.675410), 5e-7));

    const QJsonObject diag = doc.value("diagnostics").toObject();
    for (const char* key : {"kinetic_energy", "potential_energy", "total_energy", "linear_momentum",
                            "angular_momentum_origin"}) {
        QVERIFY2(diag.contains(key), key);
    }
    // P = M v = 2 (1, 1, 0)
    QVERIFY(close(diag.value("linear_momentum"), vec(2, 2, 0), 1e-15));
}

void TestCli::lesson1TraceFields()
{
    const Run r = runRbw({"run", kLesson1});
    const QJsonArray trace = QJsonDocument::fromJson(r.out).object().value("trace").toArray();
    QCOMPARE(trace.size(), 1);
    const QJsonObject step = trace[0].toObject();
    QCOMPARE(step.value("step").toInt(), 0);
    QCOMPARE(step.value("time").toDouble(), 2.0);

    // The intermediates of docs/references.md §1, each with all its fields.
    for (const char* id : {"force", "torque", "position", "linear_velocity", "orientation", "angular_momentum",
                           "inertia_body", "inverse_inertia_world", "angular_velocity"}) {
        const QJsonObject q = quantity(step, id);
        QVERIFY2(!q.isEmpty(), id);
        for (const char* field : {"id", "body", "symbol", "formula", "frame", "unit", "value", "stage"}) {
            QVERIFY2(q.contains(field), qPrintable(QString("%1.%2").arg(id, field)));
        }
        QCOMPARE(q.value("body").toString(), QString("box"));
    }
    QVERIFY(close(quantity(step, "torque").value("value"), vec(-0.25, 0.25, -0.2), 1e-15));
    QCOMPARE(quantity(step, "inertia_body").value("frame").toString(), QString("body"));
    QCOMPARE(quantity(step, "angular_velocity").value("frame").toString(), QString("world"));
    QCOMPARE(quantity(step, "angular_velocity").value("unit").toString(), QString("rad/s"));
    const QJsonArray I0 = quantity(step, "inertia_body").value("value").toArray();
    // I0 = 2/12 diag(0.6^2 + 0.5^2, 1 + 0.5^2, 1 + 0.6^2) = diag(0.101667, 0.208333, 0.226667)
    RBW_COMPARE_NEAR_STRICT(I0[0].toArray()[0].toDouble(), 0.61 / 6, 1e-15);
    RBW_COMPARE_NEAR_STRICT(I0[1].toArray()[1].toDouble(), 1.25 / 6, 1e-15);
    RBW_COMPARE_NEAR_STRICT(I0[2].toArray()[2].toDouble(), 1.36 / 6, 1e-15);
    QVERIFY(close(quantity(step, "point_velocity", 0).value("value"), vec(-1.111861, 0.929412, 2.675410), 5e-7));

    // The state the step started from (issue 10): Table 2.1 starts at rest, turned 90°
    // about z, so v_0 = omega_0 = L_0 = 0, r_0 = [cos 45°, 0, 0, sin 45°], and the probe
    // probe 1 is the world point (0.3, 0.5, 0.25) of the scene, at rest.
    const QJsonObject start = step.value("start").toObject();
    const QJsonObject box0 = start.value("bodies").toArray().at(0).toObject();
    QCOMPARE(box0.value("name").toString(), QString("box"));
    QVERIFY(close(box0.value("position"), vec(0, 0, 0), 0.0));
    QVERIFY(close(box0.value("linear_velocity"), vec(0, 0, 0), 0.0));
    QVERIFY(close(box0.value("angular_momentum"), vec(0, 0, 0), 0.0));
    const QJsonArray r0 = box0.value("orientation").toArray();
    QCOMPARE(r0.size(), 4);
    RBW_COMPARE_NEAR_STRICT(r0[0].toDouble(), std::sqrt(0.5), 1e-15);
    RBW_COMPARE_NEAR_STRICT(r0[3].toDouble(), std::sqrt(0.5), 1e-15);
    QCOMPARE(box0.value("inverse_inertia_world").toArray().size(), 3);
    const QJsonArray probes0 = start.value("probes").toArray();
    QCOMPARE(probes0.size(), 2);
    QVERIFY(close(probes0[1].toObject().value("point"), vec(0.3, 0.5, 0.25), 1e-15));
    QVERIFY(close(probes0[1].toObject().value("velocity"), vec(0, 0, 0), 0.0));
}

void TestCli::doublesRoundTrip()
{
    // omega_y = 0.5 * 9.836065... = 0.5 / 0.10166... = 60/12.2; the JSON must carry the
    // double bit for bit, so a grader can compare exactly.
    const Run r = runRbw({"run", kLesson1});
    const QJsonObject box = QJsonDocument::fromJson(r.out).object().value("bodies").toArray()[0].toObject();
    const double omegaY = box.value("angular_velocity").toArray()[1].toDouble();
    QVERIFY(r.out.contains(QByteArray::number(omegaY, 'g', 17)) || r.out.contains(QByteArray::number(omegaY, 'g', 16)));
    RBW_COMPARE_NEAR_STRICT(omegaY, 60.0 / 12.2, 1e-14);
}

void TestCli::traceModes_data()
{
    QTest::addColumn<QString>("mode");
    QTest::addColumn<int>("expectedSteps");
    QTest::newRow("none") << "none" << 0;
    QTest::newRow("last") << "last" << 1;
    QTest::newRow("all") << "all" << 5;
}

void TestCli::traceModes()
{
    QFETCH(QString, mode);
    QFETCH(int, expectedSteps);
    const Run r = runRbw({"run", kLesson1, "--steps", "5", "--dt", "0.01", "--trace", mode});
    QCOMPARE(r.exitCode, 0);
    const QJsonObject doc = QJsonDocument::fromJson(r.out).object();
    const QJsonArray trace = doc.value("trace").toArray();
    QCOMPARE(trace.size(), expectedSteps);
    if (expectedSteps > 0) {
        QCOMPARE(trace.last().toObject().value("step").toInt(), 4);
    }
    QCOMPARE(doc.value("steps").toInt(), 5);
    RBW_COMPARE_NEAR_STRICT(doc.value("time").toDouble(), 0.05, 1e-15);
}

void TestCli::csv()
{
    const Run r = runRbw({"run", kLesson1, "--steps", "3", "--dt", "0.5", "--format", "csv"});
    QCOMPARE(r.exitCode, 0);
    const QStringList lines = QString::fromUtf8(r.out).split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 1 + 1 + 3);   // header, initial state, one row per step
    const QStringList header = lines[0].split(',');
    QCOMPARE(header.first(), QString("step"));
    QVERIFY(header.contains("box.angular_velocity_y"));
    QVERIFY(header.contains("total_energy"));
    // One naming scheme (issue 18): a body's column is BODY.ID_AXIS with ID a trace id
    // of `rbw quantities`, and every other column a diagnostic of the JSON output.
    QSet<QString> traceIds;
    const Run quantities = runRbw({"quantities", "--format", "json"});
    QCOMPARE(quantities.exitCode, 0);
    for (const QJsonValue& v : QJsonDocument::fromJson(quantities.out).array()) traceIds << v.toObject().value("id").toString();
    const Run json = runRbw({"run", kLesson1, "--steps", "1"});
    QCOMPARE(json.exitCode, 0);
    const QJsonObject diagnostics = QJsonDocument::fromJson(json.out).object().value("diagnostics").toObject();
    QVERIFY(!traceIds.isEmpty() && !diagnostics.isEmpty());
    for (const QString& column : header.mid(2)) {
        if (column.startsWith("box.")) {
            const QString id = column.mid(4).section('_', 0, -2);
            QVERIFY2(traceIds.contains(id), qPrintable(column));
        } else {
            QVERIFY2(diagnostics.contains(column), qPrintable(column));
        }
    }
    // Negative control: the old column name is no trace id.
    QVERIFY(!traceIds.contains("omega"));
    const QStringList afterOne = lines[2].split(',');
    QCOMPARE(afterOne.size(), header.size());
    // After one step of h = 0.5 with F = (1,1,0), M = 2: v = h F/M = (0.25, 0.25, 0).
    QCOMPARE(afterOne[header.indexOf("box.linear_velocity_x")].toDouble(), 0.25);
    QCOMPARE(afterOne[header.indexOf("time")].toDouble(), 0.5);
}

void TestCli::lessonsList()
{
    const Run r = runRbw({"lessons"});
    QCOMPARE(r.exitCode, 0);
    QVERIFY2(r.out.contains("01-one-step"), r.out.constData());
    QVERIFY(r.out.contains("One Euler step (Table 2.1)"));
}

void TestCli::blowUpExitsWith3()
{
    // A force of 1e300 N on a mass of 1e-10 kg: step 0 gives v = h F / M = 1e310 m/s,
    // beyond the largest double (1.8e308), so v overflows to infinity in step 0.
    // (A torque-free spinner cannot blow up with the TUM algorithm: it updates L in the
    // world frame, L <- L + h q, so L stays exactly constant and omega = I^-1 L bounded.)
    QTemporaryDir dir;
    const QString path = dir.filePath("blowup.json");
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({ "dt": 1.0, "steps": 10,
                 "bodies": [ { "name": "speck", "size": [1, 1, 1], "mass": 1e-10 } ],
                 "forces": [ { "body": "speck", "point": [0, 0, 0], "force": [1e300, 0, 0] } ] })");
    f.close();
    const Run r = runRbw({"run", path});
    QCOMPARE(r.exitCode, 3);
    QVERIFY2(r.err.contains("blew up in step 0: linear_velocity of body \"speck\" is not finite"),
             qPrintable(r.err));
    QVERIFY(r.err.contains("Try a smaller dt or another integrator"));
    const QJsonObject doc = QJsonDocument::fromJson(r.out).object();
    QCOMPARE(doc.value("status").toString(), QString("blow-up"));
    QCOMPARE(doc.value("step").toInt(), 0);
    QCOMPARE(doc.value("quantity").toString(), QString("linear_velocity"));
    QVERIFY(!r.out.contains("nan") && !r.out.contains("inf"));

    // Negative control: with h = 1e-160 s, v = h F / M = 1e150 m/s after step 0 and
    // T = 1/2 M v^2 = 5e289 J stay finite (1e151 m/s and 5e291 J after the 10 steps), and
    // the run succeeds. (With h = 1e-20 s, v = 1e290 m/s is finite but T = 5e569 J is not:
    // that run is a blow-up of the kinetic energy, no longer printed as null.)
    const Run ok = runRbw({"run", path, "--dt", "1e-160"});
    QCOMPARE(ok.exitCode, 0);
}

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
