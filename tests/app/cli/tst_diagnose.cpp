// rbw diagnose through the real binary (issue 23, docs/simulator-protocol.md):
// the shipped reference simulator (examples/simulator/, target rbw_reference_simulator)
// matches, in double and in float, and so do its Python twin and the TUM adapter around
// the template stand-in (9 numbers an answer); with each motion mistake switched on (--mistake ID)
// it is explained by exactly that id; programs that print nan, exit, hang or print
// garbage (shell scripts written here) end with status 2, a message that names the
// probe, the step and the command, and no process of theirs left running. Also: each
// collision mistake explained with the restitution fitted; the template's public tests
// (which version passes with which inertia convention); the offline mode (rbw probes,
// the simulator's .states files, rbw diagnose DIR and --trajectory give the live
// verdict; bad offline answers name file and line); --format csv over several programs.
#include "tests/test_support.h"

#include "physics/workbook/probes/collision_replay.h"
#include "physics/workbook/probes/probe_models.h"
#include "physics/workbook/probes/probes.h"
#include "physics/workbook/probes/replay.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QThread>
#include <QtTest>

#include <cmath>

namespace {

const QString kReference = QStringLiteral(RBW_REFERENCE_SIMULATOR_PATH);
const QString kAdapterStub = QStringLiteral(RBW_TUM_ADAPTER_STUB_PATH);

struct Diagnosed {
    int exitCode = -1;
    QJsonObject doc;
};

Diagnosed diagnoseJson(const QString& simulator)
{
    const rbw::test::RbwRun r = rbw::test::runRbw({"diagnose", "--simulator", simulator, "--format", "json"});
    if (!r.err.isEmpty()) qWarning("stderr: %s", qPrintable(r.err));
    return {r.exitCode, QJsonDocument::fromJson(r.out).object()};
}

// A process runs when /proc has it and it is not a zombie (a container's init may
// leave killed orphans unreaped).
// The names (with the version) of the template's public tests that passed.
QStringList templatePassed(const QJsonObject& doc)
{
    QStringList names;
    for (const QJsonValue& v : doc.value("template_tests").toObject().value("tests").toArray()) {
        const QJsonObject t = v.toObject();
        if (!t.value("passed").toBool()) continue;
        const QString version = t.value("version").toString();
        names << t.value("name").toString() + (version.isEmpty() ? QString() : " (" + version + ")");
    }
    return names;
}

bool running(qint64 pid)
{
    QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!stat.open(QIODevice::ReadOnly)) return false;
    const QByteArray text = stat.readAll();
    const qsizetype close = text.lastIndexOf(')');
    return close >= 0 && close + 2 < text.size() && text[close + 2] != 'Z';
}

} // namespace

class TestDiagnose : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        QVERIFY2(QFile::exists(kReference), qPrintable(kReference));
    }

    void referenceMatches_data()
    {
        QTest::addColumn<QString>("simulator");
        QTest::newRow("double") << kReference;
        QTest::newRow("float") << kReference + " --float";   // float round-off is within 1e-4
        // the TUM adapter around the template stand-in: 9 numbers per answer, no r
        QTest::newRow("tum adapter, 9 numbers") << kAdapterStub;
        const QString python = QStandardPaths::findExecutable("python3");
        if (!python.isEmpty()) {
            QTest::newRow("python twin")
                << "\"" + python + "\" \"" RBW_SOURCE_DIR "/examples/simulator/reference_simulator.py\"";
        }
    }
    void referenceMatches()
    {
        QFETCH(QString, simulator);
        const Diagnosed run = diagnoseJson(simulator);
        QCOMPARE(run.exitCode, 0);
        const QJsonObject& d = run.doc;
        QCOMPARE(d.value("verdict").toString(), QStringLiteral("matches"));
        QVERIFY(d.value("mistakes").toArray().isEmpty());
        QVERIFY(d.value("first_divergence").isNull());
        const QJsonArray probes = d.value("probes").toArray();
        QCOMPARE(probes.size(), static_cast<qsizetype>(rbw::probes::probesOf(rbw::probes::ProbeGroup::All).size()));
        for (const QJsonValue& p : probes) QVERIFY(p.toObject().value("matches").toBool());
        QCOMPARE(d.value("probes_group").toString(), QStringLiteral("all"));
        // the reference simulator's default c = 0.5, fitted from its collision answers
        const QJsonArray c = d.value("restitution").toArray();
        QCOMPARE(c.size(), 1);
        QCOMPARE(c[0].toObject().value("model").toString(), QStringLiteral("the right algorithm"));
        QVERIFY(std::abs(c[0].toObject().value("c").toDouble() - 0.5) < 1e-4);
        // the template's public tests: a correct simulator fails both versions of
        // TestRigidBodiesAfterForceApplication (they expect R^T I0^-1 R) and passes the others
        QCOMPARE(templatePassed(d), QStringList({"TestRigidBodiesInitialization", "TestRigidBodiesOneStepGivenTableTest"}));
    }

    // The template's public tests through the protocol: which convention passes which
    // version (docs/references.md §1; examples/simulator/selfcheck.sh derives the numbers).
    void templatePublicTests_data()
    {
        QTest::addColumn<QString>("mistakes");
        QTest::addColumn<QStringList>("passed");
        const QString init = "TestRigidBodiesInitialization", table = "TestRigidBodiesOneStepGivenTableTest";
        QTest::newRow("R^T I0^-1 R") << "--mistake transposed-inertia"
                                     << QStringList{init, "TestRigidBodiesAfterForceApplication (December 2022)", table};
        QTest::newRow("R^T I0^-1 R and the 2018 quaternion product")
            << "--mistake transposed-inertia --mistake quaternion-right-multiplied"
            << QStringList{init, "TestRigidBodiesAfterForceApplication (2018)", table};
        QTest::newRow("float, R^T I0^-1 R") << "--float --mistake transposed-inertia"
                                            << QStringList{init, "TestRigidBodiesAfterForceApplication (December 2022)",
                                                           table};
    }
    void templatePublicTests()
    {
        QFETCH(QString, mistakes);
        QFETCH(QStringList, passed);
        const Diagnosed run = diagnoseJson(kReference + " " + mistakes);
        QCOMPARE(run.exitCode, 1);
        QCOMPARE(templatePassed(run.doc), passed);
        const QJsonObject t = run.doc.value("template_tests").toObject();
        QVERIFY(t.value("note").toString().contains("lessons/08-conventions"));
        for (const QJsonValue& v : t.value("tests").toArray()) {
            const QJsonObject test = v.toObject();
            if (test.value("version").toString() == "December 2022") {
                QVERIFY(test.value("expects").toString().contains("R^T I0^-1 R"));
            }
            if (!test.value("passed").toBool()) QVERIFY(test.value("failure").toObject().contains("expected"));
        }
        const rbw::test::RbwRun text = rbw::test::runRbw({"diagnose", "--simulator", kReference + " " + mistakes});
        QVERIFY2(QString::fromUtf8(text.out).contains("TestRigidBodiesAfterForceApplication (2018)  "),
                 text.out.constData());
    }

    // Each collision model with a restitution the workbook is not told: explained by its
    // id, and c fitted. impulse-without-one-plus with c and restitution-one-minus with
    // 1 - c give the same numbers (collision_replay.h): both are possible mistakes.
    void collisionMistakeIsExplained_data()
    {
        QTest::addColumn<QString>("id");
        QTest::addColumn<QString>("options");
        QStringList ids;
        for (const rbw::probes::ReplayModel& m : rbw::probes::collisionModels()) {
            ids << QString::fromStdString(rbw::probes::modelId(m));
        }
        QVERIFY(ids.size() >= 7);
        for (const QString& id : ids) QTest::newRow(qPrintable(id)) << id << "";
        QTest::newRow("relative-velocity-reversed, float") << "relative-velocity-reversed" << "--float";
        QTest::newRow("impulse-linear-only, float") << "impulse-linear-only" << "--float";
    }
    void collisionMistakeIsExplained()
    {
        QFETCH(QString, id);
        QFETCH(QString, options);
        const double c = 0.35;
        const rbw::test::RbwRun r = rbw::test::runRbw(
            {"diagnose", "--probes", "collision", "--format", "json", "--simulator",
             kReference + " --restitution 0.35 --mistake " + id + " " + options});
        QCOMPARE(r.exitCode, 1);
        const QJsonObject d = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(d.value("probes_group").toString(), QStringLiteral("collision"));
        QCOMPARE(d.value("verdict").toString(), QStringLiteral("explained"));
        const bool pair = id == "impulse-without-one-plus" || id == "restitution-one-minus";
        if (pair) {
            QCOMPARE(d.value("possible_mistakes").toArray(),
                     QJsonArray({"impulse-without-one-plus", "restitution-one-minus"}));
        } else {
            QCOMPARE(d.value("mistakes").toArray(), QJsonArray{id});
        }
        bool fitted = false;
        for (const QJsonValue& v : d.value("restitution").toArray()) {
            if (v.toObject().value("model").toString() == id) {
                fitted = std::abs(v.toObject().value("c").toDouble() - c) < 1e-4;
            }
        }
        QVERIFY2(fitted, qPrintable(QJsonDocument(d.value("restitution").toArray()).toJson()));
        QVERIFY(d.value("first_divergence").toObject().value("probe_name").toString().startsWith("collision-"));
    }

    // For tutors: several programs, one CSV row per program and probe and a summary row
    // each; a program that cannot be run gets a bad-input summary and exit status 2.
    void csvForTutors()
    {
        const QString right = kReference, wrong = kReference + " --mistake torque-reversed";
        const rbw::test::RbwRun r = rbw::test::runRbw(
            {"diagnose", "--format", "csv", "--probes", "motion", "--simulator", right, "--simulator", wrong});
        QCOMPARE(r.exitCode, 1);
        QList<QByteArray> lines = r.out.trimmed().split('\n');
        const qsizetype probes = static_cast<qsizetype>(rbw::probes::motionProbes().size());
        QCOMPARE(lines.size(), 1 + 2 * (probes + 1));
        QVERIFY(lines[0].startsWith("program,probe,result,reproduced_by,step,body,quantity,expected,given,mistakes,"
                                    "restitution,template_tests_passed,message"));
        for (const QByteArray& l : lines.mid(1)) QCOMPARE(l.count(','), lines[0].count(','));
        QVERIFY2(lines[1 + probes].startsWith(right.toUtf8() + ",summary,matches,"), lines[1 + probes].constData());
        QVERIFY(lines[1 + probes].endsWith(",2/4,"));
        const QByteArray summary = lines.last();
        QVERIFY2(summary.startsWith(wrong.toUtf8() + ",summary,explained,,1,0,motion-01/omega,"), summary.constData());
        QVERIFY(summary.contains(",torque-reversed,"));
        QVERIFY(lines[2 + probes].startsWith(wrong.toUtf8() + ",motion-01,differs,torque-reversed,1,0,omega,"));

        const rbw::test::RbwRun broken = rbw::test::runRbw(
            {"diagnose", "--format", "csv", "--probes", "motion", "--simulator", right, "--simulator", "/nonexistent/sim"});
        QCOMPARE(broken.exitCode, 2);
        QVERIFY2(broken.out.trimmed().split('\n').last().startsWith("/nonexistent/sim,summary,bad-input,"),
                 broken.out.constData());
        QVERIFY(broken.err.contains("cannot start the simulator \"/nonexistent/sim\""));
    }

    // One row per motion model of the probes (physics/workbook/probes/probe_models.cpp):
    // every one the protocol can show is a flag of the reference simulator.
    void mistakeIsExplained_data()
    {
        QTest::addColumn<QString>("id");
        QStringList ids;
        for (const rbw::probes::ReplayModel& m : rbw::probes::motionModels()) {
            const QString id = QString::fromStdString(rbw::probes::modelId(m));
            if (!ids.contains(id)) ids << id;
        }
        QVERIFY(ids.size() >= 12);
        for (const QString& id : ids) QTest::newRow(qPrintable(id)) << id;
    }
    void mistakeIsExplained()
    {
        QFETCH(QString, id);
        const Diagnosed run = diagnoseJson(kReference + " --mistake " + id);
        QCOMPARE(run.exitCode, 1);
        const QJsonObject& d = run.doc;
        QCOMPARE(d.value("verdict").toString(), QStringLiteral("explained"));
        QCOMPARE(d.value("mistakes").toArray(), QJsonArray{id});
        QVERIFY(d.value("possible_mistakes").toArray().isEmpty());
        QCOMPARE(d.value("mistake_details").toArray()[0].toObject().value("id").toString(), id);
        // the first number that leaves the right algorithm, with both values
        const QJsonObject f = d.value("first_divergence").toObject();
        QVERIFY(f.value("probe").toInt() >= 1);
        // every probe's answers before a step are right, but for a body whose orientation is
        // never set: orientation-zero-quaternion prints r = (0, 0, 0, 0) from add_body on
        if (id == "orientation-zero-quaternion") {
            QCOMPARE(f.value("step").toInt(), 0);
            QCOMPARE(f.value("quantity").toString(), QStringLiteral("r"));
        } else {
            QVERIFY(f.value("step").toInt() >= 1);
        }
        QVERIFY(QStringList({"x", "v", "omega", "r"}).contains(f.value("quantity").toString()));
        const QJsonArray e = f.value("expected").toArray(), g = f.value("given").toArray();
        QCOMPARE(e.size(), g.size());
        QVERIFY(e != g);
    }

    // Two mistakes at once are no single model (pairs are not replayed yet): the
    // verdict must not claim one explains them.
    void twoMistakesAreNotExplainedByOne()
    {
        const Diagnosed run = diagnoseJson(kReference + " --mistake torque-reversed --mistake transposed-inertia");
        QCOMPARE(run.exitCode, 1);
        const QString verdict = run.doc.value("verdict").toString();
        QVERIFY2(verdict == "partly-explained" || verdict == "unexplained", qPrintable(verdict));
        QVERIFY(run.doc.value("first_divergence").isObject());
    }

    void textReport()
    {
        const rbw::test::RbwRun r =
            rbw::test::runRbw({"diagnose", "--simulator", kReference + " --mistake lever-arm-from-origin"});
        QCOMPARE(r.exitCode, 1);
        const QString out = QString::fromUtf8(r.out);
        QVERIFY2(out.contains("verdict: explained"), qPrintable(out));
        QVERIFY2(out.contains("lever-arm-from-origin: q = p x f"), qPrintable(out));
        QVERIFY2(out.contains("first divergence from the right algorithm: probe 1 (motion-01), step 1"), qPrintable(out));
        QVERIFY2(out.contains("within 0.0001"), qPrintable(out));
    }

    // Programs that break the protocol: exit 2, the message, nothing left running.
    void brokenSimulator_data()
    {
        QTest::addColumn<QString>("body");      // what the script does, between the pid line and the loop
        QTest::addColumn<QString>("message");
        const QString loop = QStringLiteral(
            "while read -r cmd rest; do\n"
            "  case \"$cmd\" in\n"
            "    %1\n"
            "    quit) exit 0;;\n"
            "  esac\n"
            "done\n");
        QTest::newRow("nan") << loop.arg("state) echo \"1 2 3 4 5 6 nan 8 9\";;")
                             << "your simulator printed nan at probe 1, step 1 (motion-01: its answer to \"state 0\"";
        QTest::newRow("exits") << loop.arg("step) echo dying >&2; exit 3;;")
                               << "your simulator exited with status 3 at probe 1, step 1, before it answered "
                                  "\"state 0\" (motion-01)\nrbw: diagnose: its last lines on standard error:\n  dying";
        // the shell waits for a child of its own: both must be ended
        QTest::newRow("hangs") << loop.arg("step) sleep 30 & echo $! >> \"$PIDS\"; wait;;")
                               << "your simulator did not answer \"state 0\" at probe 1, step 1 within 1 s (motion-01); "
                                  "it was stopped";
        QTest::newRow("garbage") << loop.arg("state) echo hello world;;")
                                 << "your simulator answered \"hello world\" to \"state 0\" at probe 1, step 1 "
                                    "(motion-01); expected 9 or 13 numbers";
        QTest::newRow("extra output") << loop.arg("state) echo 0 0 0 0 0 0 0 0 0;; step) ;; reset) echo hi;;")
                                      << "your simulator answered \"hi\" to \"state 0\" at probe 1, step 1";
        QTest::newRow("output after quit") << loop.arg("state) echo 0 0 0 0 0 0 0 0 0;; quit) echo bye; exit 0;;")
                                           << "your simulator printed \"bye\" at probe 1 (motion-01) where no answer "
                                              "was asked for";
        QTest::newRow("status after quit") << loop.arg("state) echo 0 0 0 0 0 0 0 0 0;; quit) exit 4;;")
                                           << "your simulator exited with status 4 after \"quit\" at probe 1 "
                                              "(motion-01); expected status 0";
    }
    void brokenSimulator()
    {
        QFETCH(QString, body);
        QFETCH(QString, message);
        const QString pids = dir_.filePath(QString(QTest::currentDataTag()).replace(' ', '-') + ".pids");
        const QString script = dir_.filePath(QString(QTest::currentDataTag()).replace(' ', '-') + ".sh");
        QFile f(script);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(("#!/bin/sh\nPIDS='" + pids + "'\necho $$ >> \"$PIDS\"\n" + body).toUtf8());
        f.close();
        QVERIFY(f.setPermissions(f.permissions() | QFileDevice::ExeOwner));

        QElapsedTimer clock;
        clock.start();
        const rbw::test::RbwRun r = rbw::test::runRbw({"diagnose", "--simulator", script, "--timeout", "1"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY2(r.out.isEmpty(), r.out.constData());   // no verdict after a broken run
        QVERIFY(clock.elapsed() < 5000);

        QFile list(pids);
        QVERIFY(list.open(QIODevice::ReadOnly));
        const QList<QByteArray> started = list.readAll().split('\n');
        QVERIFY(!started.first().isEmpty());
        for (const QByteArray& line : started) {
            if (line.trimmed().isEmpty()) continue;
            const qint64 pid = line.trimmed().toLongLong();
            for (int i = 0; i < 100 && running(pid); ++i) QThread::msleep(20);
            QVERIFY2(!running(pid), qPrintable(QStringLiteral("process %1 is still running").arg(pid)));
        }
    }

    // Negative control of the process check: a process of ours runs.
    void runningSeesALiveProcess() { QVERIFY(running(QCoreApplication::applicationPid())); }

    void badInput_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        QTest::newRow("nothing to diagnose") << QStringList{"diagnose"} << "what to diagnose: --simulator \"CMD\"";
        QTest::newRow("cannot start") << QStringList{"diagnose", "--simulator", "/nonexistent/sim --x"}
                                      << "cannot start the simulator \"/nonexistent/sim\"";
        QTest::newRow("timeout") << QStringList{"diagnose", "--simulator", kReference, "--timeout", "-1"}
                                 << "--timeout: must be a number of seconds > 0";
        QTest::newRow("format") << QStringList{"diagnose", "--simulator", kReference, "--format", "xml"}
                                << "--format: must be text, json or csv for diagnose, got \"xml\"";
        QTest::newRow("several without csv") << QStringList{"diagnose", "--simulator", kReference, "--simulator", kReference}
                                             << "2 --simulator options: several programs need --format csv";
        QTest::newRow("no folder") << QStringList{"diagnose", "/nonexistent/probes"}
                                   << "/nonexistent/probes: cannot read: not a folder";
        QTest::newRow("two sources") << QStringList{"diagnose", "--simulator", kReference, "probes"}
                                     << "give one of --simulator \"CMD\", --trajectory FILE.csv or one folder DIR";
        QTest::newRow("group") << QStringList{"diagnose", "--simulator", kReference, "--probes", "contact"}
                               << "--probes: must be motion, collision or all, got \"contact\"";
        QTest::newRow("timeout offline") << QStringList{"diagnose", "--trajectory", "a.csv", "--timeout", "3"}
                                         << "--timeout: only for --simulator";
        QTest::newRow("no trajectory") << QStringList{"diagnose", "--trajectory", "/nonexistent/a.csv"}
                                       << "/nonexistent/a.csv: cannot read:";
        QTest::newRow("probes without output") << QStringList{"probes"} << "--output DIR is required";
    }
    void badInput()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const rbw::test::RbwRun r = rbw::test::runRbw(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
    }

    // The offline mode: rbw probes writes the probe files, the reference simulator
    // answers each one (as a student's loop would), and rbw diagnose DIR and
    // --trajectory FILE.csv give the live verdict, mistake and first divergence.
    void offlineGivesTheLiveVerdict_data()
    {
        QTest::addColumn<QStringList>("simulatorArgs");
        QTest::addColumn<QString>("verdict");
        QTest::newRow("right") << QStringList{} << "matches";
        QTest::newRow("right, float") << QStringList{"--float"} << "matches";
        QTest::newRow("transposed-inertia") << QStringList{"--mistake", "transposed-inertia"} << "explained";
        QTest::newRow("quaternion-missing-half") << QStringList{"--mistake", "quaternion-missing-half"} << "explained";
        QTest::newRow("two mistakes") << QStringList{"--mistake", "torque-reversed", "--mistake", "missing-time-step"}
                                      << "";   // whatever live says
    }
    void offlineGivesTheLiveVerdict()
    {
        QFETCH(QStringList, simulatorArgs);
        QFETCH(QString, verdict);
        const QString dir = dir_.filePath(QStringLiteral("offline-") + QString(QTest::currentDataTag()).replace(' ', '-'));
        QVERIFY(writeAnsweredFolder(dir, simulatorArgs));
        const QString csv = dir + "/answers.csv";
        QVERIFY(writeTrajectory(dir, csv));

        const Diagnosed live = diagnoseJson(kReference + " " + simulatorArgs.join(' '));
        const rbw::test::RbwRun fromDir = rbw::test::runRbw({"diagnose", dir, "--format", "json"});
        const rbw::test::RbwRun fromCsv = rbw::test::runRbw({"diagnose", "--trajectory", csv, "--format", "json"});
        if (!verdict.isEmpty()) QCOMPARE(live.doc.value("verdict").toString(), verdict);
        for (const rbw::test::RbwRun* r : {&fromDir, &fromCsv}) {
            QVERIFY2(r->err.isEmpty(), qPrintable(r->err));
            QCOMPARE(r->exitCode, live.exitCode);
            const QJsonObject d = QJsonDocument::fromJson(r->out).object();
            for (const char* key : {"verdict", "mistakes", "possible_mistakes", "first_divergence", "probes",
                                    "probes_group"}) {
                QVERIFY2(d.value(key) == live.doc.value(key), key);
            }
            QVERIFY(d.value("simulator").isNull());
            QVERIFY(!d.value("answers_from").toString().isEmpty());
        }
    }

    // Offline answers that are not what the probe asked: exit 2, the file, the line and
    // the reason. `edit`: delete, keep:N (the first N lines), replace:N:TEXT, append:TEXT.
    void badOfflineAnswers_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("edit");
        QTest::addColumn<QStringList>("args");   // after "diagnose"; %1 = the folder
        QTest::addColumn<QString>("message");
        const QStringList dir{"%1"};
        const QStringList csv{"--trajectory", "%1/answers.csv"};
        QTest::newRow("states missing") << "motion-02.states" << "delete" << dir
                                        << "motion-02.states: cannot read: ";
        QTest::newRow("states short") << "motion-01.states" << "keep:2" << dir
                                      << "motion-01.states: 2 answers, the probe asks 4 (none for probe 1 (motion-01), "
                                         "step 3, its answer to \"state 0\": did your program stop early?)";
        QTest::newRow("states garbage") << "motion-01.states" << "replace:2:hello world" << dir
                                        << "motion-01.states:2: \"hello world\": expected 9 or 13 numbers (probe 1 "
                                           "(motion-01), step 2, its answer to \"state 0\")";
        QTest::newRow("states nan") << "motion-03.states" << "replace:3:1 2 3 4 5 6 nan 8 9" << dir
                                    << "motion-03.states:3: your simulator printed nan (probe 3 (motion-03), step 2, "
                                       "its answer to \"state 0\")";
        QTest::newRow("states extra") << "motion-01.states" << "append:0 0 0 0 0 0 0 0 0" << dir
                                      << "motion-01.states:5: an answer where none was asked for (the probe asks 4)";
        QTest::newRow("commands edited") << "motion-02.commands" << "replace:3:state 0" << dir
                                         << "motion-02.commands:3: not the workbook's probe motion-02";
        QTest::newRow("group not written") << "motion-04.commands" << "delete" << QStringList{"%1", "--probes", "motion"}
                                           << "motion-04.commands: cannot read: no such file";
        QTest::newRow("csv header") << "answers.csv" << "replace:1:probe,step,body,x,y,z" << csv
                                    << "answers.csv:1: the header must be \"probe,step,body,x,y,z,vx,vy,vz,wx,wy,wz,qw,qx,"
                                       "qy,qz\"";
        QTest::newRow("csv fields") << "answers.csv" << "replace:2:motion-01,1,0,1,2" << csv
                                    << "answers.csv:2: 5 fields, expected 16";
        QTest::newRow("csv probe") << "answers.csv" << "replace:2:motion-99,1,0,0,0,0,0,0,0,0,0,0,,,," << csv
                                   << "answers.csv:2: no probe \"motion-99\"";
        QTest::newRow("csv order") << "answers.csv" << "replace:2:motion-01,2,0,0,0,0,0,0,0,0,0,0,,,," << csv
                                   << "answers.csv:2: step \"2\", body \"0\"; the next answer of motion-01 is step 1, "
                                      "body 0";
        QTest::newRow("csv half r") << "answers.csv" << "replace:2:motion-01,1,0,0,0,0,0,0,0,0,0,0,1,,," << csv
                                    << "answers.csv:2: qw, qx, qy, qz must all be given or all be empty";
        QTest::newRow("csv inf") << "answers.csv" << "replace:2:motion-01,1,0,inf,0,0,0,0,0,0,0,0,,,," << csv
                                 << "answers.csv:2: your simulator printed inf (probe 1 (motion-01), step 1";
        QTest::newRow("csv short") << "answers.csv" << "keep:3" << csv
                                   << "answers.csv: probe motion-01 has 2 rows (from line 2), it asks 4";
        QTest::newRow("csv group") << "answers.csv" << "keep:5" << QStringList{"--trajectory", "%1/answers.csv",
                                                                                "--probes", "motion"}
                                   << "answers.csv: no rows for probe motion-02 (the group motion has it)";
    }
    void badOfflineAnswers()
    {
        QFETCH(QString, file);
        QFETCH(QString, edit);
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const QString dir = dir_.filePath(QStringLiteral("bad-") + QString(QTest::currentDataTag()).replace(' ', '-'));
        QVERIFY(writeAnsweredFolder(dir, {}));
        QVERIFY(writeTrajectory(dir, dir + "/answers.csv"));
        // negative control: untouched, the folder and the CSV are read
        QCOMPARE(rbw::test::runRbw({"diagnose", dir}).exitCode, 0);
        QCOMPARE(rbw::test::runRbw({"diagnose", "--trajectory", dir + "/answers.csv"}).exitCode, 0);

        const QString path = dir + "/" + file;
        if (edit == "delete") {
            QVERIFY(QFile::remove(path));
        } else {
            QFile f(path);
            QVERIFY(f.open(QIODevice::ReadOnly));
            QStringList lines = QString::fromUtf8(f.readAll()).split('\n');
            f.close();
            if (lines.last().isEmpty()) lines.removeLast();
            const QStringList parts = edit.split(':');
            if (parts[0] == "keep") lines = lines.mid(0, parts[1].toInt());
            if (parts[0] == "replace") lines[parts[1].toInt() - 1] = edit.section(':', 2);
            if (parts[0] == "append") lines << edit.section(':', 1);
            QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
            f.write((lines.join('\n') + '\n').toUtf8());
        }
        QStringList full{"diagnose"};
        for (const QString& a : args) full << QString(a).replace("%1", dir);
        const rbw::test::RbwRun r = rbw::test::runRbw(full);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(dir + "/" + file), qPrintable(r.err));
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
    }

private:
    // rbw probes --output dir, then the reference simulator (with simulatorArgs) on each
    // .commands file, its answers to the .states file beside it.
    static bool writeAnsweredFolder(const QString& dir, const QStringList& simulatorArgs)
    {
        const rbw::test::RbwRun written = rbw::test::runRbw({"probes", "--output", dir});
        if (written.exitCode != 0 || !written.out.contains("probes written to")) {
            qWarning("rbw probes: %s", qPrintable(written.err));
            return false;
        }
        const QStringList files = QDir(dir).entryList({"*.commands"}, QDir::Files, QDir::Name);
        if (files.size() != static_cast<qsizetype>(rbw::probes::probesOf(rbw::probes::ProbeGroup::All).size())) {
            return false;
        }
        for (const QString& f : files) {
            QProcess p;
            p.setStandardInputFile(dir + "/" + f);
            p.setStandardOutputFile(dir + "/" + QString(f).replace(".commands", ".states"));
            p.start(kReference, simulatorArgs);
            if (!p.waitForFinished(30000) || p.exitCode() != 0) return false;
        }
        return true;
    }

    // The folder's answers as the trajectory CSV: a row per `state` answer, the probe's
    // name, its step and body (answerSlots), the numbers of the .states line.
    static bool writeTrajectory(const QString& dir, const QString& csv)
    {
        QByteArray text = "probe,step,body,x,y,z,vx,vy,vz,wx,wy,wz,qw,qx,qy,qz\n";
        for (const rbw::probes::Probe& probe : rbw::probes::probesOf(rbw::probes::ProbeGroup::All)) {
            QFile states(dir + "/" + QString::fromStdString(probe.name) + ".states");
            if (!states.open(QIODevice::ReadOnly)) return false;
            const QList<QByteArray> lines = states.readAll().trimmed().split('\n');
            const std::vector<rbw::probes::AnswerSlot> asked = rbw::probes::answerSlots(probe);
            if (lines.size() != static_cast<qsizetype>(asked.size())) return false;
            for (std::size_t k = 0; k < asked.size(); ++k) {
                QList<QByteArray> numbers = lines[static_cast<qsizetype>(k)].simplified().split(' ');
                if (numbers.size() == 9) numbers << "" << "" << "" << "";
                text += QByteArray::fromStdString(probe.name) + ',' + QByteArray::number(asked[k].step) + ',' +
                        QByteArray::number(asked[k].body) + ',' + numbers.join(',') + '\n';
            }
        }
        QFile out(csv);
        return out.open(QIODevice::WriteOnly) && out.write(text) == text.size();
    }


    QTemporaryDir dir_;
};

QTEST_GUILESS_MAIN(TestDiagnose)
#include "tst_diagnose.moc"
