// Follow-through everywhere (issue 21 item 3): one mistake makes one red answer; every
// answer the checker can recompute from it is amber (follows-from-earlier) and names it.
// physics/workbook/checker/follow_through.h through checkAnswers().
//
// Lesson 1 (Table 2.1, h = 2, M = 2, R = Rz(90), numbers by hand in tst_mistakes.cpp):
// right q = (-0.25, 0.25, -0.2), L' = (-0.5, 0.5, -0.4), v' = (1, 1, 0), F = (1, 1, 0),
// I0 = diag(0.61, 1.25, 1.36)/6, I^-1 = diag(4.8, 9.836066, 4.411765), probe 1 at
// p = (0.3, 0.5, 0.25).
// Lesson 3, step 2 (tst_mistakes.cpp): n = (-1, 0, 0), v_A(p) = (1, 0, 0), v_B(p) =
// (-1, 0, 0), c = 1, 1/M_A = 0.5, 1/M_B = 1, x_a = (0.99, 0.5, 0), I_A^-1 = 3/4 E,
// denominator 27/16, right J = 64/27; A and B do not spin.
#include "tests/physics/workbook/checker/checker_fixture.h"

#include <QtTest>

using rbw::Answer;
using rbw::Verdict;
using rbw::test::answer;

namespace {

struct Chain {
    const char* lesson;
    int step;
    std::vector<Answer> answers;   // the first is the mistake, the rest follow from it
};

Chain chain(int i)
{
    switch (i) {
    case 0:
        // q reversed (0.25, -0.25, 0.2): L' = L_n + h q = 2 q = (0.5, -0.5, 0.4);
        // omega' = I^-1 L' = (2.4, -4.918033, 1.764706); v_p = v + omega' x p =
        // (1, 1, 0) - (2.111861, 0.070588, -2.675410) = (-1.111861, 0.929412, 2.675410)
        return {"01-one-step/scene.json", 0,
                {answer("torque", 0, {0.25, -0.25, 0.2}), answer("angular_momentum", 0, {0.5, -0.5, 0.4}),
                 answer("angular_velocity", 0, {2.4, -4.918, 1.765}),
                 answer("point_velocity", 0, {-1.112, 0.9294, 2.675}, -1, 1)}};
    case 1:
        // I0 of the half extents diag(0.0254167, 0.0520833, 0.0566667): I0^-1 =
        // diag(39.34426, 19.2, 17.64706); I^-1 = Rz(90) I0^-1 Rz(90)^T = diag(19.2, 39.34426,
        // 17.64706); omega' = (-0.5 * 19.2, 0.5 * 39.34426, -0.4 * 17.64706)
        return {"01-one-step/scene.json", 0,
                {answer("inertia_body", 0, {0.02542, 0, 0, 0, 0.05208, 0, 0, 0, 0.05667}),
                 answer("inverse_inertia_body", 0, {39.34, 0, 0, 0, 19.2, 0, 0, 0, 17.65}),
                 answer("inverse_inertia_world", 0, {19.2, 0, 0, 0, 39.34, 0, 0, 0, 17.65}),
                 answer("angular_velocity", 0, {-9.6, 19.67, -7.059})}};
    case 2:
        // r without the half angle (0, 0, 0, 1): R = diag(-1, -1, 1); I^-1 = R I0^-1 R^T =
        // diag(9.836066, 4.8, 4.411765); omega' = (-4.918033, 2.4, -1.764706)
        return {"01-one-step/scene.json", 0,
                {answer("orientation", 0, {0, 0, 0, 1}), answer("rotation_matrix", 0, {-1, 0, 0, 0, -1, 0, 0, 0, 1}),
                 answer("inverse_inertia_world", 0, {9.836, 0, 0, 0, 4.8, 0, 0, 0, 4.412}),
                 answer("angular_velocity", 0, {-4.918, 2.4, -1.765})}};
    case 3:
        // F doubled (2, 2, 0): v' = v_n + h F/M = 0 + 2 (2, 2, 0)/2 = (2, 2, 0)
        return {"01-one-step/scene.json", 0, {answer("force", 0, {2, 2, 0}), answer("linear_velocity", 0, {2, 2, 0})}};
    default:
        // v_rel reversed (-2, 0, 0): v_rel.n = 2, numerator -(1 + 1) 2 = -4, J = -4 / (27/16)
        // = -64/27, P = J n = (64/27, 0, 0);
        // dv_A = P/2 = (32/27, 0, 0), v'_A = (1 + 32/27, 0, 0) = (59/27, 0, 0);
        // dL_A = x_a x P = (0, 0, -0.5 * 64/27) = (0, 0, -32/27) = L'_A; omega'_A = 3/4 L'_A = (0, 0, -8/9);
        // dv_B = -P/1 = (-64/27, 0, 0), v'_B = (-1 - 64/27, 0, 0) = (-91/27, 0, 0)
        return {"03-two-box-collision/scene.json", 2,
                {answer("relative_velocity", -1, {-2, 0, 0}, 0), answer("normal_velocity", -1, {2}, 0),
                 answer("numerator", -1, {-4}, 0), answer("impulse", -1, {-64.0 / 27.0}, 0),
                 answer("delta_v_a", -1, {32.0 / 27.0, 0, 0}, 0), answer("linear_velocity_a", -1, {59.0 / 27.0, 0, 0}, 0),
                 answer("delta_L_a", -1, {0, 0, -32.0 / 27.0}, 0), answer("angular_momentum_a", -1, {0, 0, -32.0 / 27.0}, 0),
                 answer("angular_velocity_a", -1, {0, 0, -8.0 / 9.0}, 0), answer("delta_v_b", -1, {-64.0 / 27.0, 0, 0}, 0),
                 answer("linear_velocity_b", -1, {-91.0 / 27.0, 0, 0}, 0)}};
    }
}

} // namespace

class TestFollowThrough : public QObject {
    Q_OBJECT
private slots:
    void exactlyOneRed_data()
    {
        QTest::addColumn<int>("chain");
        QTest::newRow("q -> L -> omega -> v_p") << 0;
        QTest::newRow("I0 -> I0^-1 -> I^-1 -> omega") << 1;
        QTest::newRow("r -> R -> I^-1 -> omega") << 2;
        QTest::newRow("F -> v") << 3;
        QTest::newRow("v_rel -> ... -> J -> dv, v', dL, L', omega'") << 4;
    }

    void exactlyOneRed()
    {
        QFETCH(int, chain);
        const Chain c = ::chain(chain);
        rbw::test::StepUnderTest s = rbw::test::stepOf(c.lesson, c.step);
        for (const Answer& a : c.answers) QVERIFY2(rbw::answerProblem(s.trace, a).empty(), a.quantity.c_str());
        const std::vector<rbw::AnswerResult> r = rbw::checkAnswers(*s.before, s.trace, c.answers);
        QCOMPARE(r.front().verdict, Verdict::Wrong);
        QCOMPARE(rbw::test::count(r, Verdict::Wrong), 1);
        for (size_t i = 1; i < r.size(); ++i) {
            QVERIFY2(r[i].verdict == Verdict::FollowsFromEarlier, c.answers[i].quantity.c_str());
            // The amber text names the red answer it follows from.
            QVERIFY2(r[i].explanation.find("your earlier " + c.answers.front().quantity) != std::string::npos,
                     r[i].explanation.c_str());
            QVERIFY(r[i].mistakes.empty() && r[i].possibleMistakes.empty());
        }
    }

    // Negative control: a second, independent mistake in the chain is red too. After the
    // reversed torque, L' = (1, 1, 1) is not 2 q: two red, and omega from that L' follows.
    void secondMistakeIsRed()
    {
        rbw::test::StepUnderTest s = rbw::test::stepOf("01-one-step/scene.json", 0);
        // omega' = I^-1 (1, 1, 1) = (4.8, 9.836066, 4.411765)
        const std::vector<rbw::AnswerResult> r = rbw::checkAnswers(
            *s.before, s.trace,
            {answer("torque", 0, {0.25, -0.25, 0.2}), answer("angular_momentum", 0, {1, 1, 1}),
             answer("angular_velocity", 0, {4.8, 9.836, 4.412})});
        QCOMPARE(r[0].verdict, Verdict::Wrong);
        QCOMPARE(r[1].verdict, Verdict::Wrong);
        QCOMPARE(r[2].verdict, Verdict::FollowsFromEarlier);
        QVERIFY2(r[2].explanation.find("your earlier angular_momentum") != std::string::npos, r[2].explanation.c_str());
    }

    // A right chain written to 4 figures stays right all the way (the rounding carried).
    void rightChainIsRight()
    {
        rbw::test::StepUnderTest s = rbw::test::stepOf("01-one-step/scene.json", 0);
        const std::vector<rbw::AnswerResult> r = rbw::checkAnswers(
            *s.before, s.trace,
            {answer("inertia_body", 0, {0.1017, 0, 0, 0, 0.2083, 0, 0, 0, 0.2267}),
             answer("inverse_inertia_body", 0, {9.836, 0, 0, 0, 4.8, 0, 0, 0, 4.412}),
             answer("orientation", 0, {0.7071, 0, 0, 0.7071}), answer("rotation_matrix", 0, {0, -1, 0, 1, 0, 0, 0, 0, 1}),
             answer("inverse_inertia_world", 0, {4.8, 0, 0, 0, 9.836, 0, 0, 0, 4.412}),
             answer("angular_velocity", 0, {-2.4, 4.918, -1.765})});
        QCOMPARE(rbw::test::count(r, Verdict::Correct), int(r.size()));
    }
};

QTEST_GUILESS_MAIN(TestFollowThrough)
#include "tst_follow_through.moc"
