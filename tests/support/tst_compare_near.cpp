// RBW_COMPARE_NEAR and RBW_COMPARE_NEAR_STRICT (tests/test_support.h) against their
// definitions: |actual - expected| <= tol (< tol for the strict one), for doubles and,
// with the Euclidean norm of the difference, for Eigen vectors and matrices; NaN never
// passes. Each failing case runs under QEXPECT_FAIL: if the macro passed where it must
// fail, QtTest reports XPASS and this test fails (the negative controls).
#include "tests/test_support.h"

#include <QtTest>

#include <cmath>
#include <limits>

using rbw::Mat3;
using rbw::Vec3;

class TestCompareNear : public QObject {
    Q_OBJECT

private slots:
    void doublesWithinTolerancePass();
    void boundaryPassesOnlyWhenNotStrict();
    void doublesBeyondToleranceFail();
    void nanNeverPasses();
    void vectorsUseTheNormOfTheDifference();
    void matricesUseTheFrobeniusNorm();
    void failureReturnsFromTheTest();
};

void TestCompareNear::doublesWithinTolerancePass()
{
    RBW_COMPARE_NEAR(64.0 / 27.0, 2.37037037037037, 1e-14);
    RBW_COMPARE_NEAR_STRICT(0.1 + 0.2, 0.3, 1e-15);   // differ by 2^-54 ~ 5.6e-17
    RBW_COMPARE_NEAR(-1e-13, 0.0, 1e-12, "a context");
    RBW_COMPARE_NEAR(3, 3.0, 0.0);                    // exact, through the conversion to double
}

// |1.5 - 1.0| = 0.5 exactly: at most 0.5, but not below 0.5.
void TestCompareNear::boundaryPassesOnlyWhenNotStrict()
{
    RBW_COMPARE_NEAR(1.5, 1.0, 0.5);
    QEXPECT_FAIL("", "0.5 is not < 0.5", Continue);
    RBW_COMPARE_NEAR_STRICT(1.5, 1.0, 0.5);
}

void TestCompareNear::doublesBeyondToleranceFail()
{
    QEXPECT_FAIL("", "|2.1818181818181817 - 2.18| = 1.8e-3 > 1e-3", Continue);
    RBW_COMPARE_NEAR(24.0 / 11.0, 2.18, 1e-3);
    QEXPECT_FAIL("", "the sign of the difference does not matter", Continue);
    RBW_COMPARE_NEAR(2.18, 24.0 / 11.0, 1e-3);
}

void TestCompareNear::nanNeverPasses()
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    QEXPECT_FAIL("", "NaN as the actual value", Continue);
    RBW_COMPARE_NEAR(nan, 0.0, 1e300);
    QEXPECT_FAIL("", "NaN as the expected value", Continue);
    RBW_COMPARE_NEAR(0.0, nan, 1e300);
    QEXPECT_FAIL("", "NaN as the tolerance", Continue);
    RBW_COMPARE_NEAR(0.0, 0.0, nan);
    QEXPECT_FAIL("", "a NaN component", Continue);
    RBW_COMPARE_NEAR(Vec3(0, nan, 0), Vec3::Zero(), 1e300);
}

// Each component of (0.6, 0.8, 0) is within 0.9, but the difference has length 1: the
// vector comparison is on the norm, exactly (a - b).norm() <= tol.
void TestCompareNear::vectorsUseTheNormOfTheDifference()
{
    const Vec3 a(1.6, 2.8, 3.0);
    const Vec3 b(1.0, 2.0, 3.0);
    RBW_COMPARE_NEAR(a, b, (a - b).norm());
    RBW_COMPARE_NEAR(a - b, Vec3(0.6, 0.8, 0.0), 1e-15);   // an expression as the actual value
    QEXPECT_FAIL("", "|(0.6, 0.8, 0)| = 1 > 0.9 though every component is within 0.9", Continue);
    RBW_COMPARE_NEAR(a, b, 0.9);
    QEXPECT_FAIL("", "strict: the norm itself is not below the norm", Continue);
    RBW_COMPARE_NEAR_STRICT(a, b, (a - b).norm());
}

void TestCompareNear::matricesUseTheFrobeniusNorm()
{
    Mat3 m = Mat3::Identity();
    m(0, 1) = 3e-13;
    m(2, 0) = -4e-13;   // Frobenius norm of m - E: 5e-13
    RBW_COMPARE_NEAR(m, Mat3::Identity(), 5.000001e-13);
    QEXPECT_FAIL("", "5e-13 > 4.9e-13", Continue);
    RBW_COMPARE_NEAR(m, Mat3::Identity(), 4.9e-13);
}

// A failure that was not expected ends the test function, as QVERIFY does: with
// QEXPECT_FAIL(..., Abort) the statements after it do not run.
void TestCompareNear::failureReturnsFromTheTest()
{
    bool reachedAfter = false;
    const auto body = [&reachedAfter]() {
        QEXPECT_FAIL("", "1 is not within 0.5 of 0", Abort);
        RBW_COMPARE_NEAR(1.0, 0.0, 0.5);
        reachedAfter = true;
    };
    body();
    QVERIFY(!reachedAfter);
}

QTEST_APPLESS_MAIN(TestCompareNear)
#include "tst_compare_near.moc"
