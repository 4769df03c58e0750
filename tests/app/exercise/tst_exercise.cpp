// rbw exercise (issue 10, item 6; docs/exercises.md): new numbers for practice.
// Through the real binary: the same seed gives the same bytes, different seeds different
// numbers; every scene of seeds 1..20 of each lesson loads, runs (rbw run exit 0), has
// its varied values on the exercise's grid inside its ranges, and keeps the lesson's
// point (each "require" contact happens, with the stated number of points), checked
// here by stepping the scene independently of the generator; the answers key passes
// rbw check (exit 0) and, negative control, one changed number fails it (exit 1); bad
// inputs exit 2 with the file, the JSON path and the reason.
#include "tests/test_support.h"

#include "app/exercise/exercise.h"
#include "app/output/value_format.h"
#include "physics/engine/integrator_registry.h"
#include "physics/engine/world.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <limits>
#include <random>

namespace {

const QStringList kLessons{"01-one-step", "03-two-box-collision", "06-box-on-plane", "07-bounce", "08-conventions"};

QJsonObject readJson(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QJsonDocument::fromJson(f.readAll()).object();
}

// The value at a scene path such as "bodies[0].orientation.degrees".
QJsonValue valueAt(QJsonValue v, const QString& path)
{
    static const QRegularExpression part(QStringLiteral(R"(([A-Za-z_]+)((?:\[\d+\])*))"));
    for (const QString& p : path.split('.')) {
        const QRegularExpressionMatch m = part.match(p);
        v = v.toObject().value(m.captured(1));
        const QStringList indices = m.captured(2).split(QRegularExpression(QStringLiteral(R"([\[\]])")), Qt::SkipEmptyParts);
        for (const QString& i : indices) v = v.toArray().at(i.toInt());
    }
    return v;
}

} // namespace

class TestExercise : public QObject {
    Q_OBJECT

    QTemporaryDir dir_;

    QString path(const QString& name) const { return dir_.filePath(name); }

    // A lesson folder of our own: lesson 1's or 3's scene and the given exercise.json.
    QString customLesson(const QString& name, const QString& sceneLesson, const QByteArray& exercise)
    {
        QDir(dir_.path()).mkpath(name);
        const QString folder = dir_.filePath(name);
        QFile::remove(folder + "/scene.json");
        QFile::copy(QStringLiteral(RBW_SOURCE_DIR "/lessons/") + sceneLesson + "/scene.json", folder + "/scene.json");
        QFile f(folder + "/exercise.json");
        if (!f.open(QIODevice::WriteOnly)) qFatal("cannot write %s", qPrintable(f.fileName()));
        f.write(exercise);
        return folder;
    }

private slots:
    void initTestCase() { QVERIFY(dir_.isValid()); }

    // The mapping from the engine's integers: the C++ standard fixes mt19937_64's
    // outputs (default seed 5489: the first is 14514284786278117030) and uniformIndex is
    // rejection sampling written here, so the numbers are the same everywhere.
    // 2^64 mod 10 = 6, so any first output >= 6 is kept and gives x0 % 10 = 0.
    void uniformIndexIsPortable()
    {
        std::mt19937_64 engine;   // seed 5489
        QCOMPARE(rbw::uniformIndex(engine, 9), std::uint64_t{0});
        std::mt19937_64 again;
        QCOMPARE(again(), std::uint64_t{14514284786278117030ULL});
        // n = 0: only 0; and every draw stays in [0, n]
        std::mt19937_64 e(42);
        for (int i = 0; i < 1000; ++i) QCOMPARE(rbw::uniformIndex(e, 0), std::uint64_t{0});
        for (int i = 0; i < 1000; ++i) QVERIFY(rbw::uniformIndex(e, 8) <= 8);
    }

    // The grid's decimals, from the step: a whole number of units of 10^-d for the
    // smallest d <= 6, and at least one unit (issue 22: 5e-324 is 0 units at every d,
    // not a step of 0 decimals; 1e-7 is 0.1 units at d = 6).
    void decimalsOfSteps_data()
    {
        QTest::addColumn<double>("step");
        QTest::addColumn<int>("decimals");
        QTest::newRow("2") << 2.0 << 0;
        QTest::newRow("0.5") << 0.5 << 1;
        QTest::newRow("0.25") << 0.25 << 2;
        QTest::newRow("0.000001") << 0.000001 << 6;
        QTest::newRow("0.0000001") << 0.0000001 << -1;
        QTest::newRow("1e-10") << 1e-10 << -1;
        QTest::newRow("5e-324") << 5e-324 << -1;
        QTest::newRow("1/3") << 1.0 / 3.0 << -1;
    }
    void decimalsOfSteps()
    {
        QFETCH(double, step);
        QFETCH(int, decimals);
        QCOMPARE(rbw::decimalsOf(step), decimals);
    }

    // Values on the grid: lo + k step, and k's count saturates instead of overflowing.
    void gridCounts()
    {
        QCOMPARE(rbw::gridCount(1, 5, 0.5), std::uint64_t{8});   // 1, 1.5, ..., 5: 9 values
        QCOMPARE(rbw::gridValue(1, 8, 0.5, 1), 5.0);
        QCOMPARE(rbw::gridValue(0.1, 2, 0.1, 1), 0.3);           // 3/10, not 0.30000000000000004
        QCOMPARE(rbw::gridCount(0, 1e300, 1), std::numeric_limits<std::uint64_t>::max());
    }

    void sameSeedSameBytes_data()
    {
        QTest::addColumn<QString>("lesson");
        for (const QString& l : kLessons) QTest::newRow(qPrintable(l)) << l;
    }
    void sameSeedSameBytes()
    {
        QFETCH(QString, lesson);
        const rbw::test::RbwRun a = rbw::test::runRbw({"exercise", lesson, "--seed", "42"});
        const rbw::test::RbwRun b = rbw::test::runRbw({"exercise", lesson, "--seed", "42"});
        QCOMPARE(a.exitCode, 0);
        QCOMPARE(b.exitCode, 0);
        QVERIFY(!a.out.isEmpty());
        QCOMPARE(a.out, b.out);
        // --output writes the same bytes (through QSaveFile)
        const QString file = path(lesson + "-42.json");
        QCOMPARE(rbw::test::runRbw({"exercise", lesson, "--seed", "42", "--output", file}).exitCode, 0);
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), a.out);
        // the name says the seed
        const QString name = QJsonDocument::fromJson(a.out).object().value("name").toString();
        QVERIFY2(name.endsWith(", seed 42"), qPrintable(name));
    }

    // Different seeds: different numbers (the scenes without their names differ pairwise).
    void differentSeedsDifferentNumbers_data() { sameSeedSameBytes_data(); }
    void differentSeedsDifferentNumbers()
    {
        QFETCH(QString, lesson);
        QList<QJsonObject> scenes;
        for (int seed = 1; seed <= 5; ++seed) {
            const rbw::test::RbwRun r = rbw::test::runRbw({"exercise", lesson, "--seed", QString::number(seed)});
            QCOMPARE(r.exitCode, 0);
            QJsonObject o = QJsonDocument::fromJson(r.out).object();
            o.remove("name");
            for (const QJsonObject& earlier : scenes) QVERIFY2(o != earlier, qPrintable(lesson + " seed " + QString::number(seed)));
            scenes << o;
        }
        // and none of them is the lesson's own scene (negative control of the comparison)
        QJsonObject original = readJson(QStringLiteral(RBW_SOURCE_DIR "/lessons/") + lesson + "/scene.json");
        original.remove("name");
        original.remove("description");
        for (QJsonObject s : scenes) {
            s.remove("description");
            QVERIFY(s != original);
        }
    }

    // Seeds 1..20 of every lesson: loads, runs, values on the grid, the lesson's point kept.
    void seedsLoadRunAndKeepThePoint_data()
    {
        QTest::addColumn<QString>("lesson");
        QTest::addColumn<int>("seed");
        for (const QString& l : kLessons) {
            for (int seed = 1; seed <= 20; ++seed) QTest::newRow(qPrintable(l + " seed " + QString::number(seed))) << l << seed;
        }
    }
    void seedsLoadRunAndKeepThePoint()
    {
        QFETCH(QString, lesson);
        QFETCH(int, seed);
        const QString file = path(QStringLiteral("%1-%2.json").arg(lesson).arg(seed));
        QCOMPARE(rbw::test::runRbw({"exercise", lesson, "--seed", QString::number(seed), "--output", file}).exitCode, 0);
        const rbw::test::RbwRun run = rbw::test::runRbw({"run", file, "--trace", "none"});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));

        // Every varied value lies in its range, on the grid lo + k step.
        const QJsonObject exercise = readJson(QStringLiteral(RBW_SOURCE_DIR "/lessons/") + lesson + "/exercise.json");
        const QJsonObject scene = readJson(file);
        for (const QJsonValue& ruleValue : exercise.value("vary").toArray()) {
            const QJsonObject rule = ruleValue.toObject();
            QStringList paths;
            if (rule.contains("path")) paths << rule.value("path").toString();
            for (const QJsonValue& p : rule.value("paths").toArray()) paths << p.toString();
            const double step = rule.value("step").toDouble();
            const QJsonArray range = rule.value("range").toArray();
            for (const QString& p : paths) {
                const QJsonValue v = valueAt(scene, p);
                QList<double> values;
                QList<QJsonArray> ranges;
                if (range[0].isArray()) {
                    for (int c = 0; c < range.size(); ++c) {
                        values << v.toArray().at(c).toDouble();
                        ranges << range[c].toArray();
                    }
                } else {
                    values << v.toDouble();
                    ranges << range;
                }
                for (int c = 0; c < values.size(); ++c) {
                    const double lo = ranges[c][0].toDouble(), hi = ranges[c][1].toDouble();
                    QVERIFY2(values[c] >= lo && values[c] <= hi, qPrintable(p + " out of range"));
                    const double k = (values[c] - lo) / step;
                    RBW_COMPARE_NEAR_STRICT(k, std::round(k), 1e-9, p + " not on the grid");
                    // at most 2 decimals in the file's text: x * 100 is whole
                    RBW_COMPARE_NEAR_STRICT(values[c] * 100, std::round(values[c] * 100), 1e-9);
                }
            }
            // "paths": one value for all of them
            for (const QString& p : paths) QCOMPARE(valueAt(scene, p), valueAt(scene, paths.first()));
        }

        // The lesson's point: each required pair touches within the scene's steps, at the
        // stated number of points in its first contact step. Stepped here, not by the
        // generator: the scene file as rbw run reads it.
        const rbw::SceneLoadResult loaded = rbw::loadSceneFile(file);
        QVERIFY2(loaded.ok(), qPrintable(loaded.errors.join('\n')));
        const rbw::SceneDef def = *loaded.scene;
        rbw::World world(def);
        const QJsonArray requires_ = exercise.value("require").toArray();
        QList<int> firstPoints(requires_.size(), 0);
        rbw::StepTrace trace;
        auto name = [&](int body, int plane) {
            return body >= 0 ? QString::fromStdString(def.bodies[body].name)
                             : plane >= 0 ? QString::fromStdString(def.planes[plane].name) : QString();
        };
        for (long k = 0; k < def.steps; ++k) {
            trace.clear();
            QVERIFY(world.step(&trace).ok);
            for (int r = 0; r < requires_.size(); ++r) {
                if (firstPoints[r] > 0) continue;
                const QJsonArray pair = requires_[r].toObject().value("contact").toArray();
                int points = 0;
                for (const rbw::ContactHeader& c : trace.contacts) {
                    const QStringList names{name(c.bodyA, -1), name(c.bodyB, c.plane)};
                    if (names.contains(pair[0].toString()) && names.contains(pair[1].toString())) points += c.pointCount;
                }
                firstPoints[r] = points;
            }
        }
        for (int r = 0; r < requires_.size(); ++r) {
            const QJsonObject req = requires_[r].toObject();
            QVERIFY2(firstPoints[r] > 0, qPrintable("no contact for require[" + QString::number(r) + "]"));
            if (req.contains("points")) QCOMPARE(firstPoints[r], req.value("points").toInt());
        }
        if (lesson == "03-two-box-collision") QCOMPARE(requires_.size(), 1);   // the A-B contact is required
    }

    // The key as an answers file passes rbw check; one changed number does not.
    void answersKeyPassesCheck_data()
    {
        QTest::addColumn<QString>("lesson");
        QTest::addColumn<int>("seed");
        QTest::addColumn<QString>("changed");   // the quantity whose number the negative control changes
        QTest::newRow("lesson 1, seed 7") << "01-one-step" << 7 << "angular_velocity";
        QTest::newRow("lesson 1, seed 8") << "01-one-step" << 8 << "torque";
        QTest::newRow("lesson 3, seed 7") << "03-two-box-collision" << 7 << "impulse";
        QTest::newRow("lesson 3, seed 8") << "03-two-box-collision" << 8 << "relative_velocity";
        QTest::newRow("lesson 6, seed 7") << "06-box-on-plane" << 7 << "impulse";
        QTest::newRow("lesson 7, seed 7") << "07-bounce" << 7 << "impulse";
        QTest::newRow("lesson 8, seed 7") << "08-conventions" << 7 << "angular_velocity";
    }
    void answersKeyPassesCheck()
    {
        QFETCH(QString, lesson);
        QFETCH(int, seed);
        QFETCH(QString, changed);
        const QString tag = QStringLiteral("%1-%2").arg(lesson).arg(seed);
        const QString scene = path(tag + "-scene.json"), key = path(tag + "-key.json");
        QCOMPARE(rbw::test::runRbw({"exercise", lesson, "--seed", QString::number(seed), "--output", scene,
                                    "--answers-key", key}).exitCode,
                 0);
        const rbw::test::RbwRun ok = rbw::test::runRbw({"check", scene, key, "--format", "json"});
        QVERIFY2(ok.exitCode == 0, qPrintable(ok.out + ok.err));
        const QJsonArray results = QJsonDocument::fromJson(ok.out).object().value("results").toArray();
        QVERIFY(results.size() >= 4);
        for (const QJsonValue& r : results) QCOMPARE(r.toObject().value("verdict").toString(), QStringLiteral("correct"));

        // Negative control: add 0.5 to the first component of one number: exit 1.
        QJsonObject doc = readJson(key);
        QJsonArray answers = doc.value("answers").toArray();
        bool done = false;
        for (qsizetype i = 0; i < answers.size() && !done; ++i) {
            QJsonObject a = answers[i].toObject();
            if (a.value("quantity").toString() != changed) continue;
            QJsonValue v = a.value("value");
            if (v.isDouble()) {
                v = v.toDouble() + 0.5;
            } else {
                QJsonArray arr = v.toArray();
                arr[0] = arr[0].toDouble() + 0.5;
                v = arr;
            }
            a.insert("value", v);
            answers[i] = a;
            done = true;
        }
        QVERIFY(done);
        doc.insert("answers", answers);
        const QString wrong = path(tag + "-wrong.json");
        QFile f(wrong);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QJsonDocument(doc).toJson());
        f.close();
        QCOMPARE(rbw::test::runRbw({"check", scene, wrong}).exitCode, 1);
    }

    // The worksheet has an empty answer cell per answer of the key; the answer key fills
    // every one, with the key's numbers.
    void worksheetAndAnswerKey()
    {
        const QString sheet = path("sheet.html"), keyHtml = path("key.html"), key = path("sheet-key.json");
        QCOMPARE(rbw::test::runRbw({"exercise", "01-one-step", "--seed", "3", "--worksheet", sheet, "--answer-key",
                                    keyHtml, "--answers-key", key}).exitCode,
                 0);
        QFile s(sheet), k(keyHtml);
        QVERIFY(s.open(QIODevice::ReadOnly));
        QVERIFY(k.open(QIODevice::ReadOnly));
        const QString sheetText = QString::fromUtf8(s.readAll()), keyText = QString::fromUtf8(k.readAll());
        const qsizetype answers = readJson(key).value("answers").toArray().size();
        // lesson 1: F, q, x, v, r, L, I^-1, omega and two probes' v_p
        QCOMPARE(answers, qsizetype(10));
        QCOMPARE(sheetText.count(QStringLiteral("<td class=\"answer\"></td>")), answers);
        // The key's numbers in their own column, not under "your answer" (issue 20).
        QCOMPARE(keyText.count(QStringLiteral("<td class=\"answer\">")), qsizetype(0));
        QCOMPARE(keyText.count(QStringLiteral("<td class=\"key\">")), answers);
        QVERIFY(sheetText.contains(">your answer</th>"));
        QVERIFY(!keyText.contains("your answer"));
        QVERIFY(keyText.contains(">answer</th>"));
        // Made for students: no pointer to the developers' docs, and no header a narrow
        // PDF column could break mid-word at an underscore ("angula r_velo city").
        static const QRegularExpression header(QStringLiteral("<th[^>]*>([^<]*)</th>"));
        for (const QString& text : {sheetText, keyText}) {
            QVERIFY(!text.contains("docs/"));
            QVERIFY(!text.contains(".md"));
            int headers = 0;
            for (const QRegularExpressionMatch& m : header.globalMatch(text)) {
                ++headers;
                QVERIFY2(!m.captured(1).contains('_'), qPrintable(m.captured(1)));
            }
            QVERIFY(headers > 10);   // not vacuous: the setup and the bodies' keys are headers
        }
        QVERIFY(sheetText.contains("<th>angular velocity</th>"));
        QVERIFY(sheetText.startsWith("<!DOCTYPE html>"));
        QVERIFY(sheetText.contains("seed 3"));
        for (const char* id : {"force", "torque", "angular_velocity", "point_velocity", "inverse_inertia_world"}) {
            QVERIFY2(sheetText.contains(QStringLiteral("<code>%1</code>").arg(id)), id);
        }
        // x after the step is where the box started (lesson 1's exercise box starts at rest at
        // x = (1.5, -1, 0.25), off the origin that hides the lever-arm mistakes: x' = x + h v = x)
        QVERIFY(keyText.contains(QStringLiteral("<code>position</code></td><td>box</td><td class=\"key\">(1.5, -1, 0.25)</td>")));
        // step 0: the setup is the state at its start; no second table
        QVERIFY(!sheetText.contains("The state at the start of step"));
    }

    // A worksheet for a later step (lessons 6 and 7 ask for the first contact, step 26 to
    // 153) prints every body's state at the start of that step and says which bodies each
    // contact joins (issue 21 item 9). The state is checked against the scene stepped
    // here, independently of the generator: x and v of each body after k steps.
    void laterStepWorksheet_data()
    {
        QTest::addColumn<QString>("lesson");
        QTest::newRow("06") << "06-box-on-plane";
        QTest::newRow("07") << "07-bounce";
    }

    void laterStepWorksheet()
    {
        QFETCH(QString, lesson);
        const rbw::ExerciseLoadResult spec = rbw::loadExercise(lesson);
        QVERIFY(spec.ok());
        const rbw::GeneratedExercise g = rbw::generateExercise(*spec.spec, 5);
        QVERIFY(g.ok());
        QVERIFY(g.answerStep > 0);
        const QString sheet = rbw::exerciseWorksheetHtml(*spec.spec, g, false);
        QVERIFY2(sheet.contains(QStringLiteral("The state at the start of step %1 (").arg(g.answerStep)), qPrintable(sheet));
        rbw::World world(*g.scene);
        for (long k = 0; k < g.answerStep; ++k) QVERIFY(world.step().ok);
        for (size_t b = 0; b < g.scene->bodies.size(); ++b) {
            const rbw::BodyState& s = world.states()[b];
            const QString row = QStringLiteral("<tr><td>%1</td><td>x = %2<br>")
                                    .arg(QString::fromStdString(g.scene->bodies[b].name), rbw::formatValue(rbw::TraceValue(s.x_W)));
            QVERIFY2(sheet.contains(row), qPrintable(row));
            QVERIFY(sheet.contains("v = " + rbw::formatValue(rbw::TraceValue(s.v_W))));
        }
        // each contact of the step by its two sides
        QVERIFY(!g.answerTrace.contacts.empty());
        for (size_t k = 0; k < g.answerTrace.contacts.size(); ++k) {
            const rbw::ContactHeader& c = g.answerTrace.contacts[k];
            const QString joins = QStringLiteral("contact %1 (%2 and %3)")
                                      .arg(k)
                                      .arg(QString::fromStdString(g.scene->bodies[c.bodyA].name),
                                           c.bodyB >= 0 ? QString::fromStdString(g.scene->bodies[c.bodyB].name)
                                                        : QString::fromStdString(g.scene->planes[c.plane].name));
            QVERIFY2(sheet.contains(joins), qPrintable(joins));
        }
    }

    // The worksheet's setup names the integrator as the app's integrator box does, by
    // the catalogue's title, never by the scene file's id (issue 20: "integrator ids
    // instead of names").
    void worksheetNamesTheIntegrator()
    {
        const rbw::ExerciseLoadResult spec = rbw::loadExercise(QStringLiteral("01-one-step"));
        QVERIFY(spec.ok());
        const rbw::GeneratedExercise g = rbw::generateExercise(*spec.spec, 7);
        QVERIFY(g.ok());
        const rbw::IntegratorInfo* info = rbw::findIntegrator(g.scene->integrator);
        QVERIFY(info != nullptr);
        QVERIFY(*info->title != '\0');
        const QString sheet = rbw::exerciseWorksheetHtml(*spec.spec, g, false);
        const QString row = QStringLiteral("</th><td>%1</td></tr>").arg(QString::fromUtf8(info->title).toHtmlEscaped());
        QVERIFY2(sheet.contains(row), qPrintable(row));
        // control: the id itself appears nowhere in a setup cell
        const QString idCell = QStringLiteral("<td>%1</td>").arg(QString::fromStdString(g.scene->integrator));
        QVERIFY2(!sheet.contains(idCell), qPrintable(idCell));
    }

    void badInputs_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        QTest::newRow("unknown lesson") << QStringList{"exercise", "99-nope", "--seed", "1"}
                                        << "99-nope: LESSON: no lesson folder of that name";
        QTest::newRow("no seed") << QStringList{"exercise", "01-one-step"} << "--seed N is required";
        QTest::newRow("seed not a number") << QStringList{"exercise", "01-one-step", "--seed", "abc"}
                                           << "--seed: must be a whole number";
        QTest::newRow("negative seed") << QStringList{"exercise", "01-one-step", "--seed", "-1"}
                                       << "--seed: must be a whole number";
        QTest::newRow("seed too large") << QStringList{"exercise", "01-one-step", "--seed", "18446744073709551616"}
                                        << "--seed: must be a whole number";
        QTest::newRow("lesson without exercise") << QStringList{"exercise", "02-single-body", "--seed", "1"}
                                                 << "02-single-body/exercise.json: (file): cannot open";
        QTest::newRow("two lessons") << QStringList{"exercise", "01-one-step", "03-two-box-collision", "--seed", "1"}
                                     << "exercise takes exactly one lesson";
    }
    void badInputs()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const rbw::test::RbwRun r = rbw::test::runRbw(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
    }

    // Broken exercise files: the file, the JSON path and the reason.
    void badExerciseFiles_data()
    {
        QTest::addColumn<QString>("sceneLesson");
        QTest::addColumn<QByteArray>("exercise");
        QTest::addColumn<QString>("message");
        const QByteArray q = R"("quantities": ["force"])";
        QTest::newRow("not JSON") << "01-one-step" << QByteArray("{ \"vary\": [") << "exercise.json: (file): not valid JSON";
        QTest::newRow("path not in scene")
            << "01-one-step" << QByteArray(R"({ "vary": [ { "path": "bodies[3].mass", "range": [1, 2], "step": 0.5 } ], )" + q + "}")
            << "exercise.json: vary[0].path: \"bodies[3].mass\" is not in scene.json";
        QTest::newRow("range reversed")
            << "01-one-step" << QByteArray(R"({ "vary": [ { "path": "bodies[0].mass", "range": [2, 1], "step": 0.5 } ], )" + q + "}")
            << "exercise.json: vary[0].range: must be [lo, hi]";
        QTest::newRow("vector needs ranges")
            << "01-one-step" << QByteArray(R"({ "vary": [ { "path": "forces[0].force", "range": [1, 2], "step": 0.5 } ], )" + q + "}")
            << "exercise.json: vary[0].path: \"forces[0].force\" is not a number";
        // issue 22: toInt() wrapped 4294967296 to 0, so body 0's mass varied
        QTest::newRow("index beyond int")
            << "01-one-step" << QByteArray(R"({ "vary": [ { "path": "bodies[4294967296].mass", "range": [1, 2], "step": 0.5 } ], )" + q + "}")
            << "exercise.json: vary[0].path: \"bodies[4294967296].mass\" is not in scene.json";
        QTest::newRow("index beyond int64")
            << "01-one-step" << QByteArray(R"({ "vary": [ { "path": "bodies[99999999999999999999].mass", "range": [1, 2], "step": 0.5 } ], )" + q + "}")
            << "exercise.json: vary[0].path: \"bodies[99999999999999999999].mass\" is not in scene.json";
        // issue 22: 5e-324 passed as a step of 0 decimals (0 units: every value lo)
        QTest::newRow("step 5e-324")
            << "01-one-step" << QByteArray(R"({ "vary": [ { "path": "bodies[0].mass", "range": [1, 2], "step": 5e-324 } ], )" + q + "}")
            << "exercise.json: vary[0].step: must be a number > 0 with at most 6 decimals";
        QTest::newRow("step 1e-10")
            << "01-one-step" << QByteArray(R"({ "vary": [ { "path": "bodies[0].mass", "range": [1, 1], "step": 1e-10 } ], )" + q + "}")
            << "exercise.json: vary[0].step: must be a number > 0 with at most 6 decimals";
        QTest::newRow("range too wide for the step")
            << "01-one-step" << QByteArray(R"({ "vary": [ { "path": "bodies[0].mass", "range": [1, 1e300], "step": 1 } ], )" + q + "}")
            << "exercise.json: vary[0].step: too small for the range: more than a million values";
        // issue 22: every draw of [0, 0]^3 is zero, which "nonzero" silently let through
        QTest::newRow("nonzero on an all-zero range")
            << "01-one-step" << QByteArray(R"({ "vary": [ { "path": "forces[0].force", "range": [[0, 0], [0, 0], [0, 0]], "step": 0.5, "nonzero": true } ], )" + q + "}")
            << "exercise.json: vary[0].nonzero: is true, but the range holds only 0";
        QTest::newRow("step zero")
            << "01-one-step" << QByteArray(R"({ "vary": [ { "path": "bodies[0].mass", "range": [1, 2], "step": 0 } ], )" + q + "}")
            << "exercise.json: vary[0].step: must be a number > 0";
        QTest::newRow("unknown quantity")
            << "01-one-step" << QByteArray(R"({ "vary": [ { "path": "bodies[0].mass", "range": [1, 2], "step": 0.5 } ], "quantities": ["omega"] })")
            << "exercise.json: quantities[0]: \"omega\" is not a trace id";
        QTest::newRow("unknown key")
            << "01-one-step" << QByteArray(R"({ "vary": [ { "path": "bodies[0].mass", "range": [1, 2], "step": 0.5, "stp": 1 } ], )" + q + "}")
            << "exercise.json: vary[0].stp: unknown key";
        // issue 22: a key given twice was read as its last value; refused through the scene
        // loader's strict scan, with the JSON path. (The same key in two sibling objects,
        // vary[0].path and vary[1].path, is no duplicate: the lessons' own files have it.)
        QTest::newRow("duplicate top-level key")
            << "01-one-step" << QByteArray(R"({ "vary": [ { "path": "bodies[0].mass", "range": [1, 2], "step": 0.5 } ], )" + q + R"(, "quantities": ["torque"] })")
            << "exercise.json: quantities: duplicate key \"quantities\" (first at line 1, column 75, again at line 1, column 100)";
        QTest::newRow("duplicate key in a list")
            << "01-one-step" << QByteArray(R"({ "vary": [ { "path": "bodies[0].mass", "range": [1, 2], "step": 0.5, "step": 1 } ], )" + q + "}")
            << "exercise.json: vary[0].step: duplicate key \"step\"";
        QTest::newRow("duplicate key, escaped")
            << "03-two-box-collision"
            << QByteArray(R"({ "vary": [ { "path": "restitution", "range": [0.5, 1], "step": 0.1 } ],
                             "require": [ { "contact": ["A", "B"], "cont\u0061ct": ["A", "B"] } ], "quantities": ["impulse"] })")
            << "exercise.json: require[0].contact: duplicate key \"contact\"";
        QTest::newRow("NaN")
            << "01-one-step" << QByteArray(R"({ "vary": [ { "path": "bodies[0].mass", "range": [1, 2], "step": NaN } ], )" + q + "}")
            << "exercise.json: vary[0].step: must be a finite number, got NaN";
        // Every value of the range breaks the scene: the loader's reason, after the retries.
        QTest::newRow("scene does not load")
            << "01-one-step" << QByteArray(R"({ "vary": [ { "path": "bodies[0].mass", "range": [-2, -1], "step": 0.5 } ], "attempts": 3, )" + q + "}")
            << "exercise.json: vary: no scene out of 3 sub-seeds of seed 1 kept the lesson's point; the last: the scene does not load";
        // Lesson 3 with B flying away from A: the boxes never collide.
        QTest::newRow("lesson point lost")
            << "03-two-box-collision"
            << QByteArray(R"({ "vary": [ { "path": "bodies[1].linear_velocity", "range": [[1, 2], [0, 0], [0, 0]], "step": 0.5 },
                                         { "path": "bodies[0].linear_velocity", "range": [[-2, -1], [0, 0], [0, 0]], "step": 0.5 } ],
                             "require": [ { "contact": ["A", "B"] } ], "attempts": 5, "quantities": ["impulse"] })")
            << "require[0]: no contact between A and B in the scene's 3 steps";
        // Lesson 6's vertex cube first touches at 1 corner; requiring 2 can never hold.
        QTest::newRow("contact points differ")
            << "06-box-on-plane"
            << QByteArray(R"({ "vary": [ { "path": "restitution", "range": [0.2, 0.8], "step": 0.1 } ],
                             "require": [ { "contact": ["vertex", "ground"], "points": 2 } ], "attempts": 2, "quantities": ["impulse"] })")
            << "require[0]: vertex and ground first touch with 1 contact point, the lesson needs 2";
        QTest::newRow("require unknown body")
            << "03-two-box-collision"
            << QByteArray(R"({ "vary": [ { "path": "restitution", "range": [0.5, 1], "step": 0.1 } ],
                             "require": [ { "contact": ["A", "C"] } ], "quantities": ["impulse"] })")
            << "exercise.json: require[0].contact: no body or plane \"C\" in the scene";
    }
    void badExerciseFiles()
    {
        QFETCH(QString, sceneLesson);
        QFETCH(QByteArray, exercise);
        QFETCH(QString, message);
        const QString folder = customLesson(QStringLiteral("custom-%1").arg(QTest::currentDataTag()).replace(' ', '-'),
                                            sceneLesson, exercise);
        const QString out = path("never-written.json");
        const rbw::test::RbwRun r = rbw::test::runRbw({"exercise", folder, "--seed", "1", "--output", out});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY(!QFile::exists(out));
    }

    // The good negative of badExerciseFiles: the same custom folder mechanism with a
    // valid file works (so the failures above are the files', not the mechanism's).
    void customLessonFolderWorks()
    {
        const QString folder = customLesson("custom-good", "01-one-step",
                                            R"({ "vary": [ { "path": "bodies[0].mass", "range": [1, 2], "step": 0.5 } ], "quantities": ["force"] })");
        const rbw::test::RbwRun r = rbw::test::runRbw({"exercise", folder, "--seed", "1"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const double mass = QJsonDocument::fromJson(r.out).object().value("bodies").toArray()[0].toObject().value("mass").toDouble();
        QVERIFY(mass == 1.0 || mass == 1.5 || mass == 2.0);

        // nonzero where only one component can be other than 0: accepted, and drawn so
        // (the refusal above is about a range holding only 0, not about zeros in it).
        const QString oneAxis = customLesson("custom-one-axis", "01-one-step",
                                             R"({ "vary": [ { "path": "forces[0].force", "range": [[0, 0], [0, 0.5], [0, 0]], "step": 0.5, "nonzero": true } ], "quantities": ["force"] })");
        const rbw::test::RbwRun r2 = rbw::test::runRbw({"exercise", oneAxis, "--seed", "1"});
        QVERIFY2(r2.exitCode == 0, qPrintable(r2.err));
        const QJsonArray force = QJsonDocument::fromJson(r2.out).object().value("forces").toArray()[0].toObject().value("force").toArray();
        QCOMPARE(force.size(), 3);
        QCOMPARE(force[0].toDouble(), 0.0);
        QCOMPARE(force[1].toDouble(), 0.5);
        QCOMPARE(force[2].toDouble(), 0.0);
    }

    void unwritableOutput()
    {
        const rbw::test::RbwRun r =
            rbw::test::runRbw({"exercise", "01-one-step", "--seed", "1", "--worksheet", "/nonexistent-dir/sheet.html"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("/nonexistent-dir/sheet.html: --worksheet: cannot write"), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestExercise)
#include "tst_exercise.moc"
