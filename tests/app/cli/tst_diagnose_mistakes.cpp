// rbw diagnose names the mistakes of the reference simulator (issue 23): with each
// motion mistake switched on (--mistake ID) it is explained by exactly that id; each
// collision mistake with a restitution the workbook is not told, with c fitted; a few
// pairs of two mistakes by both ids; three at once by no model.
#include "tests/app/cli/diagnose_support.h"

#include "physics/workbook/probes/collision_replay.h"
#include "physics/workbook/probes/probe_models.h"
#include "physics/workbook/probes/replay.h"

#include <QtTest>

#include <cmath>

using namespace rbw::test::diagnose;

class TestDiagnoseMistakes : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY2(QFile::exists(kReference), qPrintable(kReference));
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


    // Two mistakes at once (issue 23: "and for a few pairs"): the reference simulator with
    // two --mistake flags is explained by the pair, both ids in `mistakes` (catalogue
    // order), nothing possible; one motion pair, a motion with a collision model, two
    // collision models, with c = 0.35 to be fitted.
    void pairIsExplained_data()
    {
        QTest::addColumn<QStringList>("ids");
        QTest::addColumn<QString>("group");
        QTest::newRow("transposed-inertia + lever-arm-from-origin")
            << QStringList{"transposed-inertia", "lever-arm-from-origin"} << "all";
        QTest::newRow("torque-reversed + missing-time-step") << QStringList{"torque-reversed", "missing-time-step"}
                                                             << "motion";
        QTest::newRow("omega-accumulated + forces-not-cleared") << QStringList{"omega-accumulated", "forces-not-cleared"}
                                                                << "motion";
        QTest::newRow("transposed-inertia + impulse-linear-only")
            << QStringList{"transposed-inertia", "impulse-linear-only"} << "all";
        QTest::newRow("impulse-lever-arm-from-origin + impulse-body-inverse-inertia")
            << QStringList{"impulse-lever-arm-from-origin", "impulse-body-inverse-inertia"} << "collision";
    }
    void pairIsExplained()
    {
        QFETCH(QStringList, ids);
        QFETCH(QString, group);
        // the flags in the reverse order: the report's order is the catalogue's, not the command's
        const Diagnosed run = diagnoseJson(kReference + " --restitution 0.35 --mistake " + ids[1] + " --mistake " + ids[0],
                                           {"--probes", group});
        QCOMPARE(run.exitCode, 1);
        const QJsonObject& d = run.doc;
        QCOMPARE(d.value("verdict").toString(), QStringLiteral("explained"));
        QCOMPARE(d.value("mistakes").toArray(), QJsonArray::fromStringList(ids));
        QVERIFY(d.value("possible_mistakes").toArray().isEmpty());
        QVERIFY(d.value("possible_explanations").toArray().isEmpty());
        QCOMPARE(d.value("mistake_details").toArray().size(), 2);
        // each of the two alone explains less: the single models' rows never reach every probe
        for (const QString& id : ids) {
            const Diagnosed one = diagnoseJson(kReference + " --restitution 0.35 --mistake " + id, {"--probes", group});
            QCOMPARE(one.doc.value("mistakes").toArray(), QJsonArray{id});
        }
        if (group != "motion") {
            bool fitted = false;
            for (const QJsonValue& v : d.value("restitution").toArray()) {
                fitted = fitted || (v.toObject().value("model").toString() == ids.join(" + ") &&
                                    std::abs(v.toObject().value("c").toDouble() - 0.35) < 1e-4);
            }
            QVERIFY2(fitted, qPrintable(QJsonDocument(d.value("restitution").toArray()).toJson()));
        }
        const rbw::test::RbwRun text =
            rbw::test::runRbw({"diagnose", "--probes", group, "--simulator",
                               kReference + " --restitution 0.35 --mistake " + ids[0] + " --mistake " + ids[1]});
        QVERIFY2(text.out.contains("mistakes (the two together explain your answers):"), text.out.constData());
    }

    // Three mistakes at once are no model and no pair: the verdict must not claim one
    // explains them.
    void threeMistakesAreNotExplained()
    {
        const Diagnosed run = diagnoseJson(kReference +
                                           " --mistake torque-reversed --mistake transposed-inertia --mistake missing-time-step");
        QCOMPARE(run.exitCode, 1);
        const QString verdict = run.doc.value("verdict").toString();
        QVERIFY2(verdict == "partly-explained" || verdict == "unexplained", qPrintable(verdict));
        QVERIFY(run.doc.value("first_divergence").isObject());
    }
};

QTEST_GUILESS_MAIN(TestDiagnoseMistakes)
#include "tst_diagnose_mistakes.moc"
