// rbw diagnose with programs that break the protocol and with bad options (issue 23):
// programs that print nan, exit, hang or print garbage (shell scripts written here) end
// with status 2, a message that names the probe, the step and the command, and no
// process of theirs left running.
#include "tests/app/cli/diagnose_support.h"

#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QThread>
#include <QtTest>

using namespace rbw::test::diagnose;

class TestDiagnoseBroken : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        QVERIFY2(QFile::exists(kReference), qPrintable(kReference));
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
                             << "your simulator printed nan at probe 1, after step k = 0 (motion-01: its answer to \"state 0\"";
        QTest::newRow("exits") << loop.arg("step) echo dying >&2; exit 3;;")
                               << "your simulator exited with status 3 at probe 1, after step k = 0, before it answered "
                                  "\"state 0\" (motion-01)\nrbw: diagnose: its last lines on standard error:\n  dying";
        // the shell waits for a child of its own: both must be ended
        QTest::newRow("hangs") << loop.arg("step) sleep 30 & echo $! >> \"$PIDS\"; wait;;")
                               << "your simulator did not answer \"state 0\" at probe 1, after step k = 0 within 1 s (motion-01); "
                                  "it was stopped";
        QTest::newRow("garbage") << loop.arg("state) echo hello world;;")
                                 << "your simulator answered \"hello world\" to \"state 0\" at probe 1, after step k = 0 "
                                    "(motion-01); expected 9 or 13 numbers";
        QTest::newRow("extra output") << loop.arg("state) echo 0 0 0 0 0 0 0 0 0;; step) ;; reset) echo hi;;")
                                      << "your simulator answered \"hi\" to \"state 0\" at probe 1, after step k = 0";
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


private:
    QTemporaryDir dir_;
};

QTEST_GUILESS_MAIN(TestDiagnoseBroken)
#include "tst_diagnose_broken.moc"
