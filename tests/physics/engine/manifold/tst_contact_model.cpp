// The contact-model keys of a scene file (issue 11): "contact_model", "solver_iterations",
// "sleep", "position_fix" read by the loader, their rules in validate() (messages with
// field and reason, exit 2 through the real rbw), the pipeline each model builds, and the
// manifold trace rows.
#include "tests/test_support.h"

#include "app/scene/scene_loader.h"
#include "physics/engine/manifold/settings.h"
#include "physics/engine/world.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

namespace {

// A box above the ground; `extra` is spliced into the top-level object.
QByteArray sceneJson(const QString& extra)
{
    return QStringLiteral(R"({ "dt": 0.01, "steps": 20, "gravity": [0, -9.81, 0], %1
  "planes": [ { "name": "ground", "point": [0, 0, 0], "normal": [0, 1, 0] } ],
  "bodies": [ { "name": "box", "size": [1, 1, 1], "mass": 1, "position": [0, 0.6, 0] } ] })")
        .arg(extra)
        .toUtf8();
}

} // namespace

class TestContactModel : public QObject {
    Q_OBJECT

private slots:
    void defaults()
    {
        const rbw::SceneLoadResult course = rbw::parseScene(sceneJson(QString()), QStringLiteral("s.json"));
        QVERIFY(course.ok());
        QCOMPARE(course.scene->contactModel, rbw::ContactModel::Course);
        QVERIFY(!course.scene->solverIterations && !course.scene->sleep && !course.scene->positionFix);
        const rbw::SceneLoadResult manifold =
            rbw::parseScene(sceneJson(QStringLiteral(R"("contact_model": "manifold",)")), QStringLiteral("s.json"));
        QVERIFY(manifold.ok());
        QCOMPARE(manifold.scene->contactModel, rbw::ContactModel::Manifold);
        // Unset keys: ManifoldSettings' defaults, the model's one set of them (settings.h)
        const rbw::ManifoldSettings defaults = rbw::manifoldSettings(*manifold.scene);
        QCOMPARE(defaults.iterations, 10);
        QCOMPARE(defaults.sleep, true);
        QCOMPARE(defaults.positionFix, rbw::PositionFix::Ngs);
        const rbw::SceneLoadResult set = rbw::parseScene(
            sceneJson(QStringLiteral(
                R"("contact_model": "manifold", "solver": "sequential-impulses", "solver_iterations": 25, "sleep": false, "position_fix": "baumgarte",)")),
            QStringLiteral("s.json"));
        QVERIFY(set.ok());
        const rbw::ManifoldSettings chosen = rbw::manifoldSettings(*set.scene);
        QCOMPARE(chosen.iterations, 25);
        QCOMPARE(chosen.sleep, false);
        QCOMPARE(chosen.positionFix, rbw::PositionFix::Baumgarte);
        QCOMPARE(defaults.solver, rbw::ManifoldSolver::SoftStep);   // the default since issue 19
        QCOMPARE(chosen.solver, rbw::ManifoldSolver::SequentialImpulses);
        QCOMPARE(defaults.substeps, 5);
        const rbw::SceneLoadResult soft = rbw::parseScene(
            sceneJson(QStringLiteral(R"("contact_model": "manifold", "solver": "soft-step", "substeps": 6,)")),
            QStringLiteral("s.json"));
        QVERIFY(soft.ok());
        QCOMPARE(rbw::manifoldSettings(*soft.scene).solver, rbw::ManifoldSolver::SoftStep);
        QCOMPARE(rbw::manifoldSettings(*soft.scene).substeps, 6);
    }

    // Each bad value is refused with its field and reason, through the real rbw (exit 2).
    void badValues_data()
    {
        QTest::addColumn<QString>("extra");
        QTest::addColumn<QString>("message");
        QTest::newRow("unknown model") << R"("contact_model": "manifolds",)"
                                       << R"(contact_model: must be "course" or "manifold", got "manifolds")";
        QTest::newRow("not a word") << R"("contact_model": 1,)" << "contact_model: must be a string, got a number";
        QTest::newRow("iterations 0") << R"("contact_model": "manifold", "solver": "sequential-impulses", "solver_iterations": 0,)"
                                      << "solver_iterations: must be a whole number from 1 to 1000, got 0";
        QTest::newRow("iterations too many") << R"("contact_model": "manifold", "solver": "sequential-impulses", "solver_iterations": 5000,)"
                                             << "solver_iterations: must be a whole number from 1 to 1000, got 5000";
        QTest::newRow("iterations not whole") << R"("contact_model": "manifold", "solver": "sequential-impulses", "solver_iterations": 2.5,)"
                                              << "solver_iterations: must be a whole number, got 2.5";
        QTest::newRow("sleep not a bool") << R"("contact_model": "manifold", "sleep": "yes",)"
                                          << "sleep: must be true or false, got a string";
        QTest::newRow("unknown fix") << R"("contact_model": "manifold", "solver": "sequential-impulses", "position_fix": "split",)"
                                     << R"(position_fix: must be "ngs", "baumgarte" or "none", got "split")";
        QTest::newRow("iterations in the course model") << R"("solver_iterations": 20,)"
            << R"(solver_iterations: the key belongs to the manifold model; add "contact_model": "manifold" or leave it out)";
        QTest::newRow("sleep in the course model") << R"("sleep": true,)"
            << R"(sleep: the key belongs to the manifold model; add "contact_model": "manifold" or leave it out)";
        QTest::newRow("course correction in the manifold model")
            << R"("contact_model": "manifold", "position_correction": true,)"
            << R"(position_correction: belongs to the course model; the manifold model fixes positions itself ("position_fix"))";
        QTest::newRow("averaged plane contacts in the manifold model")
            << R"("contact_model": "manifold", "plane_contacts": "average",)"
            << "plane_contacts: belongs to the course model; the manifold model keeps every corner below a plane as a "
               "point of its manifold";
        QTest::newRow("unknown solver") << R"("contact_model": "manifold", "solver": "soft",)"
                                        << R"(solver: must be "sequential-impulses" or "soft-step", got "soft")";
        QTest::newRow("substeps 0") << R"("contact_model": "manifold", "solver": "soft-step", "substeps": 0,)"
                                    << "substeps: must be a whole number from 1 to 64, got 0";
        QTest::newRow("substeps with the sequential impulses")
            << R"("contact_model": "manifold", "solver": "sequential-impulses", "substeps": 4,)"
            << R"(substeps: belongs to the soft step; add "solver": "soft-step")";
        QTest::newRow("iterations without a solver (the soft step by default)")
            << R"("contact_model": "manifold", "solver_iterations": 10,)"
            << R"(solver_iterations: belongs to the sequential impulses; the soft step (the manifold model's default )"
               R"(solver) iterates once per substep ("substeps"); add "solver": "sequential-impulses" to use it)";
        QTest::newRow("position fix with the soft step")
            << R"("contact_model": "manifold", "solver": "soft-step", "position_fix": "ngs",)"
            << "position_fix: belongs to the sequential impulses; the soft step pushes overlap out inside its substeps";
        QTest::newRow("solver in the course model") << R"("solver": "soft-step",)"
            << R"(solver: the key belongs to the manifold model; add "contact_model": "manifold" or leave it out)";
        QTest::newRow("misspelt key") << R"("contact_modle": "manifold",)"
                                      << R"(contact_modle: unknown key (did you mean "contact_model"?))";
    }

    void badValues()
    {
        QFETCH(QString, extra);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("scene.json"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(sceneJson(extra));
        f.close();
        const rbw::test::RbwRun run = rbw::test::runRbw({QStringLiteral("run"), path});
        QCOMPARE(run.exitCode, 2);
        const QString err = run.err;
        QVERIFY2(err.contains(message), qPrintable(err));
    }

    // The pipeline runs only what the model needs: the course stages or the manifold ones.
    void pipelines()
    {
        const rbw::SceneLoadResult course = rbw::parseScene(
            sceneJson(QStringLiteral(R"("position_correction": true,)")), QStringLiteral("s.json"));
        QVERIFY(course.ok());
        QCOMPARE(rbw::World(*course.scene).pipelineLabels(),
                 (std::vector<std::string>{"gravity", "loads", "energy_bound", "integration:explicit-euler",
                                           "finite_check", "energy_check", "box_plane", "correction", "finite_check"}));
        const rbw::SceneLoadResult manifold =
            rbw::parseScene(sceneJson(QStringLiteral(R"("contact_model": "manifold",)")), QStringLiteral("s.json"));
        QCOMPARE(rbw::World(*manifold.scene).pipelineLabels(),
                 (std::vector<std::string>{"gravity", "loads", "manifold_contacts", "energy_bound",
                                           "manifold_velocities", "integration:explicit-euler", "finite_check",
                                           "energy_check",
                                           "manifold_positions", "sleep", "finite_check"}));
        const rbw::SceneLoadResult awake = rbw::parseScene(
            sceneJson(QStringLiteral(R"("contact_model": "manifold", "sleep": false,)")), QStringLiteral("s.json"));
        QCOMPARE(rbw::World(*awake.scene).pipelineLabels(),
                 (std::vector<std::string>{"gravity", "loads", "manifold_contacts", "energy_bound",
                                           "manifold_velocities", "integration:explicit-euler", "finite_check",
                                           "energy_check",
                                           "manifold_positions", "finite_check"}));
    }

    // Every manifold point is in the trace with its numbers; the course rows are not.
    void traceRows()
    {
        const rbw::SceneLoadResult r =
            rbw::parseScene(sceneJson(QStringLiteral(R"("contact_model": "manifold", "solver": "sequential-impulses",)")),
                            QStringLiteral("s.json"));
        rbw::World w(*r.scene);
        rbw::StepTrace t;
        for (int k = 0; k < 20 && t.contacts.empty(); ++k) w.step(&t);
        QCOMPARE(t.contacts.size(), std::size_t(4));   // the 4 lower corners, one header each
        for (int i = 0; i < 4; ++i) {
            QCOMPARE(QString::fromLatin1(t.contacts[static_cast<std::size_t>(i)].resolution), QStringLiteral("manifold"));
            for (const char* id : {"point", "normal", "depth", "feature_id", "normal_velocity", "target_normal_velocity",
                                   "normal_mass", "warm_start_normal", "warm_start_tangent", "normal_impulse",
                                   "tangent_impulse"}) {
                QVERIFY2(t.find(id, 0, i) != nullptr, id);
            }
            QVERIFY(t.find("impulse", 0, i) == nullptr);   // the course's J: not in this model
        }
        for (const char* id : {"solver_iterations", "manifold_points", "deepest_overlap"}) {
            QVERIFY2(t.find(id, -1) != nullptr, id);
        }
        QVERIFY(t.find("contact_force", 0) != nullptr);
        QVERIFY(t.find("sleep_time", 0) != nullptr);
        QVERIFY(t.find("asleep", 0) != nullptr);
    }

    // `rbw run --format json` writes each manifold contact's impulses after every
    // velocity iteration ("iterations"): as many as the step's solver_iterations, the
    // last equal to the contact's normal_impulse and tangent_impulse. The course model's
    // contacts have none (the control).
    void jsonIterations_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<bool>("manifold");
        QTest::newRow("manifold") << "scene.json" << true;
        QTest::newRow("course (control)") << "course.json" << false;
    }

    void jsonIterations()
    {
        QFETCH(QString, file);
        QFETCH(bool, manifold);
        const rbw::test::RbwRun run = rbw::test::runRbw(
            {QStringLiteral("run"), QStringLiteral(RBW_SOURCE_DIR "/lessons/11-resting-contact/") + file,
             QStringLiteral("--trace"), QStringLiteral("all"), QStringLiteral("--steps"), QStringLiteral("40"),
             QStringLiteral("--format"), QStringLiteral("json")});
        QCOMPARE(run.exitCode, 0);
        int contacts = 0;
        for (const QJsonValue& stepValue : QJsonDocument::fromJson(run.out).object().value(QStringLiteral("trace")).toArray()) {
            const QJsonObject step = stepValue.toObject();
            double used = -1.0;
            for (const QJsonValue& q : step.value(QStringLiteral("quantities")).toArray()) {
                if (q.toObject().value(QStringLiteral("id")).toString() == QLatin1String("solver_iterations")) {
                    used = q.toObject().value(QStringLiteral("value")).toDouble();
                }
            }
            for (const QJsonValue& cValue : step.value(QStringLiteral("contacts")).toArray()) {
                const QJsonObject c = cValue.toObject();
                ++contacts;
                QCOMPARE(c.contains(QStringLiteral("iterations")), manifold);
                if (!manifold) continue;
                const QJsonArray iterations = c.value(QStringLiteral("iterations")).toArray();
                QCOMPARE(double(iterations.size()), used);
                const QJsonObject last = iterations.last().toObject();
                QCOMPARE(last.value(QStringLiteral("normal_impulse")).toDouble(),
                         c.value(QStringLiteral("normal_impulse")).toDouble());
                QCOMPARE(last.value(QStringLiteral("tangent_impulse")).toArray(),
                         c.value(QStringLiteral("tangent_impulse")).toArray());
            }
        }
        QVERIFY(contacts > 0);
    }
};

QTEST_GUILESS_MAIN(TestContactModel)
#include "tst_contact_model.moc"
