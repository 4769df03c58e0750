// The lesson texts against the app (issue 20, items 2 and 7).
//
// 1. Setup placeholders (app/derivation/lesson_text.h): every lesson text filled from
//    its own scene shows its published numbers unchanged (so every setup number the
//    text writes agrees with the scene file), a scene with other numbers shows its own
//    in bold beside the published ones with a note, and a bad placeholder is an error.
// 2. Worked numbers: each number a lesson text states about a run (an energy at a time,
//    when the boxes fall asleep) agrees with what the app computes for that scene, to
//    the digits the text writes: lesson 4's table, its manifold variant, lesson 11's
//    times (tests/lessons/tst_lesson_texts.cpp checks the other lessons' numbers).
#include "app/core/lesson_catalogue.h"
#include "app/derivation/lesson_text.h"
#include "app/exercise/exercise.h"
#include "tests/app/derivation/derivation_test_support.h"

#include <QFile>
#include <QFileInfo>
#include <QtTest>

#include <cmath>
#include <functional>
#include <map>

using namespace rbw;
using namespace rbw::test;

namespace {

QString readText(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) qFatal("cannot read %s", qPrintable(path));
    return QString::fromUtf8(f.readAll());
}

// A scene run step by step, its diagnostics and sleep state after every step
// (index n: the state at t = n h, after steps 0 … n − 1).
struct Run {
    double h = 0.0;
    std::vector<Diagnostics> after;
    std::vector<bool> allAsleep;
};

const Run& runOf(const QString& file, long steps)
{
    static std::map<QString, Run> runs;
    auto it = runs.find(file);
    if (it != runs.end()) return it->second;
    const SceneLoadResult loaded = loadSceneFile(QStringLiteral(RBW_SOURCE_DIR "/lessons/") + file);
    if (!loaded.ok()) qFatal("%s", qPrintable(loaded.errors.join('\n')));
    World w(*loaded.scene);
    Run r;
    r.h = loaded.scene->dt;
    const int n = static_cast<int>(w.states().size());
    auto record = [&] {
        r.after.push_back(w.diagnostics());
        bool all = true;
        for (int b = 0; b < n; ++b) all = all && w.contactState().sleep.bodyCount() == n && w.contactState().sleep.asleep(b);
        r.allAsleep.push_back(all);
    };
    record();
    for (long k = 0; k < steps; ++k) {
        if (!w.step().ok) qFatal("%s: step %ld failed", qPrintable(file), k);
        record();
    }
    return runs.emplace(file, std::move(r)).first->second;
}

std::size_t indexAt(const Run& r, double t) { return static_cast<std::size_t>(std::llround(t / r.h)); }

// The first time at which every body sleeps; -1 if never.
double firstAllAsleep(const Run& r)
{
    for (std::size_t n = 0; n < r.allAsleep.size(); ++n) {
        if (r.allAsleep[n]) return static_cast<double>(n) * r.h;
    }
    return -1.0;
}

// One number a lesson text states: where (a regular expression whose group 1 is the
// number) and what the app computes for it.
struct Claim {
    QString name;
    QString text;      // under lessons/
    QString pattern;
    std::function<double()> app;
};

std::vector<Claim> claims()
{
    std::vector<Claim> out;
    const QString l4 = QStringLiteral("04-many-boxes/lesson.md");
    for (const int t : {0, 1, 2, 3, 4, 10, 20}) {
        out.push_back({QStringLiteral("lesson 4: E at %1 s").arg(t), l4, QStringLiteral(R"(\n\| %1 \| ([\d.]+) \|)").arg(t), [t] {
                           const Run& r = runOf("04-many-boxes/scene.json", 4000);
                           return r.after[indexAt(r, t)].total;
                       }});
        out.push_back({QStringLiteral("lesson 4: kinetic at %1 s").arg(t), l4,
                       QStringLiteral(R"(\n\| %1 \| [\d.]+ \| ([\d.]+) \|)").arg(t), [t] {
                           const Run& r = runOf("04-many-boxes/scene.json", 4000);
                           return r.after[indexAt(r, t)].kinetic;
                       }});
    }
    out.push_back({"lesson 4: Euler's gain in the first step", l4, R"(the total grows by ([\d.]+) J per step)", [] {
                       const Run& r = runOf("04-many-boxes/scene.json", 4000);
                       return r.after[1].total - r.after[0].total;
                   }});
    const QString m = QStringLiteral("04-many-boxes/manifold.md");
    for (const double t : {0.6, 1.5, 3.0}) {
        out.push_back({QStringLiteral("manifold variant: kinetic at %1 s").arg(t), m,
                       QStringLiteral(R"(\n\| %1 \| [^|]+ \| ([\d.]+))").arg(t), [t] {
                           const Run& r = runOf("04-many-boxes/manifold.json", 4000);
                           return r.after[indexAt(r, t)].kinetic;
                       }});
    }
    out.push_back({"manifold variant: all six asleep", m, R"(\n\| ([\d.]+) \| [\d.]+ \| 0 \(all six asleep)", [] {
                       return firstAllAsleep(runOf("04-many-boxes/manifold.json", 4000));
                   }});
    out.push_back({"manifold variant: course kinetic when all sleep", m, R"(\n\| [\d.]+ \| ([\d.]+) \| 0 \(all six asleep)", [] {
                       const Run& course = runOf("04-many-boxes/scene.json", 4000);
                       return course.after[indexAt(course, firstAllAsleep(runOf("04-many-boxes/manifold.json", 4000)))].kinetic;
                   }});
    out.push_back({"lesson 11: lesson 4's manifold boxes asleep", "11-resting-contact/lesson.md",
                   R"(six boxes are all asleep after ([\d.]+) s)",
                   [] { return firstAllAsleep(runOf("04-many-boxes/manifold.json", 4000)); }});
    out.push_back({"lesson 11: asleep since (time)", "11-resting-contact/lesson.md", R"(all 5 boxes asleep since step \d+ \(([\d.]+) s\))",
                   [] { return firstAllAsleep(runOf("11-resting-contact/scene.json", 600)); }});
    out.push_back({"lesson 11: course kinetic at 10 s", "11-resting-contact/lesson.md", R"(\| 10 s \| KE = ([\d.]+) J)", [] {
                       const Run& r = runOf("11-resting-contact/course.json", 600);
                       return r.after[indexAt(r, 10.0)].kinetic;
                   }});
    out.push_back({"lesson 11 course: kinetic at 1 s", "11-resting-contact/course.md", R"(\| 1 s \| KE = ([\d.]+) J)", [] {
                       const Run& r = runOf("11-resting-contact/course.json", 600);
                       return r.after[indexAt(r, 1.0)].kinetic;
                   }});
    return out;
}

} // namespace

class TestLessonText : public QObject {
    Q_OBJECT
private slots:
    void everyTextAgreesWithItsScene_data();
    void everyTextAgreesWithItsScene();
    void newNumbersAreShownAndMarked_data();
    void newNumbersAreShownAndMarked();
    void changedSetupIsBoldBesidePublished();
    void unpublishedSceneIsMarkedWithoutChanges();
    void badPlaceholders_data();
    void badPlaceholders();
    void textNumbersAgreeWithTheApp_data();
    void textNumbersAgreeWithTheApp();
};

void TestLessonText::everyTextAgreesWithItsScene_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("scene");
    int rows = 0;
    for (const Lesson& l : lessonCatalogue(QStringLiteral(RBW_SOURCE_DIR "/lessons"))) {
        if (!QFileInfo::exists(l.textPath)) continue;
        QTest::addRow("%s", qPrintable(l.id)) << l.textPath << l.scenePath;
        ++rows;
    }
    QVERIFY(rows >= 11);
}

void TestLessonText::everyTextAgreesWithItsScene()
{
    QFETCH(QString, text);
    QFETCH(QString, scene);
    const SceneLoadResult loaded = loadSceneFile(scene);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errors.join('\n')));
    const FilledLessonText filled = fillLessonText(readText(text), *loaded.scene);
    QVERIFY2(filled.errors.isEmpty(), qPrintable(filled.errors.join('\n')));
    // Each published setup number is the scene file's, to the digits the text writes.
    QVERIFY2(filled.changed.isEmpty(), qPrintable(filled.changed.join('\n')));
    QVERIFY(!filled.ownNumbers);
    QVERIFY(!filled.markdown.contains(QLatin1String("{{")));
    QVERIFY(!filled.markdown.contains(QLatin1String("published")));
}

// Every lesson with New numbers writes its setup with placeholders: for any seed, the
// text shows the new scene's numbers (at least one differs) and the note.
void TestLessonText::newNumbersAreShownAndMarked_data()
{
    QTest::addColumn<QString>("lesson");
    QTest::addColumn<quint64>("seed");
    for (const char* lesson : {"01-one-step", "03-two-box-collision", "06-box-on-plane", "07-bounce", "08-conventions"}) {
        for (const quint64 seed : {1ULL, 42ULL, 7777ULL}) QTest::addRow("%s seed %llu", lesson, seed) << QString(lesson) << seed;
    }
}

void TestLessonText::newNumbersAreShownAndMarked()
{
    QFETCH(QString, lesson);
    QFETCH(quint64, seed);
    const ExerciseLoadResult spec = loadExercise(lessonDir(lesson));
    QVERIFY2(spec.ok(), qPrintable(spec.errors.join('\n')));
    const GeneratedExercise generated = generateExercise(*spec.spec, seed);
    QVERIFY2(generated.ok(), qPrintable(generated.errors.join('\n')));
    const QString raw = readText(lessonDir(lesson) + QStringLiteral("/lesson.md"));
    const FilledLessonText filled = fillLessonText(raw, *generated.scene, false);
    QVERIFY2(filled.errors.isEmpty(), qPrintable(filled.errors.join('\n')));
    QVERIFY(filled.placeholders >= 3);
    QVERIFY2(!filled.changed.isEmpty(), "no setup number of the text follows the new numbers");
    QVERIFY(filled.ownNumbers);
    QVERIFY(filled.markdown.contains(QLatin1String("for the published numbers")));
    QVERIFY(!filled.markdown.contains(QLatin1String("{{")));
}

// Lesson 1 with M = 4.5, f = (−2, 1, 0.5), h = 2 (the issue's example): the new numbers
// in bold beside the published ones, h unchanged as written.
void TestLessonText::changedSetupIsBoldBesidePublished()
{
    SceneDef scene = lessonScene(QStringLiteral("01-one-step"));
    scene.bodies[0].mass = 4.5;
    scene.forces[0].f_W = Vec3(-2.0, 1.0, 0.5);
    const FilledLessonText filled = fillLessonText(readText(lessonDir(QStringLiteral("01-one-step")) + "/lesson.md"), scene);
    QVERIFY2(filled.errors.isEmpty(), qPrintable(filled.errors.join('\n')));
    QVERIFY(filled.ownNumbers);
    QCOMPARE(filled.changed.size(), 2);
    QVERIFY2(filled.markdown.contains(QString::fromUtf8("mass M = **4.5** (published: 2)")), qPrintable(filled.markdown));
    QVERIFY(filled.markdown.contains(QString::fromUtf8("f = **(−2, 1, 0.5)** (published: (1, 1, 0))")));
    QVERIFY(filled.markdown.contains(QString::fromUtf8("h = 2 |")));
    // The note comes right after the title.
    QVERIFY(filled.markdown.startsWith(QString::fromUtf8("# Lesson 1: one Euler step by hand (Table 2.1)\n\n> **Your numbers.**")));
}

void TestLessonText::unpublishedSceneIsMarkedWithoutChanges()
{
    const SceneDef scene = lessonScene(QStringLiteral("01-one-step"));
    const QString raw = readText(lessonDir(QStringLiteral("01-one-step")) + "/lesson.md");
    const FilledLessonText edited = fillLessonText(raw, scene, false);
    QVERIFY(edited.changed.isEmpty());
    QVERIFY(edited.ownNumbers);
    QVERIFY(edited.markdown.contains(QLatin1String("for the published numbers")));
    // Negative control: the published scene has no note.
    QVERIFY(!fillLessonText(raw, scene, true).markdown.contains(QLatin1String("for the published numbers")));
}

void TestLessonText::badPlaceholders_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("reason");
    QTest::newRow("unknown key") << "{{scene:colour@box = 2}}" << "unknown key 'colour'";
    QTest::newRow("unknown body") << "{{scene:mass@lid = 2}}" << "no body named 'lid'";
    QTest::newRow("no body") << "{{scene:mass = 2}}" << "which body";
    QTest::newRow("no force") << "{{scene:force#3 = (1, 1, 0)}}" << "no force #3";
    QTest::newRow("count") << "{{scene:size@box = (1, 0.6)}}" << "the published value has 2 numbers, the scene's 3";
    QTest::newRow("component of a number") << "{{scene:mass@box.x = 2}}" << ".x needs a vector";
    QTest::newRow("no published value") << "{{scene:mass@box}}" << "not {{scene:KEY";
}

void TestLessonText::badPlaceholders()
{
    QFETCH(QString, text);
    QFETCH(QString, reason);
    const FilledLessonText filled = fillLessonText(QStringLiteral("# T\n\nM = ") + text, lessonScene(QStringLiteral("01-one-step")));
    QCOMPARE(filled.errors.size(), 1);
    QVERIFY2(filled.errors[0].startsWith(QLatin1String("line 3: ")), qPrintable(filled.errors[0]));
    QVERIFY2(filled.errors[0].contains(reason), qPrintable(filled.errors[0]));
}

void TestLessonText::textNumbersAgreeWithTheApp_data()
{
    QTest::addColumn<int>("index");
    const std::vector<Claim> all = claims();
    for (std::size_t i = 0; i < all.size(); ++i) QTest::newRow(qPrintable(all[i].name)) << static_cast<int>(i);
}

// The text's number, with d decimals, is the app's rounded to d decimals.
void TestLessonText::textNumbersAgreeWithTheApp()
{
    QFETCH(int, index);
    const Claim c = claims()[static_cast<std::size_t>(index)];
    const QString text = readText(QStringLiteral(RBW_SOURCE_DIR "/lessons/") + c.text);
    const QRegularExpressionMatch m = QRegularExpression(c.pattern).match(text);
    QVERIFY2(m.hasMatch(), qPrintable(QStringLiteral("%1 no longer says %2").arg(c.text, c.pattern)));
    const QString shown = m.captured(1);
    const int dot = static_cast<int>(shown.indexOf(QLatin1Char('.')));
    const int decimals = dot < 0 ? 0 : static_cast<int>(shown.size()) - dot - 1;
    const double app = c.app();
    QVERIFY(std::isfinite(app));
    QVERIFY2(std::abs(app - shown.toDouble()) <= 0.5 * std::pow(10.0, -decimals) * (1.0 + 1e-9),
             qPrintable(QStringLiteral("%1 says %2, the app computes %3").arg(c.text, shown).arg(app, 0, 'g', 10)));
}

QTEST_MAIN(TestLessonText)
#include "tst_lesson_text.moc"
