// The checker of physics/workbook/checker/checker.h: verdicts, the mistakes a wrong number
// shows, error carried forward and the rounding of a student's earlier answers.
// Numbers by hand: Table 2.1 and lesson 3 as in tst_mistakes.cpp; lesson 8's
// "standard" box (Table 2.1's box at 30 deg about z, f = (100, 100, 0) at lever arm
// (0.3, 0.5, 0.25), h = 0.01): q = (-25, 25, -20), L' = h q = (-0.25, 0.25, -0.2),
// omega0 = 0 so R stays Rz(30).
#include "tests/physics/workbook/checker/checker_fixture.h"

#include <QtTest>

using rbw::Answer;
using rbw::Verdict;
using rbw::Vec3;
using rbw::test::answer;
using rbw::test::has;
using rbw::test::mayBe;
using rbw::test::StepUnderTest;
using rbw::test::stepOf;

namespace {

std::vector<double> flat(const rbw::TraceValue& v) { return rbw::test::flatValue(v); }

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
            QVERIFY(r[i].mistakes.empty() && r[i].possibleMistakes.empty());
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
        // v_p = v = (1, 1, 0)
        QTest::newRow("v_p without rotation") << "point_velocity" << 1 << std::vector<double>{1, 1, 0}
                                              << "point-velocity-without-rotation";
        // v_p = v + (p - x) x omega' = (-1.111861, 0.929412, 2.675410) (tst_mistakes): the
        // reversed torque gives it too, through a torque and an L the student did not write,
        // so alone it is only possible (tst_diagnosis names it with the right q and omega).
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
        QVERIFY(r.possibleMistakes.empty());
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

        // Alone it fits only through an I^-1 the student did not write: possible, not named.
        const rbw::AnswerResult alone = rbw::checkAnswers(*s.before, s.trace, {wrongOmega}).front();
        QCOMPARE(alone.verdict, Verdict::Wrong);
        QVERIFY(!has(alone, "transposed-inertia"));
        QVERIFY(mayBe(alone, "transposed-inertia"));

        const std::vector<rbw::AnswerResult> chain = rbw::checkAnswers(*s.before, s.trace, {wrongIinv, wrongOmega});
        QCOMPARE(chain[0].verdict, Verdict::Wrong);
        QVERIFY(has(chain[0], "transposed-inertia"));
        QCOMPARE(chain[1].verdict, Verdict::FollowsFromEarlier);

        // Negative control: an omega that neither the workbook's nor the student's I^-1 gives.
        const Answer other = answer("angular_velocity", 0, {1, 2, 3});
        QCOMPARE(rbw::checkAnswers(*s.before, s.trace, {wrongIinv, other})[1].verdict, Verdict::Wrong);
    }

    // Lesson 8's template box (issue 21 item 5): I^-1 written with the standard R I0^-1 R^T
    // for the body in the course template's convention (which needs R^T I0^-1 R) is the
    // convention mix-up, and the explanation gives the formula that body needs, not the
    // one the student used. Negative control: the same matrix is right for the standard box.
    void templateBoxWithStandardFormula()
    {
        StepUnderTest s = stepOf("08-conventions/scene.json", 0);
        const rbw::Mat3 R = std::get<rbw::Mat3>(s.trace.find(rbw::q::rotation_matrix.id, 1)->value);
        const rbw::Mat3 I0inv = std::get<rbw::Mat3>(s.trace.find(rbw::q::inverse_inertia_body.id, 1)->value);
        rbw::TraceValue standard = rbw::Mat3(R * I0inv * R.transpose());
        const rbw::AnswerResult r =
            rbw::checkAnswers(*s.before, s.trace, {answer("inverse_inertia_world", 1, flat(standard))}).front();
        QCOMPARE(r.verdict, Verdict::Wrong);
        QVERIFY2(has(r, "transposed-inertia"), r.explanation.c_str());
        const QString text = QString::fromStdString(r.explanation);
        QVERIFY2(text.contains("course template's convention") && text.contains("needs I^-1 = R^T I0^-1 R"),
                 qPrintable(text));
        QVERIFY2(!text.contains("needs I^-1 = R I0^-1 R^T"), qPrintable(text));
        const rbw::AnswerResult std0 =
            rbw::checkAnswers(*s.before, s.trace, {answer("inverse_inertia_world", 0, flat(standard))}).front();
        QCOMPARE(std0.verdict, Verdict::Correct);
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

        // J alone: each model changes a numerator or denominator the student did not write,
        // so it is possible; with those written (and right where the model keeps them) it is named.
        const rbw::AnswerResult linear =
            rbw::checkAnswers(*s.before, s.trace, {answer("impulse", -1, {8.0 / 3.0}, 0)}).front();
        QCOMPARE(linear.verdict, Verdict::Wrong);
        QVERIFY(mayBe(linear, "impulse-linear-only"));
        const rbw::AnswerResult onePlus =
            rbw::checkAnswers(*s.before, s.trace, {answer("impulse", -1, {32.0 / 27.0}, 0)}).front();
        QVERIFY(mayBe(onePlus, "impulse-without-one-plus"));
        // numerator 4 (right), denominator 1.5 = 1/M_A + 1/M_B, J = 8/3: the denominator is
        // red and J follows from it. 1.5 is also the denominator without the cross product
        // with x_a (A's term (I^-1 (x_a x n)) . n = 0 here): both possible, until the right
        // rotational_a = 3/16 is written, which contradicts the missing cross product.
        for (bool withTerm : {false, true}) {
            std::vector<Answer> answers = {answer("numerator", -1, {4.0}, 0)};
            if (withTerm) answers.push_back(answer("rotational_a", -1, {0.1875}, 0));
            answers.push_back(answer("denominator", -1, {1.5}, 0));
            answers.push_back(answer("impulse", -1, {8.0 / 3.0}, 0));
            const std::vector<rbw::AnswerResult> written = rbw::checkAnswers(*s.before, s.trace, answers);
            QCOMPARE(rbw::test::count(written, Verdict::Wrong), 1);
            const rbw::AnswerResult& den = written[answers.size() - 2];
            QCOMPARE(den.verdict, Verdict::Wrong);
            if (withTerm) {
                QVERIFY(has(den, "impulse-linear-only"));
                QVERIFY(den.possibleMistakes.empty());
            } else {
                QVERIFY(mayBe(den, "impulse-linear-only") && mayBe(den, "impulse-denominator-missing-cross"));
            }
            QCOMPARE(written.back().verdict, Verdict::FollowsFromEarlier);
        }
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

    // Precision is not a mistake (issue 21 item 4). Right to 3 significant figures is
    // half a unit of the third figure of the largest component: I0 = diag(0.1016667,
    // 0.2083333, 0.2266667) as diag(0.102, 0.208, 0.227) is 0.00033 off per entry, within
    // 0.0005 but not the 4-figure tolerance 0.001 * 0.2266667 = 0.00023; the docs'
    // v_p = (3.11, 1.07, -2.68) for (3.111861, 1.070588, -2.675410) is at most 0.0046 off,
    // within 0.005 but not 0.001 * 3.111861 = 0.0031. Wrong in the third figure: 0.103 is
    // 0.0013 off, (3.12, ...) 0.0081 off: wrong.
    void imprecise_data()
    {
        QTest::addColumn<QString>("id");
        QTest::addColumn<int>("index");
        QTest::addColumn<std::vector<double>>("value");
        QTest::addColumn<int>("verdict");
        QTest::newRow("I0 to 3 figures") << "inertia_body" << -1
                                         << std::vector<double>{0.102, 0, 0, 0, 0.208, 0, 0, 0, 0.227}
                                         << int(Verdict::Imprecise);
        QTest::newRow("v_p to 3 figures") << "point_velocity" << 1 << std::vector<double>{3.11, 1.07, -2.68}
                                          << int(Verdict::Imprecise);
        QTest::newRow("I0 wrong in the 3rd figure") << "inertia_body" << -1
                                                    << std::vector<double>{0.103, 0, 0, 0, 0.208, 0, 0, 0, 0.227}
                                                    << int(Verdict::Wrong);
        QTest::newRow("v_p wrong in the 3rd figure") << "point_velocity" << 1 << std::vector<double>{3.12, 1.07, -2.68}
                                                     << int(Verdict::Wrong);
        QTest::newRow("v_p to 4 figures") << "point_velocity" << 1 << std::vector<double>{3.112, 1.071, -2.675}
                                          << int(Verdict::Correct);
    }

    void imprecise()
    {
        QFETCH(QString, id);
        QFETCH(int, index);
        QFETCH(std::vector<double>, value);
        QFETCH(int, verdict);
        StepUnderTest s = stepOf("01-one-step/scene.json", 0);
        const rbw::AnswerResult r = rbw::checkAnswers(*s.before, s.trace, {answer(qPrintable(id), 0, value, -1, index)}).front();
        QCOMPARE(int(r.verdict), verdict);
        QCOMPARE(rbw::countsAsCorrect(r.verdict), verdict != int(Verdict::Wrong));
        if (r.verdict == Verdict::Imprecise) {
            QCOMPARE(QString::fromStdString(r.explanation),
                     QStringLiteral("Right to 3 significant figures; write 4 for the check."));
            QVERIFY(r.mistakes.empty() && r.possibleMistakes.empty());
        }
    }

    // A separating contact (v_rel . n = +2 > 0) gets no impulse: the trace records none,
    // and J = 0 is the right answer (not bad input); J = 1 is wrong.
    void separatingContactHasNoImpulse()
    {
        StepUnderTest s = stepOf("03-two-box-collision/scene.json", 2);
        rbw::StepTrace t;
        t.step = 2;
        t.contacts.push_back(rbw::ContactHeader{0, 1, -1, "vertex-face", "single-point", 1, true, {}});
        t.add(rbw::q::contact_normal, 0, Vec3(1, 0, 0), 0);
        t.add(rbw::q::relative_velocity, 0, Vec3(2, 0, 0), 0);
        t.add(rbw::q::normal_velocity, 0, 2.0, 0);
        const Answer zero = answer("impulse", -1, {0.0}, 0);
        QVERIFY2(rbw::answerProblem(t, zero).empty(), rbw::answerProblem(t, zero).c_str());
        QCOMPARE(rbw::checkAnswers(*s.before, t, {zero}).front().verdict, Verdict::Correct);
        QCOMPARE(rbw::checkAnswers(*s.before, t, {answer("impulse", -1, {1.0}, 0)}).front().verdict, Verdict::Wrong);
        // Negative control: an approaching contact without its J recorded stays bad input.
        t.contacts.front().separating = false;
        QVERIFY(!rbw::answerProblem(t, zero).empty());

        // Lesson 6, step 33: the edge box's corner leaves the ground (contact 0 separating,
        // as rbw run --trace all shows): J = 0 is right.
        StepUnderTest edge = stepOf("06-box-on-plane/scene.json", 33);
        QVERIFY(!edge.trace.contacts.empty() && edge.trace.contacts.front().separating);
        QVERIFY(rbw::answerProblem(edge.trace, zero).empty());
        QCOMPARE(rbw::checkAnswers(*edge.before, edge.trace, {zero}).front().verdict, Verdict::Correct);
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
