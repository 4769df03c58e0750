// Lesson 6's further exercise, 06-box-on-plane/separating (issue 21 item 9: an exercise in
// which no-separating-check can show; docs/exercises.md). Through the real binary, for
// seeds 1..20: `rbw exercise 06-box-on-plane/separating` makes a scene whose answer step
// is the first step with a separating contact (a cube that bounced is still below the
// ground and moves up, v_rel.n > 0), checked here by stepping the scene independently of
// the generator (no earlier step has one); the key writes J = 0 for every separating
// contact and `rbw check` accepts it (exit 0); the worksheet gives the state at the
// step's start and says which bodies each contact joins. Negative control: the J a
// student gets without the separation check (hand-derived for seed 1 in
// tst_exercise_mistakes.cpp, separatingKeyIsZeroAndTheModelIsNamed) fails the check
// (exit 1) and is named no-separating-check. An id that leaves the lessons is refused.
#include "tests/test_support.h"

#include "app/scene/scene_loader.h"
#include "physics/engine/world.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

namespace {

const QString kExercise = QStringLiteral("06-box-on-plane/separating");

QJsonObject readJson(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QJsonDocument::fromJson(f.readAll()).object();
}

QString readText(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QString::fromUtf8(f.readAll());
}

} // namespace

class TestExerciseSeparating : public QObject {
    Q_OBJECT

    QTemporaryDir dir_;

    QString path(const QString& name) const { return dir_.filePath(name); }

private slots:
    void seeds_data()
    {
        QTest::addColumn<int>("seed");
        for (int seed = 1; seed <= 20; ++seed) QTest::newRow(qPrintable("seed " + QString::number(seed))) << seed;
    }

    void seeds()
    {
        QFETCH(int, seed);
        const QString tag = QString::number(seed);
        const QString scene = path(tag + "-scene.json"), key = path(tag + "-key.json"), sheet = path(tag + "-sheet.html"),
                      keyHtml = path(tag + "-key.html");
        const rbw::test::RbwRun made = rbw::test::runRbw({"exercise", kExercise, "--seed", tag, "--output", scene,
                                                          "--answers-key", key, "--worksheet", sheet, "--answer-key", keyHtml});
        QVERIFY2(made.exitCode == 0, qPrintable(made.err));
        const QJsonObject keyDoc = readJson(key);
        const long step = keyDoc.value("step").toInteger(-1);
        QVERIFY(step > 0);

        // Stepped here: no separating contact before the answer step, one in it.
        const rbw::SceneLoadResult loaded = rbw::loadSceneFile(scene);
        QVERIFY2(loaded.ok(), qPrintable(loaded.errors.join('\n')));
        rbw::World world(*loaded.scene);
        rbw::StepTrace trace;
        std::vector<rbw::BodyState> start;
        for (long k = 0; k <= step; ++k) {
            trace.clear();
            start = world.states();
            QVERIFY(world.step(&trace).ok);
            bool separating = false;
            for (const rbw::ContactHeader& c : trace.contacts) separating = separating || c.separating;
            QCOMPARE(separating, k == step);
        }

        // The key: J = 0 for each separating contact (after its v_rel.n > 0), J < 0 never.
        int zeros = 0;
        double lastNormalVelocity = 0.0;
        int lastContact = -1;
        for (const QJsonValue& v : keyDoc.value("answers").toArray()) {
            const QJsonObject a = v.toObject();
            const int contact = a.value("contact").toInt(-1);
            QVERIFY(contact >= 0 && contact < int(trace.contacts.size()));
            if (a.value("quantity") == QLatin1String("normal_velocity")) {
                lastNormalVelocity = a.value("value").toDouble();
                lastContact = contact;
            }
            if (a.value("quantity") != QLatin1String("impulse")) continue;
            QCOMPARE(contact, lastContact);
            QCOMPARE(trace.contacts[contact].separating, lastNormalVelocity > 0.0);
            if (trace.contacts[contact].separating) {
                QCOMPARE(a.value("value").toDouble(), 0.0);
                ++zeros;
            } else {
                QVERIFY(a.value("value").toDouble() > 0.0);
            }
        }
        int separatingContacts = 0;
        for (const rbw::ContactHeader& c : trace.contacts) separatingContacts += c.separating ? 1 : 0;
        QCOMPARE(zeros, separatingContacts);
        QVERIFY(zeros > 0);

        // rbw check accepts the key: every answer correct, J = 0 included.
        const rbw::test::RbwRun ok = rbw::test::runRbw({"check", scene, key, "--format", "json"});
        QVERIFY2(ok.exitCode == 0, qPrintable(ok.out + ok.err));
        for (const QJsonValue& r : QJsonDocument::fromJson(ok.out).object().value("results").toArray()) {
            QCOMPARE(r.toObject().value("verdict").toString(), QStringLiteral("correct"));
        }

        // The worksheet: the state at the step's start (x of every body, as stepped here)
        // and, for every contact, the two sides it joins; the answer key names the command.
        const QString html = readText(sheet);
        QVERIFY2(html.contains(QStringLiteral("The state at the start of step %1 (").arg(step)), qPrintable(html));
        for (size_t b = 0; b < loaded.scene->bodies.size(); ++b) {
            QVERIFY(html.contains(QStringLiteral("<tr><td>%1</td><td>x = ").arg(QString::fromStdString(loaded.scene->bodies[b].name))));
        }
        for (size_t k = 0; k < trace.contacts.size(); ++k) {
            const rbw::ContactHeader& c = trace.contacts[k];
            const QString joins = QStringLiteral("contact %1 (%2 and ground)").arg(k).arg(QString::fromStdString(loaded.scene->bodies[c.bodyA].name));
            QVERIFY2(html.contains(joins), qPrintable(joins));
        }
        QVERIFY(readText(keyHtml).contains("rbw exercise " + kExercise + " --seed " + tag));
    }

    // Seed 1's edge cube, contact 0: J = -1.288016 without the separation check (the
    // hand derivation is in tst_exercise_mistakes.cpp): wrong, named no-separating-check.
    void forgottenCheckIsNamed()
    {
        const QString scene = path("s1.json"), key = path("k1.json"), wrong = path("w1.json");
        QCOMPARE(rbw::test::runRbw({"exercise", kExercise, "--seed", "1", "--output", scene, "--answers-key", key}).exitCode, 0);
        QJsonObject doc = readJson(key);
        QCOMPARE(doc.value("step").toInteger(), 33);
        QJsonArray answers = doc.value("answers").toArray();
        bool changed = false;
        for (qsizetype i = 0; i < answers.size(); ++i) {
            QJsonObject a = answers[i].toObject();
            if (a.value("quantity") != QLatin1String("impulse") || a.value("contact").toInt() != 0) continue;
            QCOMPARE(a.value("value").toDouble(), 0.0);
            a.insert("value", -1.288016);
            answers[i] = a;
            changed = true;
        }
        QVERIFY(changed);
        doc.insert("answers", answers);
        QFile f(wrong);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QJsonDocument(doc).toJson());
        f.close();
        const rbw::test::RbwRun r = rbw::test::runRbw({"check", scene, wrong, "--format", "json"});
        QCOMPARE(r.exitCode, 1);
        bool named = false;
        for (const QJsonValue& v : QJsonDocument::fromJson(r.out).object().value("results").toArray()) {
            const QJsonObject o = v.toObject();
            if (o.value("quantity") != QLatin1String("impulse")) continue;
            QCOMPARE(o.value("verdict").toString(), QStringLiteral("wrong"));
            named = o.value("mistakes").toArray() == QJsonArray{"no-separating-check"};
        }
        QVERIFY2(named, r.out.constData());
    }

    // An exercise id is a lesson or a folder inside one; nothing that leaves the lessons.
    void idsStayInsideTheLessons_data()
    {
        QTest::addColumn<QString>("id");
        QTest::newRow("up and across") << "06-box-on-plane/../03-two-box-collision";
        QTest::newRow("no such exercise") << "06-box-on-plane/nope";
        QTest::newRow("too deep") << "06-box-on-plane/separating/x";
    }

    void idsStayInsideTheLessons()
    {
        QFETCH(QString, id);
        const rbw::test::RbwRun r = rbw::test::runRbw({"exercise", id, "--seed", "1"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(id + ": LESSON: no lesson folder of that name"), qPrintable(r.err));
        // the message lists the further exercise beside the lessons
        QVERIFY2(r.err.contains("06-box-on-plane, 06-box-on-plane/separating, 07-bounce"), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestExerciseSeparating)
#include "tst_exercise_separating.moc"
