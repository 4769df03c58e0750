#include "app/gui/panels/editor/scene_editor_fields.h"

#include "app/gui/panels/editor/scene_editor_model.h"

#include <QLocale>
#include <QRegularExpression>

#include <cmath>

namespace rbw::editorfields {

QString positionFixText(PositionFix f)
{
    return f == PositionFix::Ngs ? QStringLiteral("ngs") : f == PositionFix::Baumgarte ? QStringLiteral("baumgarte")
                                                                                        : QStringLiteral("none");
}

const QHash<QString, KeyInfo>& keyInfo()
{
    static const QHash<QString, KeyInfo> info{
        {"name", {"", "title of the scene; unique name of a body or plane"}},
        {"description", {"", "one-line summary"}},
        {"dt", {"s", "time step h; > 0"}},
        {"steps", {"", "steps `rbw run` takes; 0 … 10^9"}},
        {"integrator", {"", "integration method (rbw integrators)"}},
        {"inertia_convention", {"", "standard: I⁻¹ = R I0⁻¹ Rᵀ; course-template: Rᵀ I0⁻¹ R"}},
        {"gravity", {"m/s²", "gravitational acceleration g, world frame"}},
        {"box_collisions", {"", "boxes collide with each other"}},
        {"restitution", {"", "coefficient of restitution c, 0 … 1"}},
        {"restitution_threshold", {"m/s", "approaches slower than this do not bounce; 0 is off"}},
        {"friction", {"", "Coulomb friction coefficient μ ≥ 0"}},
        {"position_correction", {"", "push penetrating bodies apart after the impulses"}},
        {"plane_contacts", {"", "per-point: one impulse per corner; average: one at their mean"}},
        {"energy_jump.factor", {"", "blow-up bound: 0 (off) or ≥ 1"}},
        {"energy_jump.floor", {"J", "blow-up bound floor, ≥ 0"}},
        {"size", {"m", "edge lengths a, b, c along body x, y, z"}},
        {"mass", {"kg", "M > 0 (a fixed body has none)"}},
        {"fixed", {"", "infinite mass: never moves"}},
        {"position", {"m", "centre of mass at t = 0"}},
        {"orientation", {"", "unit quaternion w, x, y, z (body → world) at t = 0; normalised"}},
        {"linear_velocity", {"m/s", "v at t = 0"}},
        {"angular_velocity", {"rad/s", "ω at t = 0, world frame"}},
        {"angular_response", {"", "off: in collisions a particle (L never changes)"}},
        {"body", {"", "the body it acts on"}},
        {"point", {"m", "world point at t = 0"}},
        {"force", {"N", "force f, world frame"}},
        {"torque", {"N m", "torque q, world frame"}},
        {"from_step", {"", "first step in which it acts"}},
        {"to_step", {"", "first step in which it no longer acts"}},
        {"switchable", {"", "the K key turns it off and on"}},
        {"enabled", {"", "on at the start"}},
        {"normal", {"", "towards the free side; normalised"}},
        {"bodies[0]", {"", "a body"}},
        {"contact_model", {"", "course: one impulse per contact point; manifold: manifolds and an iterative solver"}},
        {"solver_iterations", {"", "manifold model: velocity iterations (empty: the default)"}},
        {"sleep", {"", "manifold model: bodies at rest sleep"}},
        {"position_fix", {"", "manifold model: how overlap is removed"}},
        {"bodies[1]", {"", "a body or a plane"}},
    };
    return info;
}

QString num(double x) { return QString::number(x, 'g', QLocale::FloatingPointShortest); }

QString vecText(const Vec3& v) { return QStringLiteral("%1, %2, %3").arg(num(v.x()), num(v.y()), num(v.z())); }

QString convention(InertiaConvention c)
{
    return c == InertiaConvention::CourseTemplate ? QStringLiteral("course-template") : QStringLiteral("standard");
}

QString quoted(const QString& text) { return QStringLiteral("\"%1\"").arg(text.left(40)); }

// Numbers from "1, 2, 3", "[1 2 3]" or "1;2;3" (C locale: a point is the decimal sign).
bool parseNumbers(const QString& text, int count, QList<double>* out, QString* error)
{
    QString t = text.trimmed();
    if (t.startsWith('[') && t.endsWith(']')) t = t.mid(1, t.size() - 2);
    static const QRegularExpression separator(QStringLiteral("[,;\\s]+"));
    const QStringList parts = t.split(separator, Qt::SkipEmptyParts);
    if (parts.size() != count) {
        *error = QStringLiteral("must be %1 numbers separated by commas, got %2").arg(count).arg(quoted(text));
        return false;
    }
    for (const QString& p : parts) {
        bool ok = false;
        const double x = QLocale::c().toDouble(p, &ok);
        if (!ok || !std::isfinite(x)) {
            *error = QStringLiteral("must be %1 finite numbers, got %2").arg(count).arg(quoted(p));
            return false;
        }
        out->append(x);
    }
    return true;
}

bool parseNumber(const QString& text, double* x, QString* error)
{
    bool ok = false;
    *x = QLocale::c().toDouble(text.trimmed(), &ok);
    if (!ok || !std::isfinite(*x)) {
        *error = QStringLiteral("must be a finite number, got %1").arg(quoted(text));
        return false;
    }
    return true;
}

// As the loader reads a whole number: no fraction, at most 9e15 in size.
bool parseWhole(const QString& text, long* n, QString* error)
{
    double x = 0;
    if (!parseNumber(text, &x, error)) return false;
    if (x != std::floor(x) || std::abs(x) > 9.0e15) {
        *error = QStringLiteral("must be a whole number from -9e15 to 9e15, got %1").arg(num(x));
        return false;
    }
    *n = static_cast<long>(x);
    return true;
}

bool parseVec(const QString& text, Vec3* v, QString* error)
{
    QList<double> n;
    if (!parseNumbers(text, 3, &n, error)) return false;
    *v = Vec3(n[0], n[1], n[2]);
    return true;
}

bool isBool(int group, const QString& key)
{
    if (group == SceneEditorModel::Settings) return key == "box_collisions" || key == "position_correction";
    if (group == SceneEditorModel::Bodies) return key == "fixed" || key == "angular_response";
    if (group == SceneEditorModel::Torques) return key == "switchable" || key == "enabled";
    return false;
}

} // namespace rbw::editorfields
