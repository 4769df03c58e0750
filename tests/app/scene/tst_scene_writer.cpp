// The scene writer (app/scene/scene_writer.h) against the loader: every lesson, and
// scenes built in code, read back bit for bit, load(write(scene)) == scene; the text
// is a fixed point (write(load(write(s))) == write(s)); files are written through
// QSaveFile. Negative controls: sceneDifferences() sees a change of one field,
// down to the last bit of a quaternion, so an empty difference means equal.
#include "app/core/lesson_catalogue.h"
#include "app/scene/scene_loader.h"
#include "app/scene/scene_writer.h"
#include "physics/engine/world.h"
#include "tests/test_support.h"

#include <QDir>
#include <QFile>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <limits>

using namespace rbw;

namespace {

// Every scene file under lessons/ (lesson scenes and variants; exercise.json is not a scene).
QStringList lessonSceneFiles()
{
    QStringList files;
    const QDir root(QStringLiteral(RBW_SOURCE_DIR "/lessons"));
    for (const QString& folder : root.entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name)) {
        const QDir d(root.filePath(folder));
        for (const QString& f : d.entryList({"*.json"}, QDir::Files, QDir::Name)) {
            if (f != QLatin1String("exercise.json")) files << folder + '/' + f;
        }
    }
    return files;
}

SceneDef reread(const SceneDef& s, QStringList* errors)
{
    const SceneLoadResult r = parseScene(writeScene(s), QStringLiteral("written.json"));
    *errors = r.errors;
    return r.ok() ? *r.scene : SceneDef{};
}

} // namespace

class TestSceneWriter : public QObject {
    Q_OBJECT
private slots:
    void lessonsRoundTrip_data()
    {
        QTest::addColumn<QString>("file");
        const QStringList files = lessonSceneFiles();
        QVERIFY(files.size() >= 14);   // ten lessons and their variants
        for (const QString& f : files) QTest::newRow(qPrintable(f)) << f;
    }
    void lessonsRoundTrip()
    {
        QFETCH(QString, file);
        const SceneDef original = test::lessonScene(file);
        QStringList errors;
        const SceneDef back = reread(original, &errors);
        QVERIFY2(errors.isEmpty(), qPrintable(errors.join('\n')));
        const QStringList diff = sceneDifferences(original, back);
        QVERIFY2(diff.isEmpty(), qPrintable(diff.join('\n')));
        // The text is a fixed point: writing what was read back gives the same bytes.
        QCOMPARE(writeScene(back), writeScene(original));
        // And it steps the same: 20 steps, every state bit for bit.
        World a(original), b(back);
        for (int k = 0; k < 20; ++k) {
            a.step(nullptr);
            b.step(nullptr);
        }
        for (std::size_t i = 0; i < original.bodies.size(); ++i) {
            QCOMPARE(test::flat(b.states()[i].x_W), test::flat(a.states()[i].x_W));
            QCOMPARE(test::flat(b.states()[i].q_WB), test::flat(a.states()[i].q_WB));
        }
    }

    // Scenes built in code: orientations from random axes and angles and tilted plane
    // normals, unit only to rounding; normalised again they would move by a bit, so the
    // loader keeps such a vector as written.
    void randomOrientationsRoundTrip()
    {
        QRandomGenerator rng(12345);
        SceneDef s = test::lessonScene("01-one-step/scene.json");
        int nudged = 0;
        for (int n = 0; n < 2000; ++n) {
            const Vec3 axis(rng.generateDouble() - 0.5, rng.generateDouble() - 0.5, rng.generateDouble() - 0.5);
            s.bodies[0].q0_WB = Quat(Eigen::AngleAxisd(10 * rng.generateDouble(), axis.normalized()));
            s.planes = {PlaneDef{"p", Vec3(0, -3, 0), Vec3(rng.generateDouble(), 1, rng.generateDouble()).normalized()}};
            const Quat q = s.bodies[0].q0_WB;
            if (Quat(q.w(), q.x(), q.y(), q.z()).normalized().coeffs() != q.coeffs()) ++nudged;
            QStringList errors;
            const SceneDef back = reread(s, &errors);
            QVERIFY2(errors.isEmpty(), qPrintable(errors.join('\n')));
            const QStringList diff = sceneDifferences(s, back);
            QVERIFY2(diff.isEmpty(), qPrintable(QStringLiteral("case %1: ").arg(n) + diff.join('\n')));
        }
        // The case the rule exists for occurred (else this test proved nothing).
        QVERIFY2(nudged > 0, "no quaternion would have moved");
    }

    // Every optional part of a scene in one, each away from its default.
    void everyFieldRoundTrips()
    {
        SceneDef s = test::lessonScene("07-bounce/scene.json");
        s.name = "Ünïcode \"quoted\" \\ name";
        s.description = "line\nbreak";
        s.steps = 1000000000;
        s.integrator = "rk4";
        s.inertiaConvention = InertiaConvention::CourseTemplate;
        s.bodies[0].integrator = "midpoint";
        s.bodies[0].inertiaConvention = InertiaConvention::Standard;
        s.bodies[0].angularResponse = false;
        s.torques = {TorqueDef{0, Vec3(0, 0, 1.5), 2, std::numeric_limits<long>::max(), true, false, ""},
                     TorqueDef{0, Vec3(1e-300, 0, 0), 0, 7, false, true, ""}};
        s.push = PushDef{0, Vec3(0.1, 0.2, 0.3), 2.5, ""};
        s.forces.push_back(ForceDef{0, Vec3(1, 2, 3), Vec3(0.1, 0.2, 0.3), 9000000000000000L - 1, 9000000000000000L, ""});
        s.probes.push_back(ProbeDef{0, Vec3(0.25, 0.5, 0.125), ""});
        s.restitutionThreshold = 0.125;
        s.energyJumpFactor = 0;
        s.energyJumpFloor = 2.5e-7;
        // The manifold model with its own keys (lesson 7's course switches do not apply to it;
        // the lessons' own round trip covers them).
        s.contactModel = ContactModel::Manifold;
        s.positionCorrection = false;
        s.planeContacts = PlaneContactMode::PerPoint;
        s.solverIterations = 7;
        s.sleep = false;
        s.positionFix = PositionFix::Baumgarte;
        s.solver = ManifoldSolver::SequentialImpulses;   // given, though the default
        const std::vector<SceneIssue> issues = validate(s);
        QVERIFY2(issues.empty(), issues.empty() ? "" : issues.front().reason.c_str());
        QStringList errors;
        const SceneDef back = reread(s, &errors);
        QVERIFY2(errors.isEmpty(), qPrintable(errors.join('\n')));
        const QStringList diff = sceneDifferences(s, back);
        QVERIFY2(diff.isEmpty(), qPrintable(diff.join('\n')));
    }

    // Negative controls: one changed field is one difference, at its path.
    void differencesAreSeen_data()
    {
        QTest::addColumn<int>("mutation");
        QTest::addColumn<QString>("path");
        QTest::newRow("mass") << 0 << "bodies[0].mass";
        QTest::newRow("quaternion, last bit") << 1 << "bodies[0].orientation[1]";
        QTest::newRow("force lifetime") << 2 << "forces[0].to_step";
        QTest::newRow("probe point") << 3 << "probes[1].point[2]";
        QTest::newRow("fixed") << 4 << "bodies[0].fixed";
        QTest::newRow("dt") << 5 << "dt";
        QTest::newRow("a body more") << 6 << "bodies";
        QTest::newRow("solver iterations given") << 7 << "solver_iterations";
        QTest::newRow("solver given") << 8 << "solver";
        QTest::newRow("substeps given") << 9 << "substeps";
    }
    void differencesAreSeen()
    {
        QFETCH(int, mutation);
        QFETCH(QString, path);
        const SceneDef a = test::lessonScene("01-one-step/scene.json");
        SceneDef b = a;
        switch (mutation) {
        case 0: b.bodies[0].mass = 2.0000000000000004; break;
        case 1: b.bodies[0].q0_WB.x() = std::nextafter(a.bodies[0].q0_WB.x(), 1.0); break;
        case 2: b.forces[0].toStep += 1; break;
        case 3: b.probes[1].p0_W.z() = -b.probes[1].p0_W.z(); break;
        case 4: b.bodies[0].fixed = true; break;
        case 5: b.dt = 1.0; break;
        case 6: b.bodies.push_back(a.bodies[0]); break;
        case 7: b.solverIterations = 10; break;   // the default's value, but given
        case 8: b.solver = ManifoldSolver::SoftStep; break;
        case 9: b.substeps = 5; break;   // the default's value, but given
        }
        const QStringList diff = sceneDifferences(a, b);
        QCOMPARE(diff.size(), 1);
        QVERIFY2(diff.first().startsWith(path + ':'), qPrintable(diff.first()));
        QVERIFY(sceneDifferences(a, a).isEmpty());
    }

    void savesThroughQSaveFile()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const SceneDef s = test::lessonScene("03-two-box-collision/scene.json");
        const QString path = dir.filePath("mine.json");
        QString error;
        QVERIFY2(saveSceneFile(s, path, &error), qPrintable(error));
        const SceneLoadResult r = loadSceneFile(path);
        QVERIFY2(r.ok(), qPrintable(r.errors.join('\n')));
        QVERIFY(sceneDifferences(s, *r.scene).isEmpty());
        // Written again with other numbers, the file holds the new scene.
        SceneDef other = s;
        other.dt = 0.5;
        QVERIFY2(saveSceneFile(other, path, &error), qPrintable(error));
        QCOMPARE(loadSceneFile(path).scene->dt, 0.5);
        // A write that cannot happen (the folder is a file) says where and why, and
        // leaves nothing behind.
        const QString impossible = path + QStringLiteral("/inside.json");
        QVERIFY(!saveSceneFile(s, impossible, &error));
        QVERIFY2(error.startsWith(impossible + ": cannot write"), qPrintable(error));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{"mine.json"});
    }
};

QTEST_GUILESS_MAIN(TestSceneWriter)
#include "tst_scene_writer.moc"
