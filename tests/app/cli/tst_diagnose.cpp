// rbw diagnose --simulator through the real binary (issue 23, docs/simulator-protocol.md):
// the shipped reference simulator (examples/simulator/, target rbw_reference_simulator)
// matches, in double and in float, and so do its Python twin and the TUM adapter around
// the template stand-in (9 numbers an answer); with each motion mistake switched on (--mistake ID)
// it is explained by exactly that id; programs that print nan, exit, hang or print
// garbage (shell scripts written here) end with status 2, a message that names the
// probe, the step and the command, and no process of theirs left running.
#include "tests/test_support.h"

#include "physics/workbook/probes/probe_models.h"
#include "physics/workbook/probes/replay.h"

#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QThread>
#include <QtTest>

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
        QCOMPARE(probes.size(), static_cast<qsizetype>(rbw::probes::motionProbes().size()));
        for (const QJsonValue& p : probes) QVERIFY(p.toObject().value("matches").toBool());
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
        QTest::newRow("no simulator") << QStringList{"diagnose"} << "--simulator \"CMD\" is required";
        QTest::newRow("cannot start") << QStringList{"diagnose", "--simulator", "/nonexistent/sim --x"}
                                      << "cannot start the simulator \"/nonexistent/sim\"";
        QTest::newRow("timeout") << QStringList{"diagnose", "--simulator", kReference, "--timeout", "-1"}
                                 << "--timeout: must be a number of seconds > 0";
        QTest::newRow("format") << QStringList{"diagnose", "--simulator", kReference, "--format", "csv"}
                                << "--format: must be text or json for diagnose, got \"csv\"";
        QTest::newRow("folder") << QStringList{"diagnose", "probes"} << "is not built yet";
    }
    void badInput()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const rbw::test::RbwRun r = rbw::test::runRbw(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
    }

private:
    QTemporaryDir dir_;
};

QTEST_GUILESS_MAIN(TestDiagnose)
#include "tst_diagnose.moc"
