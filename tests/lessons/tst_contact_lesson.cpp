// Lesson 11 (issue 11): its one derivation template serves both of its scenes, the
// manifold model (scene.json) and the course model (course.json): at the first contact
// and a second later every placeholder finds its number, the template has no error,
// and each model's own rows appear (the control: the other model's rows do not).
#include "app/scene/scene_loader.h"
#include "app/derivation/derivation_builder.h"
#include "physics/engine/world.h"

#include <QtTest>

namespace {

const QString kLesson = QStringLiteral(RBW_SOURCE_DIR "/lessons/11-resting-contact");

rbw::SceneDef load(const QString& file)
{
    const rbw::SceneLoadResult r = rbw::loadSceneFile(kLesson + QLatin1Char('/') + file);
    if (!r.ok()) qFatal("%s", qPrintable(r.errors.join('\n')));
    return *r.scene;
}

} // namespace

class TestContactLesson : public QObject {
    Q_OBJECT

private slots:
    void derivationForBothModels_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("ownRow");
        QTest::addColumn<QString>("otherRow");
        QTest::addColumn<bool>("soft");
        QTest::newRow("manifold") << "scene.json" << "sweep of the solver" << "lesson 3 derives it" << false;
        QTest::newRow("course") << "course.json" << "lesson 3 derives it" << "feature id" << false;
        // The same scene with the soft step: its own section, not the iterations' one
        QTest::newRow("manifold, soft step") << "scene.json" << "The soft step" << "sweep of the solver" << true;
    }

    void derivationForBothModels()
    {
        QFETCH(QString, file);
        QFETCH(QString, ownRow);
        QFETCH(QString, otherRow);
        QFETCH(bool, soft);
        rbw::SceneDef scene = load(file);
        if (soft) scene.solver = rbw::ManifoldSolver::SoftStep;
        rbw::World w(scene);
        rbw::StepTrace t;
        int withContacts = 0;
        for (int k = 0; k < 90; ++k) {
            QVERIFY(w.step(&t).ok);
            if (t.contacts.empty() || (k != 30 && k != 89 && withContacts > 0)) continue;
            ++withContacts;
            const rbw::DerivationDocument doc = rbw::buildLessonDerivation(t, scene, kLesson);
            QVERIFY2(!doc.fallback, qPrintable(doc.errors.join('\n')));
            QVERIFY2(doc.errors.isEmpty(), qPrintable(doc.errors.join('\n')));
            QVERIFY2(doc.notes.isEmpty(), qPrintable(doc.notes.join('\n')));
            QVERIFY(doc.html.contains(ownRow));
            QVERIFY(!doc.html.contains(otherRow));
        }
        QVERIFY(withContacts >= 2);
    }

    // @iterations writes a manifold point's impulses after each velocity iteration: in
    // the manifold model one table per point with one row per iteration the solver ran
    // (solver_iterations) and a warm-start row; nothing in the course model (the
    // control). Outside a contact loop it is an error that names the line.
    void iterationTable_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<bool>("tables");
        QTest::newRow("manifold") << "scene.json" << true;
        QTest::newRow("course (control)") << "course.json" << false;
    }

    void iterationTable()
    {
        QFETCH(QString, file);
        QFETCH(bool, tables);
        const rbw::SceneDef scene = load(file);
        rbw::World w(scene);
        rbw::StepTrace t;
        for (int k = 0; k < 90 && t.contacts.empty(); ++k) QVERIFY(w.step(&t).ok);
        QVERIFY(!t.contacts.empty());
        const rbw::DerivationDocument doc = rbw::buildLessonDerivation(t, scene, kLesson);
        QVERIFY2(doc.errors.isEmpty(), qPrintable(doc.errors.join('\n')));
        const int warmRows = static_cast<int>(doc.html.count(QStringLiteral("\\text{(warm start)}")));
        QCOMPARE(warmRows, tables ? static_cast<int>(t.contacts.size()) : 0);
        if (tables) {
            // iterations 1 .. n in every table: "n &" opens the last row
            const rbw::TraceEntry* used = t.find("solver_iterations", -1);
            QVERIFY(used != nullptr);
            const int n = static_cast<int>(std::get<double>(used->value));
            QVERIFY(n >= 1);
            QCOMPARE(static_cast<int>(doc.html.count(QStringLiteral("\\\\ %1 &amp; ").arg(n))), warmRows);
            // Under each table: what one iteration is (ContactHeader::iteration)
            QCOMPARE(static_cast<int>(doc.html.count(QStringLiteral("One iteration: one sweep of the sequential impulses"))),
                     warmRows);
        }
        // Misuse: @iterations outside @foreach contact
        const rbw::DerivationDocument wrong = rbw::buildDerivation(t, scene, QStringLiteral("# x\n@iterations\n"),
                                                                   QStringLiteral("wrong.md"));
        QVERIFY2(wrong.errors.join('\n').contains(QStringLiteral("wrong.md:2: @iterations needs a contact")),
                 qPrintable(wrong.errors.join('\n')));
    }
};

QTEST_GUILESS_MAIN(TestContactLesson)
#include "tst_contact_lesson.moc"
