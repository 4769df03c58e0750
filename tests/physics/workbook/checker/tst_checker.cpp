// The checker of physics/workbook/checker/checker.h: verdicts, the mistakes a wrong number
// shows, error carried forward and the rounding of a student's earlier answers.
// Numbers by hand: Table 2.1 and lesson 3 as in tst_mistakes.cpp; lesson 8's
// "standard" box (Table 2.1's box at 30 deg about z, f = (100, 100, 0) at lever arm
// (0.3, 0.5, 0.25), h = 0.01): q = (-25, 25, -20), L' = h q = (-0.25, 0.25, -0.2),
// omega0 = 0 so R stays Rz(30).
#include "tests/test_support.h"

#include "physics/workbook/checker/checker.h"
#include "physics/engine/quantities.h"
#include "physics/engine/world.h"

#include <QtTest>

using rbw::Answer;
using rbw::Verdict;
using rbw::Vec3;

namespace {

// The world at the start of step k of a lesson and the trace of that step.
struct StepUnderTest {
    std::unique_ptr<rbw::World> before;
    rbw::StepTrace trace;
};

StepUnderTest stepOf(const char* lesson, int k)
{
    StepUnderTest s;
    s.before = std::make_unique<rbw::World>(rbw::test::lessonScene(QString::fromLatin1(lesson)));
    for (int i = 0; i < k; ++i) {
        if (!s.before->step().ok) qFatal("blew up");
    }
    const rbw::WorldSnapshot snap = s.before->snapshot();
    if (!s.before->step(&s.trace).ok) qFatal("blew up");
    s.before->restore(snap);
    return s;
}

Answer answer(const char* id, int body, std::vector<double> v, int contact = -1, int index = -1)
{
    Answer a;
    a.quantity = id;
    a.body = body;
    a.contact = contact;
    a.index = index;
    a.value = std::move(v);
    return a;
}

bool has(const rbw::AnswerResult& r, const char* mistake)
{
    return std::any_of(r.mistakes.begin(), r.mistakes.end(), [&](const char* m) { return std::strcmp(m, mistake) == 0; });
}

std::vector<double> flat(const rbw::TraceValue& v)
{
    const QList<double> l = rbw::test::flatten(v);
    return std::vector<double>(l.begin(), l.end());
}

} // namespace

class TestChecker : public QObject {
    Q_OBJECT
private slots:
    // Table 2.1, every answer right to 4 significant figures: all correct, no mistake
    // named (the negative control for the mistake matching).
    void rightAnswersAreCorrect()
    {
        StepUnderTest s = stepOf("01-one-step/scene.json", 0);
        const std::vector<Answer> answers = {
            answer("torque", 0, {-0.25, 0.25, -0.2}),
            answer("position", 0, {0, 0, 0}),
            answer("linear_velocity", 0, {1, 1, 0}),
            answer("angular_momentum", 0, {-0.5, 0.5, -0.4}),
            answer("inverse_inertia_world", 0, {4.8, 0, 0, 0, 9.836, 0, 0, 0, 4.412}),
            answer("angular_velocity", 0, {-2.4, 4.918, -1.765}),
            answer("point_velocity", 0, {3.112, 1.071, -2.675}, -1, 1),
        };
        const std::vector<rbw::AnswerResult> r = rbw::checkAnswers(*s.before, s.trace, answers);
        for (size_t i = 0; i < r.size(); ++i) {
            QVERIFY2(r[i].verdict == Verdict::Correct, answers[i].quantity.c_str());
            QVERIFY(r[i].mistakes.empty());
        }
    }

    void wrongAnswersNameTheirMistake_data()
    {
        QTest::addColumn<QString>("id");
        QTest::addColumn<int>("index");
        QTest::addColumn<std::vector<double>>("value");
        QTest::addColumn<QString>("mistake");
        // x = x + h v_{n+1} = (2, 2, 0)
        QTest::newRow("x with the new v") << "position" << -1 << std::vector<double>{2, 2, 0}
                                          << "velocity-before-position";
        // L = L + q (no h) = (-0.25, 0.25, -0.2)
        QTest::newRow("L without h") << "angular_momentum" << -1 << std::vector<double>{-0.25, 0.25, -0.2}
                                     << "missing-time-step";
        // omega = I0^-1 L' = (-4.918, 2.4, -1.765)
        QTest::newRow("omega in the body frame") << "angular_velocity" << -1 << std::vector<double>{-4.918, 2.4, -1.765}
                                                 << "body-inverse-inertia";
        // v_p = v = (1, 1, 0)
        QTest::newRow("v_p without rotation") << "point_velocity" << 1 << std::vector<double>{1, 1, 0}
                                              << "point-velocity-without-rotation";
    }

    void wrongAnswersNameTheirMistake()
    {
        QFETCH(QString, id);
        QFETCH(int, index);
        QFETCH(std::vector<double>, value);
        QFETCH(QString, mistake);
        StepUnderTest s = stepOf("01-one-step/scene.json", 0);
        const Answer a = answer(qPrintable(id), 0, value, -1, index);
        QVERIFY(rbw::answerProblem(s.trace, a).empty());
        const rbw::AnswerResult r = rbw::checkAnswers(*s.before, s.trace, {a}).front();
        QCOMPARE(r.verdict, Verdict::Wrong);
        QVERIFY2(has(r, qPrintable(mistake)), qPrintable(QString::number(r.mistakes.size())));
    }

    // Lesson 8: omega made with R^T I0^-1 R shows transposed-inertia; an omega consistent
    // with an earlier wrong (transposed) I^-1 follows from it; the same omega without
    // that earlier answer is only wrong.
    void transposedInertiaAndCarriedError()
    {
        StepUnderTest s = stepOf("08-conventions/scene.json", 0);
        const rbw::Mat3 R = std::get<rbw::Mat3>(s.trace.find(rbw::q::rotation_matrix.id, 0)->value);
        const rbw::Mat3 I0inv = std::get<rbw::Mat3>(s.trace.find(rbw::q::inverse_inertia_body.id, 0)->value);
        const Vec3 L = std::get<Vec3>(s.trace.find(rbw::q::angular_momentum.id, 0)->value);
        QVERIFY(rbw::test::mismatch(rbw::test::flat(L), {-0.25, 0.25, -0.2}, 1e-12).isEmpty());
        // The student's I^-1 = R^T I0^-1 R and omega = I^-1 L with it.
        const rbw::Mat3 IinvT = R.transpose() * I0inv * R;
        const Vec3 omegaT = IinvT * L;
        rbw::TraceValue iv = IinvT;
        const Answer wrongIinv = answer("inverse_inertia_world", 0, flat(iv));
        const Answer wrongOmega = answer("angular_velocity", 0, {omegaT.x(), omegaT.y(), omegaT.z()});

        const rbw::AnswerResult alone = rbw::checkAnswers(*s.before, s.trace, {wrongOmega}).front();
        QCOMPARE(alone.verdict, Verdict::Wrong);
        QVERIFY(has(alone, "transposed-inertia"));

        const std::vector<rbw::AnswerResult> chain = rbw::checkAnswers(*s.before, s.trace, {wrongIinv, wrongOmega});
        QCOMPARE(chain[0].verdict, Verdict::Wrong);
        QVERIFY(has(chain[0], "transposed-inertia"));
        QCOMPARE(chain[1].verdict, Verdict::FollowsFromEarlier);

        // Negative control: an omega that neither the workbook's nor the student's I^-1 gives.
        const Answer other = answer("angular_velocity", 0, {1, 2, 3});
        QCOMPARE(rbw::checkAnswers(*s.before, s.trace, {wrongIinv, other})[1].verdict, Verdict::Wrong);
    }

    // Lesson 3, step 2 (the contact): v_rel reversed, (-2, 0, 0), and the J it gives,
    // -(1 + 1)(+2)/(27/16) = -64/27: the J follows from the wrong v_rel. J = 8/3 is the
    // linear-only impulse, J = 32/27 the one without "1 +".
    void impulseChain()
    {
        StepUnderTest s = stepOf("03-two-box-collision/scene.json", 2);
        QCOMPARE(s.trace.contacts.size(), size_t(1));
        const Answer vrel = answer("relative_velocity", -1, {-2, 0, 0}, 0);
        const Answer J = answer("impulse", -1, {-64.0 / 27.0}, 0);
        const std::vector<rbw::AnswerResult> r = rbw::checkAnswers(*s.before, s.trace, {vrel, J});
        QCOMPARE(r[0].verdict, Verdict::Wrong);
        QVERIFY(has(r[0], "relative-velocity-reversed"));
        QCOMPARE(r[1].verdict, Verdict::FollowsFromEarlier);

        const rbw::AnswerResult linear =
            rbw::checkAnswers(*s.before, s.trace, {answer("impulse", -1, {8.0 / 3.0}, 0)}).front();
        QCOMPARE(linear.verdict, Verdict::Wrong);
        QVERIFY(has(linear, "impulse-linear-only"));
        const rbw::AnswerResult onePlus =
            rbw::checkAnswers(*s.before, s.trace, {answer("impulse", -1, {32.0 / 27.0}, 0)}).front();
        QVERIFY(has(onePlus, "impulse-without-one-plus"));
        const rbw::AnswerResult right =
            rbw::checkAnswers(*s.before, s.trace, {answer("impulse", -1, {2.370}, 0)}).front();
        QCOMPARE(right.verdict, Verdict::Correct);
    }

    // Rounding carried forward, where it matters: a difference of two nearly equal
    // numbers. Contact 0 has v_A(p) = (10.0123, 0, 0) and v_B(p) = (10, 0, 0), so
    // v_rel = (0.0123, 0, 0). A student writes both to 4 figures, (10.01, 0, 0) and
    // (10.00, 0, 0) (both right within 0.1 %), and subtracts: v_rel = (0.01, 0, 0), 19 %
    // below the workbook's. Their rounding, 0.1 % of each, carries
    // 0.001 * 10.01 + 0.001 * 10.00 = 0.02001 into v_rel's tolerance: right. The same
    // v_rel alone is wrong; from a wrong v_A(p) = (10.5, 0, 0) the student's 0.5 follows
    // from the earlier error.
    void roundingIsCarriedForward()
    {
        StepUnderTest s = stepOf("03-two-box-collision/scene.json", 2);
        rbw::StepTrace t;
        t.step = 2;
        t.contacts.push_back(rbw::ContactHeader{0, 1, -1, "vertex-face", "single-point", 1, false, {}});
        t.add(rbw::q::velocity_a, 0, Vec3(10.0123, 0, 0), 0);
        t.add(rbw::q::velocity_b, 1, Vec3(10, 0, 0), 0);
        t.add(rbw::q::relative_velocity, 0, Vec3(0.0123, 0, 0), 0);
        const auto verdicts = [&](std::vector<Answer> answers) { return rbw::checkAnswers(*s.before, t, answers); };
        const Answer vA = answer("velocity_a", -1, {10.01, 0, 0}, 0);
        const Answer vB = answer("velocity_b", -1, {10.00, 0, 0}, 0);
        const Answer vrel = answer("relative_velocity", -1, {0.01, 0, 0}, 0);
        const std::vector<rbw::AnswerResult> r = verdicts({vA, vB, vrel});
        QCOMPARE(r[0].verdict, Verdict::Correct);
        QCOMPARE(r[1].verdict, Verdict::Correct);
        QCOMPARE(r[2].verdict, Verdict::Correct);
        // Negative control: without the rounded inputs the same v_rel is wrong.
        QCOMPARE(verdicts({vrel})[0].verdict, Verdict::Wrong);
        // From a wrong input: follows from the earlier error.
        const std::vector<rbw::AnswerResult> carried =
            verdicts({answer("velocity_a", -1, {10.5, 0, 0}, 0), vB, answer("relative_velocity", -1, {0.5, 0, 0}, 0)});
        QCOMPARE(carried[0].verdict, Verdict::Wrong);
        QCOMPARE(carried[2].verdict, Verdict::FollowsFromEarlier);
    }

    void problems_data()
    {
        QTest::addColumn<QString>("id");
        QTest::addColumn<int>("body");
        QTest::addColumn<int>("contact");
        QTest::addColumn<int>("count");
        QTest::addColumn<QString>("words");
        QTest::newRow("unknown quantity") << "angular_velocty" << 0 << -1 << 3 << "unknown quantity";
        QTest::newRow("vector as number") << "angular_velocity" << 0 << -1 << 1 << "a vector of 3 numbers";
        QTest::newRow("contact id without contact") << "impulse" << 0 << -1 << 1 << "needs \"contact\"";
        QTest::newRow("no such contact") << "impulse" << -1 << 3 << 1 << "no contact 3";
        QTest::newRow("matrix of 3") << "inverse_inertia_world" << 0 << -1 << 3 << "3x3 matrix";
    }

    void problems()
    {
        QFETCH(QString, id);
        QFETCH(int, body);
        QFETCH(int, contact);
        QFETCH(int, count);
        QFETCH(QString, words);
        StepUnderTest s = stepOf("01-one-step/scene.json", 0);
        const std::string p = rbw::answerProblem(s.trace, answer(qPrintable(id), body, std::vector<double>(count, 1.0), contact));
        QVERIFY2(QString::fromStdString(p).contains(words), p.c_str());
    }
};

QTEST_GUILESS_MAIN(TestChecker)
#include "tst_checker.moc"
