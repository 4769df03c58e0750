// Helpers shared by the tests: compare trace values against hand-derived numbers,
// near-comparisons that print what they compared (RBW_COMPARE_NEAR), and run the rbw
// command line.
#pragma once

#include "app/scene/scene_loader.h"
#include "physics/engine/collision/contact.h"
#include "physics/engine/trace.h"

#include <QList>
#include <QProcess>
#include <QString>
#include <QStringList>
#include <QTest>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace rbw::test {

using rbw::Mat3;
using rbw::Quat;
using rbw::Vec3;

// A lesson's scene from the source tree, e.g. lessonScene("05-spinning/scene.json").
// A lesson that does not load is a broken test setup, not a failed check: abort.
inline rbw::SceneDef lessonScene(const QString& relative)
{
    const rbw::SceneLoadResult r = rbw::loadSceneFile(QStringLiteral(RBW_SOURCE_DIR "/lessons/") + relative);
    if (!r.ok()) qFatal("%s", qPrintable(r.errors.join('\n')));
    return *r.scene;
}

// Flattens a trace value: scalar -> 1 entry, Vec3 -> (x, y, z), quaternion ->
// (w, x, y, z), Mat3 -> 9 entries row by row.
inline QList<double> flatten(const rbw::TraceValue& value)
{
    const std::vector<double> v = rbw::traceValueComponents(value);
    return QList<double>(v.begin(), v.end());
}

inline QList<double> flat(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
inline QList<double> flat(const Quat& q) { return {q.w(), q.x(), q.y(), q.z()}; }

inline QString listText(const QList<double>& v)
{
    QStringList parts;
    for (double d : v) {
        parts << QString::number(d, 'g', 17);
    }
    return QLatin1Char('(') + parts.join(QStringLiteral(", ")) + QLatin1Char(')');
}

// Empty when |a_i - e_i| <= relTol * max_j |e_j| for all i (relTol = 0: exact ==).
inline QString mismatch(const QList<double>& actual, const QList<double>& expected, double relTol)
{
    if (actual.size() != expected.size()) {
        return QStringLiteral("size %1, expected %2").arg(actual.size()).arg(expected.size());
    }
    double scale = 0.0;
    for (double e : expected) {
        scale = std::max(scale, std::abs(e));
    }
    const double allowed = relTol * scale;
    for (int i = 0; i < actual.size(); ++i) {
        const double diff = std::abs(actual[i] - expected[i]);
        if (!(diff <= allowed)) {
            return QStringLiteral("entry %1: got %2, expected %3 (|diff| = %4 > %5)\n  actual   %6\n  expected %7")
                .arg(i)
                .arg(actual[i], 0, 'g', 17)
                .arg(expected[i], 0, 'g', 17)
                .arg(diff, 0, 'g', 3)
                .arg(allowed, 0, 'g', 3)
                .arg(listText(actual), listText(expected));
        }
    }
    return {};
}

// RBW_COMPARE_NEAR(actual, expected, tol[, context]): passes when
// |actual - expected| <= tol. On failure it prints both values (17 significant digits),
// their difference, the tolerance and the optional context (a QString or a C string),
// and returns from the test function, as QVERIFY does (and, like it, honours
// QEXPECT_FAIL). It takes doubles (and what converts to double) and Eigen vectors or
// matrices; for those |actual - expected| is the Euclidean (Frobenius) norm of the
// difference, exactly (actual - expected).norm(), and every component of both and of
// the difference is printed. NaN never passes.
// RBW_COMPARE_NEAR_STRICT is the same with |actual - expected| < tol, for a bound that
// is meant strictly.
#define RBW_COMPARE_NEAR(actual, expected, tol, ...)                                                          \
    do {                                                                                                      \
        if (!::rbw::test::compareNear((actual), (expected), (tol), ::rbw::test::NearBound::AtMost,           \
                                      {#actual, #expected, #tol, __FILE__, __LINE__} __VA_OPT__(, ) __VA_ARGS__)) \
            return;                                                                                           \
    } while (false)
#define RBW_COMPARE_NEAR_STRICT(actual, expected, tol, ...)                                                   \
    do {                                                                                                      \
        if (!::rbw::test::compareNear((actual), (expected), (tol), ::rbw::test::NearBound::Below,            \
                                      {#actual, #expected, #tol, __FILE__, __LINE__} __VA_OPT__(, ) __VA_ARGS__)) \
            return;                                                                                           \
    } while (false)

// What RBW_COMPARE_NEAR asks of the difference: at most the tolerance, or below it.
enum class NearBound { AtMost, Below };

// Where a comparison is written: its three expressions, file and line.
struct NearSite {
    const char* actual;
    const char* expected;
    const char* tol;
    const char* file;
    int line;
};

inline bool withinTolerance(double difference, double tol, NearBound bound)
{
    return bound == NearBound::AtMost ? difference <= tol : difference < tol;   // false for NaN
}

inline QString nearNumber(double x) { return QString::number(x, 'g', 17); }

template <typename Derived>
QString nearNumbers(const Eigen::MatrixBase<Derived>& m)
{
    QStringList parts;
    for (Eigen::Index i = 0; i < m.rows(); ++i) {
        for (Eigen::Index j = 0; j < m.cols(); ++j) parts << nearNumber(double(m(i, j)));
    }
    return QLatin1Char('(') + parts.join(QStringLiteral(", ")) + QLatin1Char(')');
}

// Reports a failed comparison through QTest::qVerify, as QVERIFY2 does; true only when
// the failure was expected (QEXPECT_FAIL with Continue).
inline bool failNear(const QString& actualText, const QString& expectedText, const QString& differenceText,
                     double difference, double tol, NearBound bound, const NearSite& at, const QString& context)
{
    const char* op = bound == NearBound::AtMost ? "<=" : "<";
    const QString statement = QStringLiteral("|%1 - (%2)| %3 %4").arg(QString::fromUtf8(at.actual),
                                                                       QString::fromUtf8(at.expected),
                                                                       QString::fromUtf8(op), QString::fromUtf8(at.tol));
    const QString message = QStringLiteral("|difference| = %1, tolerance %2%3\n"
                                           "   Actual   (%4): %5\n"
                                           "   Expected (%6): %7\n"
                                           "   Difference: %8")
                                .arg(nearNumber(difference), nearNumber(tol),
                                     context.isEmpty() ? QString() : QStringLiteral("; ") + context,
                                     QString::fromUtf8(at.actual), actualText, QString::fromUtf8(at.expected),
                                     expectedText, differenceText);
    return QTest::qVerify(false, qPrintable(statement), qPrintable(message), at.file, at.line);
}

inline bool compareNear(double actual, double expected, double tol, NearBound bound, const NearSite& at,
                        const QString& context = {})
{
    const double difference = std::abs(actual - expected);
    if (withinTolerance(difference, tol, bound)) return true;
    return failNear(nearNumber(actual), nearNumber(expected), nearNumber(actual - expected), difference, tol, bound,
                    at, context);
}

template <typename A, typename B>
bool compareNear(const Eigen::MatrixBase<A>& actual, const Eigen::MatrixBase<B>& expected, double tol, NearBound bound,
                 const NearSite& at, const QString& context = {})
{
    const double difference = (actual - expected).norm();
    if (withinTolerance(difference, tol, bound)) return true;
    return failNear(nearNumbers(actual), nearNumbers(expected), nearNumbers(actual - expected), difference, tol, bound,
                    at, context);
}

// A body definition for tests: a box with its initial state (world frame).
inline rbw::BodyDef boxDef(const char* name, const Vec3& size, double mass, const Vec3& x0,
                           const Quat& q0 = Quat::Identity(), const Vec3& v0 = Vec3::Zero(),
                           const Vec3& omega0 = Vec3::Zero())
{
    rbw::BodyDef b;
    b.name = name;
    b.size = size;
    b.mass = mass;
    b.x0_W = x0;
    b.q0_WB = q0;
    b.v0_W = v0;
    b.omega0_W = omega0;
    return b;
}

// An oriented box: centre, rotation (body axes as columns), half extents.
inline BoxPose box(const Vec3& c, const Mat3& R, const Vec3& h)
{
    BoxPose b;
    b.c_W = c;
    b.R_WB = R;
    b.halfExtents = h;
    return b;
}

// What one run of rbw returned.
struct RbwRun {
    int exitCode = -1;
    QByteArray out;
    QString err;
};

inline RbwRun runRbw(const QStringList& args)
{
    QProcess p;
    p.start(QStringLiteral(RBW_CLI_PATH), args);
    p.waitForFinished(120000);
    return RbwRun{p.exitCode(), p.readAllStandardOutput(), QString::fromUtf8(p.readAllStandardError())};
}

} // namespace rbw::test
