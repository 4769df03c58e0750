// Helpers shared by the tests: compare trace values against hand-derived numbers,
// and run the rbw command line.
#pragma once

#include "app/scene/scene_loader.h"
#include "physics/engine/collision/contact.h"
#include "physics/engine/trace.h"

#include <QList>
#include <QProcess>
#include <QString>
#include <QStringList>

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
