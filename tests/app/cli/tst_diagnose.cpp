// rbw diagnose through the real binary (issue 23, docs/simulator-protocol.md): the
// shipped reference simulator (examples/simulator/, target rbw_reference_simulator)
// matches, in double and in float, and so do its Python twin and the TUM adapter around
// the template stand-in (9 numbers an answer); the template's public tests (which version
// passes with which inertia convention); the text report; --format csv over several
// programs. The mistakes: tst_diagnose_mistakes; broken programs and bad options:
// tst_diagnose_broken; the offline mode: tst_diagnose_offline.
#include "tests/app/cli/diagnose_support.h"

#include "physics/workbook/probes/probes.h"

#include <QtTest>

#include <cmath>

using namespace rbw::test::diagnose;

class TestDiagnose : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
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


    void textReport()
    {
        const rbw::test::RbwRun r =
            rbw::test::runRbw({"diagnose", "--simulator", kReference + " --mistake lever-arm-from-origin"});
        QCOMPARE(r.exitCode, 1);
        const QString out = QString::fromUtf8(r.out);
        QVERIFY2(out.contains("verdict: explained"), qPrintable(out));
        QVERIFY2(out.contains("lever-arm-from-origin: q = p x f"), qPrintable(out));
        QVERIFY2(out.contains("first divergence from the right algorithm: probe 1 (motion-01), after step k = 0, body 0"),
                 qPrintable(out));
        QVERIFY2(out.contains("within 0.0001"), qPrintable(out));
    }

    // Issue 23: the report words a state as every screen of the app does
    // (app/core/step_numbering.h: steps k = 0, 1, ...; the state after n steps is "after
    // step k = n - 1"), while the JSON keeps its number, the steps taken n
    // (docs/simulator-protocol.md). The old words said "step 1" for the state after one
    // step, the app's step k = 0: this fails on them.
    void stepWordsAreTheApps()
    {
        const QString sim = kReference + " --mistake missing-time-step";
        const rbw::test::RbwRun json = rbw::test::runRbw({"diagnose", "--probes", "motion", "--format", "json", "--simulator", sim});
        const rbw::test::RbwRun text = rbw::test::runRbw({"diagnose", "--probes", "motion", "--simulator", sim});
        QCOMPARE(json.exitCode, 1);
        QCOMPARE(text.exitCode, 1);
        const QJsonObject f = QJsonDocument::fromJson(json.out).object().value("first_divergence").toObject();
        const int n = f.value("step").toInt();
        QVERIFY2(n >= 1, json.out.constData());   // a missing h shows after a step, not before any
        const QString out = QString::fromUtf8(text.out);
        const QString where = QStringLiteral("probe %1 (%2), after step k = %3, body %4")
                                  .arg(f.value("probe").toInt())
                                  .arg(f.value("probe_name").toString())
                                  .arg(n - 1)
                                  .arg(f.value("body").toInt());
        QVERIFY2(out.contains("first divergence from the right algorithm: " + where), qPrintable(out));
        // negative control: the old wording, the count of steps as a step number
        QVERIFY2(!out.contains(QStringLiteral("), step %1, body").arg(n)), qPrintable(out));
    }

};

QTEST_GUILESS_MAIN(TestDiagnose)
#include "tst_diagnose.moc"
