// The checker's tolerance never becomes infinite (issue 22, item 5): a value recomputed
// from the student's answers through a denominator near zero overflows, and an
// infinite reference (or tolerance) would take every number, so a wrong impulse read
// "follows from your earlier answers". physics/workbook/checker/tolerance.h: a
// reference or tolerance that is not finite matches nothing.
//
// Lesson 3, step 2 (tst_mistakes.cpp): numerator 4, denominator 27/16, right J = 64/27.
// The case: numerator 1.8e8 and denominator 1e-300 written (both wrong); J from
// them is 1.8e8 / 1e-300 = 1.8e308 > DBL_MAX = 1.797e308, i.e. inf.
#include "physics/workbook/checker/tolerance.h"
#include "tests/physics/workbook/checker/checker_fixture.h"

#include <QtTest>

#include <limits>

using rbw::Answer;
using rbw::Verdict;
using rbw::checking::Values;
using rbw::test::answer;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
} // namespace

class TestTolerance : public QObject {
    Q_OBJECT
private slots:
    void matchesWithin_data()
    {
        QTest::addColumn<Values>("given");
        QTest::addColumn<Values>("ref");
        QTest::addColumn<double>("tol");
        QTest::addColumn<Values>("extra");
        QTest::addColumn<bool>("match");
        // negative controls: finite numbers behave as before
        QTest::newRow("within tol") << Values{1.0} << Values{1.05} << 0.1 << Values{} << true;
        QTest::newRow("outside tol") << Values{1.0} << Values{1.2} << 0.1 << Values{} << false;
        QTest::newRow("within tol + extra") << Values{1.0} << Values{1.2} << 0.1 << Values{0.15} << true;
        QTest::newRow("quaternion as -q") << Values{1, 0, 0, 0} << Values{-1, 0, 0, 0} << 1e-9 << Values{} << true;
        // what an overflow upstream makes
        QTest::newRow("reference inf") << Values{5.0} << Values{kInf} << 0.1 << Values{} << false;
        QTest::newRow("reference inf, answer inf") << Values{kInf} << Values{kInf} << 0.1 << Values{} << false;
        QTest::newRow("tolerance inf") << Values{5.0} << Values{1.0} << kInf << Values{} << false;
        QTest::newRow("extra inf") << Values{5.0} << Values{1.0} << 0.1 << Values{kInf} << false;
        QTest::newRow("extra NaN") << Values{1.0} << Values{1.0} << 0.1 << Values{kNaN} << false;
        QTest::newRow("reference NaN") << Values{1.0} << Values{kNaN} << 0.1 << Values{} << false;
    }
    void matchesWithin()
    {
        QFETCH(Values, given);
        QFETCH(Values, ref);
        QFETCH(double, tol);
        QFETCH(Values, extra);
        QFETCH(bool, match);
        QCOMPARE(rbw::checking::matchesWithin(given, ref, tol, extra), match);
    }

    // Through checkAnswers: the impulse after a denominator near zero.
    void impulseAfterDenominatorNearZero_data()
    {
        QTest::addColumn<double>("numerator");
        QTest::addColumn<double>("denominator");
        QTest::addColumn<double>("impulse");
        QTest::addColumn<int>("verdict");
        // The row: J = 1.8e8 / 1e-300 overflows; any J was follows-from-earlier.
        QTest::newRow("1.8e8 / 1e-300, J = 5") << 1.8e8 << 1e-300 << 5.0 << int(Verdict::Wrong);
        QTest::newRow("1.8e8 / 1e-300, J = 1e308") << 1.8e8 << 1e-300 << 1e308 << int(Verdict::Wrong);
        QTest::newRow("-1e10 / 1e-300, J = -7") << -1e10 << 1e-300 << -7.0 << int(Verdict::Wrong);   // -inf
        // Negative control: a finite wrong chain still follows: 4 / 1.5 = 8/3.
        QTest::newRow("4 / 1.5, J = 8/3") << 4.0 << 1.5 << 8.0 / 3.0 << int(Verdict::FollowsFromEarlier);
        // A large but finite quotient follows as well: 1.8e8 / 1e-200 = 1.8e208.
        QTest::newRow("1.8e8 / 1e-200, J = 1.8e208") << 1.8e8 << 1e-200 << 1.8e208 << int(Verdict::FollowsFromEarlier);
    }
    void impulseAfterDenominatorNearZero()
    {
        QFETCH(double, numerator);
        QFETCH(double, denominator);
        QFETCH(double, impulse);
        QFETCH(int, verdict);
        rbw::test::StepUnderTest s = rbw::test::stepOf("03-two-box-collision/scene.json", 2);
        QCOMPARE(s.trace.contacts.size(), size_t(1));
        const std::vector<Answer> answers = {answer("numerator", -1, {numerator}, 0),
                                             answer("denominator", -1, {denominator}, 0),
                                             answer("impulse", -1, {impulse}, 0)};
        const std::vector<rbw::AnswerResult> r = rbw::checkAnswers(*s.before, s.trace, answers);
        QCOMPARE(r[1].verdict, Verdict::Wrong);   // the right one is 27/16
        QCOMPARE(int(r[2].verdict), verdict);
        QVERIFY(!r[2].explanation.empty());
    }
};

QTEST_GUILESS_MAIN(TestTolerance)
#include "tst_tolerance.moc"
