// rbw diagnose's offline mode (issue 23): rbw probes writes the probe files, the
// reference simulator's .states files answer them, and rbw diagnose DIR and
// --trajectory give the live verdict; bad offline answers name file and line.
#include "tests/app/cli/diagnose_support.h"

#include "physics/workbook/probes/probes.h"
#include "physics/workbook/probes/replay.h"

#include <QDir>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

using namespace rbw::test::diagnose;

class TestDiagnoseOffline : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        QVERIFY2(QFile::exists(kReference), qPrintable(kReference));
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
                                      << "explained";   // by the pair
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
                                         "after step k = 2, its answer to \"state 0\": did your program stop early?)";
        QTest::newRow("states garbage") << "motion-01.states" << "replace:2:hello world" << dir
                                        << "motion-01.states:2: \"hello world\": expected 9 or 13 numbers (probe 1 "
                                           "(motion-01), after step k = 1, its answer to \"state 0\")";
        QTest::newRow("states nan") << "motion-03.states" << "replace:3:1 2 3 4 5 6 nan 8 9" << dir
                                    << "motion-03.states:3: your simulator printed nan (probe 3 (motion-03), after step k = 1, "
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
                                   << "answers.csv:2: step \"2\", body \"0\"; the next answer of motion-01 has step 1 "
                                      "(the state after step k = 0), body 0";
        QTest::newRow("csv half r") << "answers.csv" << "replace:2:motion-01,1,0,0,0,0,0,0,0,0,0,0,1,,," << csv
                                    << "answers.csv:2: qw, qx, qy, qz must all be given or all be empty";
        QTest::newRow("csv inf") << "answers.csv" << "replace:2:motion-01,1,0,inf,0,0,0,0,0,0,0,0,,,," << csv
                                 << "answers.csv:2: your simulator printed inf (probe 1 (motion-01), after step k = 0";
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

QTEST_GUILESS_MAIN(TestDiagnoseOffline)
#include "tst_diagnose_offline.moc"
