// Exercises that show mistakes (issue 21 items 9 and 10; app/exercise/exercise_mistakes.h).
// Every mistake model of the checker's catalogue (iterated: a model added there is
// covered here without a change) against every exercise draw of seeds 1..20 of each
// lesson with an exercise: no draw may make a model give the right number in a quantity
// where other draws show it (h = 1 hides missing-time-step: L + q = L + h q), and no draw
// may make two models give the same numbers where other draws tell them apart (c = 0.5:
// -(1 - c) v_rel.n = -c v_rel.n). Negative controls: the same measurement flags exactly
// those two draws when the generator is allowed to make them. And docs/checker.md's
// per-lesson section is the measured table, not a claim, and so is the "shows in" column
// of its table of mistake models.
#include "tests/test_support.h"

#include "app/exercise/exercise.h"
#include "app/exercise/exercise_mistakes.h"
#include "physics/engine/world.h"
#include "physics/workbook/checker/checker.h"
#include "physics/workbook/checker/mistakes.h"

#include <QFile>
#include <QRegularExpression>
#include <QSaveFile>
#include <QSet>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <map>
#include <numeric>

namespace {

// 06-box-on-plane/separating: lesson 6's further exercise, the first step with a separating
// contact (J = 0), where no-separating-check shows.
const QStringList kLessons{"01-one-step",    "03-two-box-collision", "06-box-on-plane", "06-box-on-plane/separating",
                           "07-bounce",      "08-conventions"};

// "06-box-on-plane" -> "06", "06-box-on-plane/separating" -> "06/separating"
QString exerciseName(const QString& lessonId)
{
    const qsizetype slash = lessonId.indexOf('/');
    return lessonId.left(lessonId.indexOf('-')) + (slash < 0 ? QString() : lessonId.mid(slash));
}

std::vector<std::uint64_t> seeds(int n)
{
    std::vector<std::uint64_t> s(n);
    std::iota(s.begin(), s.end(), std::uint64_t{1});
    return s;
}

rbw::ExerciseSpec lessonSpec(const QString& lesson)
{
    const rbw::ExerciseLoadResult r = rbw::loadExercise(lesson);
    if (!r.ok()) qFatal("%s", qPrintable(r.errors.join("; ")));
    return *r.spec;
}

rbw::ExerciseVary& ruleFor(rbw::ExerciseSpec& spec, const QString& path)
{
    for (rbw::ExerciseVary& v : spec.vary) {
        if (v.paths.contains(path)) return v;
    }
    qFatal("no vary rule for %s", qPrintable(path));
    return spec.vary.front();
}

const rbw::ModelVisibility& modelOf(const rbw::ExerciseMistakeReport& r, const QString& name)
{
    for (const rbw::ModelVisibility& m : r.models) {
        if (m.model == name) return m;
    }
    qFatal("no model %s", qPrintable(name));
    return r.models.front();
}

// The per-lesson section of docs/checker.md: from its heading to the end of the file.
const char* kSectionHeading = "## Which mistakes each exercise can show";
// The header of docs/checker.md's table of mistake models; its last column is measured.
const char* kCatalogueHeader = "| id | the wrong equation | example | shows in (exercises, measured) |";

// "inertia-axes-swapped (variant 1)" -> "inertia-axes-swapped"
QString catalogueId(const QString& model)
{
    const qsizetype at = model.indexOf(" (variant ");
    return at < 0 ? model : model.left(at);
}

// Why a one-step model shows in no exercise, each reason checked by a test of this file
// over every draw (named in the text). A model that shows nowhere without a reason here
// fails catalogueTableAgrees: the doc never says "no exercise" without saying why. Empty
// while every one-step model shows in some exercise (impulse-body-inverse-inertia, the last
// one here, shows in exercise 03 since its box B is no cube: bodyInverseInertiaShowsInTwoBoxes).
const std::map<QString, QString> kWhyNoExercise{};

// The measured "shows in" cell of one model: the exercises in which it (any of its
// variants) changes some answer in every draw; a several-step model is named by no
// one-step check (MistakeInfo::oneStep), whatever numbers it gives.
QString showsInCell(const rbw::MistakeInfo& info, const std::vector<rbw::ExerciseMistakeReport>& reports)
{
    if (!info.oneStep) return QStringLiteral("**never in a one-step check** (simulator only)");
    QStringList lessons;
    for (const rbw::ExerciseMistakeReport& r : reports) {
        for (const rbw::ModelVisibility& m : r.models) {
            if (catalogueId(m.model) == QLatin1String(info.id) && !m.shownIn.isEmpty()) {
                lessons << exerciseName(r.lessonId);
                break;
            }
        }
    }
    if (lessons.isEmpty()) {
        const auto why = kWhyNoExercise.find(QLatin1String(info.id));
        return why != kWhyNoExercise.end() ? why->second : QStringLiteral("no exercise");
    }
    return (lessons.size() == 1 ? "exercise " : "exercises ") + lessons.join(", ");
}

} // namespace

class TestExerciseMistakes : public QObject {
    Q_OBJECT

    QString measured_;   // the sections of every lesson, in kLessons' order
    std::vector<rbw::ExerciseMistakeReport> reports_;   // the same measurements

private slots:
    void noDrawHidesAMistake_data()
    {
        QTest::addColumn<QString>("lesson");
        for (const QString& l : kLessons) QTest::newRow(qPrintable(l)) << l;
    }

    void noDrawHidesAMistake()
    {
        QFETCH(QString, lesson);
        const rbw::ExerciseMistakeReport r = rbw::measureExerciseMistakes(lessonSpec(lesson), seeds(20));
        QVERIFY2(r.errors.isEmpty(), qPrintable(r.errors.join("\n")));
        QCOMPARE(r.models.size() >= rbw::mistakeCatalogue().size(), true);   // every model, each variant
        // Not vacuous: each lesson shows some mistakes.
        int showing = 0;
        for (const rbw::ModelVisibility& m : r.models) showing += m.shownIn.isEmpty() ? 0 : 1;
        QVERIFY2(showing > 0, qPrintable(lesson));
        QVERIFY2(r.failures().isEmpty(), qPrintable(r.failures().join("\n")));
        measured_ += '\n' + r.markdown();
        reports_.push_back(r);
    }

    // Negative control: lesson 1 with h drawn from 0.5 .. 2 (its old range, which holds
    // h = 1): the draws with h = 1 hide missing-time-step in L' = L + q = L + h q.
    void hOfOneIsFlagged()
    {
        rbw::ExerciseSpec spec = lessonSpec("01-one-step");
        rbw::ExerciseVary& h = ruleFor(spec, "dt");
        h.lo = {0.5};
        h.hi = {2};
        h.step = 0.5;
        h.decimals = 1;
        h.avoid.clear();
        const rbw::ExerciseMistakeReport r = rbw::measureExerciseMistakes(spec, seeds(20));
        const rbw::ModelVisibility& m = modelOf(r, "missing-time-step");
        QVERIFY2(!m.hiddenAt.isEmpty(), "h = 1 was never drawn or not flagged");
        QVERIFY2(m.hiddenAt.join('\n').contains(QRegularExpression("dt = 1[,)]")), qPrintable(m.hiddenAt.join('\n')));
        QVERIFY(!r.failures().isEmpty());
    }

    // Negative control: lesson 3 with c fixed at 0.5 for half the draws' range (0.5 .. 0.6):
    // restitution-one-minus and impulse-without-one-plus give the same J there.
    void cOfHalfIsFlagged()
    {
        rbw::ExerciseSpec spec = lessonSpec("03-two-box-collision");
        rbw::ExerciseVary& c = ruleFor(spec, "restitution");
        c.lo = {0.5};
        c.hi = {0.6};
        c.step = 0.1;
        c.decimals = 1;
        c.avoid.clear();
        const rbw::ExerciseMistakeReport r = rbw::measureExerciseMistakes(spec, seeds(20));
        const rbw::ModelVisibility& m = modelOf(r, "restitution-one-minus");
        QVERIFY2(m.coincidences.join('\n').contains("impulse-without-one-plus"), qPrintable(r.failures().join('\n')));
        QVERIFY2(m.coincidences.join('\n').contains("restitution = 0.5"), qPrintable(m.coincidences.join('\n')));
    }

    // Negative control: lesson 1's box back at Table 2.1's origin (without the rules that
    // move it, its force point and probes to x = (1.5, -1, 0.25)): q = p x f = (p - x) x f
    // and v + w x p = v + w x (p - x), so neither lever-arm mistake can show; moved, both do.
    void boxAtOriginHidesLeverArm()
    {
        rbw::ExerciseSpec spec = lessonSpec("01-one-step");
        const rbw::ExerciseMistakeReport moved = rbw::measureExerciseMistakes(spec, seeds(20));
        QVERIFY(modelOf(moved, "lever-arm-from-origin").shownIn.contains("torque (box)"));
        QVERIFY(modelOf(moved, "point-velocity-lever-arm-from-origin").shownIn.contains("point_velocity (box #1)"));
        ruleFor(spec, "bodies[0].position");   // the rules exist
        std::erase_if(spec.vary, [](const rbw::ExerciseVary& v) {
            return v.paths.contains("bodies[0].position") || v.paths.contains("forces[0].point") ||
                   v.paths.contains("probes[0].point");
        });
        const rbw::ExerciseMistakeReport origin = rbw::measureExerciseMistakes(spec, seeds(20));
        QVERIFY(origin.errors.isEmpty());
        QVERIFY(modelOf(origin, "lever-arm-from-origin").shownIn.isEmpty());
        QVERIFY(modelOf(origin, "point-velocity-lever-arm-from-origin").shownIn.isEmpty());
        QVERIFY(!modelOf(origin, "torque-reversed").shownIn.isEmpty());   // the measurement still sees the others
    }

    // Negative control: lesson 1's box back at rest (without the rule that draws its
    // starting omega, Table 2.1's omega = 0): r' = r + h/2 (0, omega) r = r, so none of the
    // quaternion mistakes, omega-accumulated (omega' = 0 + I^-1 L') or
    // inertia-from-old-orientation (R' = R) can show; spinning, each does.
    void boxAtRestHidesQuaternionMistakes()
    {
        rbw::ExerciseSpec spec = lessonSpec("01-one-step");
        const QStringList models{"quaternion-missing-half", "quaternion-not-normalised", "quaternion-right-multiplied",
                                 "omega-accumulated", "inertia-from-old-orientation"};
        const rbw::ExerciseMistakeReport spinning = rbw::measureExerciseMistakes(spec, seeds(20));
        for (const QString& m : models) QVERIFY2(!modelOf(spinning, m).shownIn.isEmpty(), qPrintable(m));
        QVERIFY(modelOf(spinning, "quaternion-missing-half").shownIn.contains("orientation (box)"));
        ruleFor(spec, "bodies[0].angular_velocity");   // the rule exists
        std::erase_if(spec.vary, [](const rbw::ExerciseVary& v) { return v.paths.contains("bodies[0].angular_velocity"); });
        const rbw::ExerciseMistakeReport resting = rbw::measureExerciseMistakes(spec, seeds(20));
        QVERIFY(resting.errors.isEmpty());
        for (const QString& m : models) QVERIFY2(modelOf(resting, m).shownIn.isEmpty(), qPrintable(m));
        QVERIFY(!modelOf(resting, "torque-reversed").shownIn.isEmpty());   // the measurement still sees the others
    }

    // "avoid" (docs/exercises.md): a number's values that are redrawn. Lesson 1's h from
    // 0.5 .. 2 avoiding 1: over 40 seeds every other value of the grid is drawn, 1 never.
    void avoidIsNeverDrawn()
    {
        const rbw::ExerciseSpec spec = lessonSpec("01-one-step");
        QSet<double> drawn;
        for (std::uint64_t seed = 1; seed <= 40; ++seed) {
            const rbw::GeneratedExercise g = rbw::generateExercise(spec, seed);
            QVERIFY(g.ok());
            drawn.insert(g.scene->dt);
            QVERIFY(g.scene->bodies[0].mass != 1.0);
        }
        QCOMPARE(drawn, (QSet<double>{0.5, 1.5, 2.0}));
    }

    // A bad "avoid": the file, the JSON path and the reason.
    void badAvoid_data()
    {
        QTest::addColumn<QByteArray>("rule");
        QTest::addColumn<QString>("message");
        QTest::newRow("not on the grid") << QByteArray(R"("path": "dt", "range": [0.5, 2], "step": 0.5, "avoid": [1.2])")
                                         << "vary[0].avoid[0]: must be one of the range's values";
        QTest::newRow("every value") << QByteArray(R"("path": "dt", "range": [0.5, 1], "step": 0.5, "avoid": [0.5, 1])")
                                     << "vary[0].avoid: avoids every value of the range";
        QTest::newRow("a vector") << QByteArray(R"("path": "forces[0].force", "range": [[0, 1], [0, 1], [0, 1]], "step": 1, "avoid": [1])")
                                  << "vary[0].avoid: is for a number";
        QTest::newRow("not a list") << QByteArray(R"("path": "dt", "range": [0.5, 2], "step": 0.5, "avoid": 1)")
                                    << "vary[0].avoid: must be a list of numbers";
    }

    void badAvoid()
    {
        QFETCH(QByteArray, rule);
        QFETCH(QString, message);
        QTemporaryDir dir;
        QVERIFY(QFile::copy(QStringLiteral(RBW_SOURCE_DIR "/lessons/01-one-step/scene.json"), dir.filePath("scene.json")));
        QFile f(dir.filePath("exercise.json"));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("{ \"vary\": [ { " + rule + " } ], \"quantities\": [\"force\"] }");
        f.close();
        const rbw::ExerciseLoadResult r = rbw::loadExercise(dir.path());
        QVERIFY(!r.ok());
        QVERIFY2(r.errors.join('\n').contains("exercise.json: " + message), qPrintable(r.errors.join('\n')));
    }

    // docs/checker.md's last section is the table measured above, word for word.
    void docAgrees()
    {
        if (measured_.isEmpty()) QSKIP("run with noDrawHidesAMistake");
        const QString expected = QString(kSectionHeading) + "\n" + measuredIntro() + measured_;
        QFile f(QStringLiteral(RBW_SOURCE_DIR "/docs/checker.md"));
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QString doc = QString::fromUtf8(f.readAll());
        const qsizetype at = doc.indexOf(kSectionHeading);
        QVERIFY2(at >= 0, "docs/checker.md has no per-lesson section");
        const QString section = doc.mid(at).trimmed();
        if (section != expected.trimmed()) {
            qWarning().noquote() << "docs/checker.md's section should read:\n" << expected;
            // After a change to the catalogue: RBW_UPDATE_CHECKER_DOC=1 writes it (atomically).
            if (qEnvironmentVariableIsSet("RBW_UPDATE_CHECKER_DOC")) {
                QSaveFile out(f.fileName());
                QVERIFY(out.open(QIODevice::WriteOnly));
                out.write((doc.left(at) + expected.trimmed() + '\n').toUtf8());
                QVERIFY(out.commit());
            }
        }
        QCOMPARE(section, expected.trimmed());
    }

    // docs/checker.md's table of mistake models: one row per model of the catalogue, and
    // its last column is the measurement above (showsInCell), not a claim.
    void catalogueTableAgrees()
    {
        if (reports_.size() != std::size_t(kLessons.size())) QSKIP("run with noDrawHidesAMistake");
        QFile f(QStringLiteral(RBW_SOURCE_DIR "/docs/checker.md"));
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QString doc = QString::fromUtf8(f.readAll());
        f.close();
        QStringList lines = doc.split('\n');
        const qsizetype header = lines.indexOf(QString::fromUtf8(kCatalogueHeader));
        QVERIFY2(header >= 0, "docs/checker.md has no table of mistake models with a measured column");
        QStringList differ;
        QSet<QString> rows;
        for (qsizetype i = header + 2; i < lines.size() && lines[i].startsWith("| `"); ++i) {
            QString& row = lines[i];
            const QString id = row.section('`', 1, 1);
            const rbw::MistakeInfo* info = rbw::findMistake(id.toStdString());
            QVERIFY2(info, qPrintable("docs/checker.md: no mistake model " + id));
            QVERIFY2(!rows.contains(id), qPrintable("docs/checker.md: two rows for " + id));
            rows.insert(id);
            QVERIFY2(row.endsWith(" |"), qPrintable(row));
            const QString body = row.left(row.size() - 2);
            const qsizetype last = body.lastIndexOf(" | ");
            const QString cell = showsInCell(*info, reports_);
            if (body.mid(last + 3) != cell) {
                differ << QString("%1: \"%2\" should be \"%3\"").arg(id, body.mid(last + 3), cell);
                row = body.left(last) + " | " + cell + " |";
            }
        }
        // Not vacuous: every model of the catalogue has its row.
        QCOMPARE(rows.size(), qsizetype(rbw::mistakeCatalogue().size()));
        // A one-step model that no exercise shows says why (kWhyNoExercise, each reason a test).
        for (const rbw::MistakeInfo& m : rbw::mistakeCatalogue()) {
            QVERIFY2(showsInCell(m, reports_) != QLatin1String("no exercise"),
                     qPrintable(QString("%1 shows in no exercise: make one show it, or add why to kWhyNoExercise").arg(m.id)));
        }
        if (!differ.isEmpty() && qEnvironmentVariableIsSet("RBW_UPDATE_CHECKER_DOC")) {
            QSaveFile out(f.fileName());
            QVERIFY(out.open(QIODevice::WriteOnly));
            out.write(lines.join('\n').toUtf8());
            QVERIFY(out.commit());
        }
        QVERIFY2(differ.isEmpty(), qPrintable("docs/checker.md's \"shows in\" column:\n" + differ.join('\n')));
    }

    // Negative control: a model's cell names exactly the exercises whose section shows it
    // (lesson 3's impulse-linear-only: exercises 03, 06, 06/separating, 07, measured above), and a
    // several-step model is never placed in an exercise although it changes numbers there
    // (gravity-always-on changes lesson 1's force).
    void showsInCellIsTheMeasurement()
    {
        if (reports_.size() != std::size_t(kLessons.size())) QSKIP("run with noDrawHidesAMistake");
        QCOMPARE(showsInCell(*rbw::findMistake("impulse-linear-only"), reports_), QString("exercises 03, 06, 06/separating, 07"));
        // Only a separating contact shows a forgotten separation check (J = 0 is right there).
        QCOMPARE(showsInCell(*rbw::findMistake("no-separating-check"), reports_), QString("exercise 06/separating"));
        QVERIFY(!modelOf(reports_.front(), "gravity-always-on").shownIn.isEmpty());
        QCOMPARE(showsInCell(*rbw::findMistake("gravity-always-on"), reports_),
                 QString("**never in a one-step check** (simulator only)"));
        QCOMPARE(showsInCell(*rbw::findMistake("omega-accumulated"), reports_), QString("exercise 01"));
        QCOMPARE(showsInCell(*rbw::findMistake("impulse-body-inverse-inertia"), reports_), QString("exercise 03"));
    }

    // impulse-body-inverse-inertia (the impulse's angular terms with I0^-1, not R I0^-1 R^T)
    // shows in exercise 03, whose box B is 1.4 x 1 x 0.6 in every draw (lessons/03-two-box-
    // collision/exercise.json, a range of one value). Hand derivation, seed 1: the draw is
    // M_A = 2, M_B = 0.5, v_A = (1.5, 0, 0), v_B = (-1.5, 0, 0), c = 0.7. B's sides sum to 3,
    // like the lesson's unit cube, so its nearest corner, R (0.7, 0.5, 0.3) from its centre
    // (R: 2.186276 rad about (0, -1, 1), first row -(1, 1, 1)/sqrt 3), is 3/(2 sqrt 3) =
    // 0.866025 behind B's centre, 1.916025 - 0.866025 = 1.05, 0.05 from A's face x = 1;
    // each step closes 0.01 * 3 = 0.03, so step 0 ends 0.02 apart and step 1 (ending 0.01
    // inside) is the first contact. x_b = R (0.7, 0.5, 0.3) = (-sqrt 3/2, (sqrt 3 + 1)/10,
    // (sqrt 3 - 1)/10) = (-0.866025, 0.273205, 0.073205), n = (-1, 0, 0),
    // u = x_b x n = (0, -0.073205, 0.273205). I0_B^-1 = (12/M_B) diag(1/(b^2+c^2),
    // 1/(a^2+c^2), 1/(a^2+b^2)) = 24 diag(1/1.36, 1/2.32, 1/2.96)
    // = diag(17.647059, 10.344828, 8.108108).
    // Right: [(I_B^-1 u) x x_b].n = u.(R I0^-1 R^T u) = u_B.(I0^-1 u_B) with
    // u_B = R^T u = (0.7, 0.5, 0.3) x (R^T n) = (0.7, 0.5, 0.3) x (1, 1, 1)/sqrt 3
    // = (0.2, -0.4, 0.2)/sqrt 3: (0.04 * 17.647059 + 0.16 * 10.344828 + 0.04 * 8.108108)/3
    // = 0.895126. The mistake: u.(I0^-1 u) = 0.073205^2 * 10.344828 + 0.273205^2 * 8.108108
    // = 0.660635. A is a cube (I^-1 = 0.75 E in every frame): its term is the same either
    // way, 0.75 |(0, -0.073205, 0.773205)|^2 = 0.452404. Denominator 1/2 + 1/0.5 + 0.452404
    // + 0.895126 = 3.847530, numerator 1.7 * 3 = 5.1: J = 1.325526; with the mistake
    // 2.5 + 0.452404 + 0.660635 = 3.613039, J = 1.411554.
    void bodyInverseInertiaShowsInTwoBoxes()
    {
        const rbw::ExerciseSpec spec = lessonSpec("03-two-box-collision");
        const rbw::GeneratedExercise g = rbw::generateExercise(spec, 1);
        QVERIFY2(g.ok(), qPrintable(g.errors.join('\n')));
        QCOMPARE(g.answerStep, 1L);
        const rbw::BodyDef& B = g.scene->bodies[1];
        QCOMPARE(B.name, std::string("B"));
        QCOMPARE(B.mass, 0.5);
        QCOMPARE(g.scene->bodies[0].mass, 2.0);
        QCOMPARE(g.scene->restitution, 0.7);
        std::vector<rbw::Answer> answers = rbw::exerciseAnswers(g);
        const auto at = [&answers](const char* quantity) {
            const auto it = std::find_if(answers.begin(), answers.end(),
                                         [quantity](const rbw::Answer& a) { return a.quantity == quantity && a.contact == 0; });
            if (it == answers.end()) qFatal("no %s in the key", quantity);
            return it;
        };
        RBW_COMPARE_NEAR_STRICT(at("rotational_a")->value[0], 0.452404, 1e-6);
        RBW_COMPARE_NEAR_STRICT(at("rotational_b")->value[0], 0.895126, 1e-6);
        RBW_COMPARE_NEAR_STRICT(at("denominator")->value[0], 3.847530, 1e-6);
        RBW_COMPARE_NEAR_STRICT(at("impulse")->value[0], 1.325526, 1e-6);
        rbw::World before(*g.scene);
        while (before.stepIndex() < g.answerStep) QVERIFY(before.step().ok);
        // the student who uses I0_B^-1: B's term, the denominator and J as derived above
        at("rotational_b")->value = {0.660635};
        at("denominator")->value = {3.613039};
        at("impulse")->value = {1.411554};
        const std::vector<rbw::AnswerResult> results = rbw::checkAnswers(before, g.answerTrace, answers);
        const rbw::AnswerResult& r = results[std::size_t(at("rotational_b") - answers.begin())];
        QCOMPARE(r.verdict, rbw::Verdict::Wrong);
        QStringList named;
        for (const char* id : r.mistakes) named << id;
        QVERIFY2(named == QStringList{"impulse-body-inverse-inertia"},
                 qPrintable(named.join(", ") + " / " + QString::fromStdString(r.explanation)));
        // one mistake, one red: the denominator and J follow from the student's B term
        for (const char* q : {"denominator", "impulse"}) {
            QCOMPARE(results[std::size_t(at(q) - answers.begin())].verdict, rbw::Verdict::FollowsFromEarlier);
        }
        // and the measurement over seeds 1..20 finds it in B's term, the denominator and J
        const rbw::ExerciseMistakeReport boxes = rbw::measureExerciseMistakes(spec, seeds(20));
        const rbw::ModelVisibility& m = modelOf(boxes, "impulse-body-inverse-inertia");
        QCOMPARE(m.shownIn, (QStringList{"rotational_b (A–B)", "denominator (A–B)", "impulse (A–B)"}));
    }

    // Negative control: exercise 03 with the lesson's unit cube for B (without the rule that
    // makes it 1.4 x 1 x 0.6): a cube's I0^-1 = k E is R I0^-1 R^T in every frame (and its
    // corner lies on the line through its centre along n, u_B = (0.5, 0.5, 0.5) x (1, 1, 1) = 0),
    // and A is a cube as well, so impulse-body-inverse-inertia shows nowhere.
    void cubesHideBodyInverseInertia()
    {
        rbw::ExerciseSpec spec = lessonSpec("03-two-box-collision");
        ruleFor(spec, "bodies[1].size");   // the rule exists
        std::erase_if(spec.vary, [](const rbw::ExerciseVary& v) { return v.paths.contains("bodies[1].size"); });
        const rbw::ExerciseMistakeReport cubes = rbw::measureExerciseMistakes(spec, seeds(20));
        QVERIFY(cubes.errors.isEmpty());
        QVERIFY(modelOf(cubes, "impulse-body-inverse-inertia").shownIn.isEmpty());
        QVERIFY(!modelOf(cubes, "impulse-linear-only").shownIn.isEmpty());   // the measurement still sees the others
    }

    // The separating exercise's key (lesson 6's further exercise, seed 1): step 33, the
    // edge cube (unit cube, M = 2.5, c = 0.7) has bounced and its corner is still below the
    // ground, moving up: v_rel.n = 0.729025 > 0, so the key's J is 0 (the checker's own
    // expectation, checker.h: expectedValue), and J = 0 written by a student is correct.
    // Forgetting the check: I^-1 = (6/M) E = 2.4 E for a cube at any orientation,
    // x_a = (0, -0.718154, -0.483999), n = (0, 1, 0), x_a x n = (0.483999, 0, 0),
    // [(I^-1 (x_a x n)) x x_a].n = 2.4 * 0.483999^2 = 0.562211,
    // J = -(1 + 0.7) * 0.729025 / (1/2.5 + 0.562211) = -1.239343 / 0.962211 = -1.288016:
    // the checker names no-separating-check for it.
    void separatingKeyIsZeroAndTheModelIsNamed()
    {
        const rbw::GeneratedExercise g = rbw::generateExercise(lessonSpec("06-box-on-plane/separating"), 1);
        QVERIFY2(g.ok(), qPrintable(g.errors.join('\n')));
        QCOMPARE(g.answerStep, 33L);
        std::vector<rbw::Answer> answers = rbw::exerciseAnswers(g);
        const auto J = std::find_if(answers.begin(), answers.end(), [](const rbw::Answer& a) {
            return a.quantity == "impulse" && a.contact == 0;
        });
        QVERIFY(J != answers.end());
        QVERIFY(g.answerTrace.contacts[0].separating);
        QCOMPARE(g.scene->bodies[g.answerTrace.contacts[0].bodyA].name, std::string("edge"));
        QCOMPARE(J->value, std::vector<double>{0.0});
        // the key's J comes after the contact's v_rel.n, as a student computes it
        QVERIFY(J != answers.begin() && std::prev(J)->quantity == "normal_velocity");
        QVERIFY(std::abs(std::prev(J)->value[0] - 0.729025) < 1e-6);
        rbw::World before(*g.scene);
        while (before.stepIndex() < g.answerStep) QVERIFY(before.step().ok);
        // the key as the student's answers: every one correct, J = 0 included
        for (const rbw::AnswerResult& r : rbw::checkAnswers(before, g.answerTrace, answers)) {
            QCOMPARE(r.verdict, rbw::Verdict::Correct);
        }
        // the impulse applied anyway
        J->value = {-1.288016};
        const std::vector<rbw::AnswerResult> results = rbw::checkAnswers(before, g.answerTrace, answers);
        const rbw::AnswerResult& r = results[std::size_t(J - answers.begin())];
        QCOMPARE(r.verdict, rbw::Verdict::Wrong);
        QCOMPARE(r.expected, std::vector<double>{0.0});
        QStringList named;
        for (const char* id : r.mistakes) named << id;
        QVERIFY2(named == QStringList{"no-separating-check"}, qPrintable(named.join(", ") + " / " +
                                                                        QString::fromStdString(r.explanation)));
        // Negative control: J = 1 (no model gives it) names nothing.
        J->value = {1.0};
        const rbw::AnswerResult other = rbw::checkAnswers(before, g.answerTrace, answers)[std::size_t(J - answers.begin())];
        QCOMPARE(other.verdict, rbw::Verdict::Wrong);
        QVERIFY(other.mistakes.empty());
    }

private:
    static QString measuredIntro()
    {
        return QStringLiteral(
            "\n"
            "Measured, not claimed: `tests/app/exercise/tst_exercise_mistakes.cpp` runs every mistake\n"
            "model of the catalogue (each variant) against every draw of seeds 1–20 of each lesson's\n"
            "exercise (`app/exercise/exercise_mistakes.h`) and writes this section; it fails when this\n"
            "text differs (it prints the new one), when a draw makes a model give the right number\n"
            "in a quantity where other draws show it, or when a draw makes two models give the same\n"
            "numbers where other draws tell them apart. \"Shows in\": the exercise's answers in which\n"
            "the model gives another number than the right one in every draw (a quantity, its body\n"
            "or its contact's pair; a separating contact's answers, whose right J is 0, are rows of\n"
            "their own). \"The same numbers as\": models it cannot be told apart from in\n"
            "that exercise (every answer the same in every draw). \"Cannot show\": models that give\n"
            "the right number in every answer of every draw.\n");
    }
};

QTEST_GUILESS_MAIN(TestExerciseMistakes)
#include "tst_exercise_mistakes.moc"
