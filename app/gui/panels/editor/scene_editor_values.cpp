#include "app/gui/panels/editor/scene_editor_model.h"

#include "app/gui/panels/editor/scene_editor_fields.h"
#include "physics/engine/integrator_registry.h"

#include <cmath>

// The values of the editor's rows: each scene-file key's field of the SceneDef as
// text (valueOf), read back from text (setValue) and the choices it offers (optionsOf).

namespace rbw {

using namespace editorfields;

QStringList SceneEditorModel::optionsOf(int group, const QString& key) const
{
    if (key == "integrator") {
        QStringList names;
        if (group == Bodies) names << kScenes;
        for (const IntegratorInfo& i : integratorCatalogue()) names << QString::fromLatin1(i.name);
        return names;
    }
    if (key == "inertia_convention") {
        return group == Bodies ? QStringList{kScenes, "standard", "course-template"}
                               : QStringList{"standard", "course-template"};
    }
    if (key == "plane_contacts") return QStringList{"per-point", "average"};
    if (key == "contact_model") return QStringList{"course", "manifold"};
    if (key == "sleep") return QStringList{kDefault, "true", "false"};
    if (key == "position_fix") return QStringList{kDefault, "ngs", "baumgarte", "none"};
    if (key == "body" || key == "bodies[0]") return bodyNames();
    if (key == "bodies[1]") {
        QStringList names = bodyNames();
        for (const PlaneDef& p : scene_.planes) names << QString::fromStdString(p.name);
        return names;
    }
    return QStringList();
}

QVariant SceneEditorModel::valueOf(int group, int element, const QString& key, int role) const
{
    if (isBool(group, key)) {
        bool on = false;
        if (group == Settings) on = key == "box_collisions" ? scene_.boxCollisions : scene_.positionCorrection;
        if (group == Bodies) on = key == "fixed" ? scene_.bodies[element].fixed : scene_.bodies[element].angularResponse;
        if (group == Torques) on = key == "switchable" ? scene_.torques[element].switchable
                                                       : scene_.torques[element].enabledAtStart;
        if (role == Qt::CheckStateRole) return on ? Qt::Checked : Qt::Unchecked;
        if (role == Qt::DisplayRole) return on ? tr("true") : tr("false");
        return {};
    }
    if (role != Qt::DisplayRole && role != Qt::EditRole) return {};
    const bool display = role == Qt::DisplayRole;
    auto bodyRef = [&](int i, const std::string& given) {
        return i >= 0 && i < static_cast<int>(scene_.bodies.size()) ? QString::fromStdString(scene_.bodies[i].name)
                                                                     : QString::fromStdString(given);
    };
    auto optional = [&](const std::optional<double>& x) { return x ? num(*x) : (display ? kScenes : QString()); };
    const SceneDef& s = scene_;
    switch (group) {
    case Settings:
        if (key == "name") return QString::fromStdString(s.name);
        if (key == "description") return QString::fromStdString(s.description);
        if (key == "dt") return num(s.dt);
        if (key == "steps") return QString::number(s.steps);
        if (key == "integrator") return QString::fromStdString(s.integrator);
        if (key == "inertia_convention") return convention(s.inertiaConvention);
        if (key == "gravity") return vecText(s.g_W);
        if (key == "restitution") return num(s.restitution);
        if (key == "restitution_threshold") return num(s.restitutionThreshold);
        if (key == "friction") return num(s.friction);
        if (key == "plane_contacts") return s.planeContacts == PlaneContactMode::Average ? QStringLiteral("average") : QStringLiteral("per-point");
        if (key == "energy_jump.factor") return num(s.energyJumpFactor);
        if (key == "energy_jump.floor") return num(s.energyJumpFloor);
        if (key == "contact_model") return s.contactModel == ContactModel::Manifold ? QStringLiteral("manifold") : QStringLiteral("course");
        if (key == "solver_iterations") return s.solverIterations ? QString::number(*s.solverIterations) : (display ? kDefault : QString());
        if (key == "sleep") return s.sleep ? (*s.sleep ? QStringLiteral("true") : QStringLiteral("false")) : kDefault;
        if (key == "position_fix") return s.positionFix ? positionFixText(*s.positionFix) : kDefault;
        break;
    case Bodies: {
        const BodyDef& b = s.bodies[element];
        if (key == "name") return QString::fromStdString(b.name);
        if (key == "size") return vecText(b.size);
        if (key == "mass") return b.fixed ? (display ? tr("(fixed: none)") : QString()) : num(b.mass);
        if (key == "position") return vecText(b.x0_W);
        if (key == "orientation") {
            const QString q = QStringLiteral("%1, %2, %3, %4").arg(num(b.q0_WB.w()), num(b.q0_WB.x()), num(b.q0_WB.y()), num(b.q0_WB.z()));
            if (!display) return q;
            // For reading: the same rotation as an angle about an axis.
            const Eigen::AngleAxisd aa(b.q0_WB);
            if (aa.angle() == 0.0) return tr("no rotation · q = %1").arg(q);
            const Vec3& n = aa.axis();
            return tr("%2° about (%3, %4, %5) · q = %1")
                .arg(q, QString::number(aa.angle() * 180.0 / 3.14159265358979323846, 'g', 4), QString::number(n.x(), 'g', 3),
                     QString::number(n.y(), 'g', 3), QString::number(n.z(), 'g', 3));
        }
        if (key == "linear_velocity") return vecText(b.v0_W);
        if (key == "angular_velocity") return vecText(b.omega0_W);
        if (key == "integrator") return b.integrator.empty() ? kScenes : QString::fromStdString(b.integrator);
        if (key == "inertia_convention") return b.inertiaConvention ? convention(*b.inertiaConvention) : kScenes;
        break;
    }
    case Forces: {
        const ForceDef& f = s.forces[element];
        if (key == "body") return bodyRef(f.body, f.bodyName);
        if (key == "point") return vecText(f.p_W);
        if (key == "force") return vecText(f.f_W);
        if (key == "from_step") return QString::number(f.fromStep);
        if (key == "to_step") return QString::number(f.toStep);
        break;
    }
    case Torques: {
        const TorqueDef& t = s.torques[element];
        if (key == "body") return bodyRef(t.body, t.bodyName);
        if (key == "torque") return vecText(t.q_W);
        if (key == "from_step") return QString::number(t.fromStep);
        if (key == "to_step") return t.toStep == kForever ? (display ? kNever : QString()) : QString::number(t.toStep);
        break;
    }
    case Probes: {
        const ProbeDef& p = s.probes[element];
        if (key == "body") return bodyRef(p.body, p.bodyName);
        if (key == "point") return vecText(p.p0_W);
        break;
    }
    case Planes: {
        const PlaneDef& p = s.planes[element];
        if (key == "name") return QString::fromStdString(p.name);
        if (key == "point") return vecText(p.point_W);
        if (key == "normal") return vecText(p.n_W);
        break;
    }
    case Pairs: {
        const PairOverride& p = s.pairs[element];
        if (key == "bodies[0]") return bodyRef(p.bodyA, p.nameA);
        if (key == "bodies[1]") {
            if (p.bodyB >= 0) return bodyRef(p.bodyB, p.nameB);
            if (p.planeB >= 0 && p.planeB < static_cast<int>(s.planes.size())) return QString::fromStdString(s.planes[p.planeB].name);
            return QString::fromStdString(p.nameB);
        }
        if (key == "restitution") return optional(p.restitution);
        if (key == "friction") return optional(p.friction);
        break;
    }
    default: break;
    }
    return {};
}

bool SceneEditorModel::setValue(int group, int element, const QString& key, const QVariant& value, QString* error)
{
    SceneDef& s = scene_;
    const QString text = value.toString();
    double x = 0;
    long n = 0;
    Vec3 v;
    auto bodyIndex = [&](const QString& name) { return s.bodyIndex(name.toStdString()); };
    switch (group) {
    case Settings:
        if (key == "name") { s.name = text.toStdString(); return true; }
        if (key == "description") { s.description = text.toStdString(); return true; }
        if (key == "dt") { if (!parseNumber(text, &x, error)) return false; s.dt = x; return true; }
        if (key == "steps") { if (!parseWhole(text, &n, error)) return false; s.steps = n; return true; }
        if (key == "integrator") { s.integrator = text.trimmed().toStdString(); return true; }
        if (key == "inertia_convention") {
            if (text != "standard" && text != "course-template") {
                *error = QStringLiteral("must be \"standard\" or \"course-template\", got %1").arg(quoted(text));
                return false;
            }
            s.inertiaConvention = text == "standard" ? InertiaConvention::Standard : InertiaConvention::CourseTemplate;
            return true;
        }
        if (key == "gravity") { if (!parseVec(text, &v, error)) return false; s.g_W = v; return true; }
        if (key == "box_collisions") { s.boxCollisions = value.toBool(); return true; }
        if (key == "position_correction") { s.positionCorrection = value.toBool(); return true; }
        if (key == "restitution") { if (!parseNumber(text, &x, error)) return false; s.restitution = x; return true; }
        if (key == "restitution_threshold") {
            if (!parseNumber(text, &x, error)) return false;
            s.restitutionThreshold = x;
            return true;
        }
        if (key == "friction") { if (!parseNumber(text, &x, error)) return false; s.friction = x; return true; }
        if (key == "plane_contacts") {
            if (text != "per-point" && text != "average") {
                *error = QStringLiteral("must be \"per-point\" or \"average\", got %1").arg(quoted(text));
                return false;
            }
            s.planeContacts = text == "average" ? PlaneContactMode::Average : PlaneContactMode::PerPoint;
            return true;
        }
        if (key == "energy_jump.factor") { if (!parseNumber(text, &x, error)) return false; s.energyJumpFactor = x; return true; }
        if (key == "energy_jump.floor") { if (!parseNumber(text, &x, error)) return false; s.energyJumpFloor = x; return true; }
        if (key == "contact_model") {
            if (text != "course" && text != "manifold") {
                *error = QStringLiteral("must be \"course\" or \"manifold\", got %1").arg(quoted(text));
                return false;
            }
            s.contactModel = text == "manifold" ? ContactModel::Manifold : ContactModel::Course;
            return true;
        }
        if (key == "solver_iterations") {
            if (text.trimmed().isEmpty() || text.trimmed() == kDefault) { s.solverIterations.reset(); return true; }
            if (!parseWhole(text, &n, error)) return false;
            s.solverIterations = n;
            return true;
        }
        if (key == "sleep") {
            if (text == kDefault) s.sleep.reset();
            else if (text == "true" || text == "false") s.sleep = text == "true";
            else { *error = QStringLiteral("must be true, false or %1, got %2").arg(kDefault, quoted(text)); return false; }
            return true;
        }
        if (key == "position_fix") {
            if (text == kDefault) s.positionFix.reset();
            else if (text == "ngs") s.positionFix = PositionFix::Ngs;
            else if (text == "baumgarte") s.positionFix = PositionFix::Baumgarte;
            else if (text == "none") s.positionFix = PositionFix::None;
            else {
                *error = QStringLiteral("must be \"ngs\", \"baumgarte\", \"none\" or %1, got %2").arg(kDefault, quoted(text));
                return false;
            }
            return true;
        }
        break;
    case Bodies: {
        BodyDef& b = s.bodies[element];
        if (key == "name") { b.name = text.toStdString(); return true; }
        if (key == "size") { if (!parseVec(text, &v, error)) return false; b.size = v; return true; }
        if (key == "mass") { if (!parseNumber(text, &x, error)) return false; b.mass = x; return true; }
        if (key == "fixed") { b.fixed = value.toBool(); return true; }
        if (key == "angular_response") { b.angularResponse = value.toBool(); return true; }
        if (key == "position") { if (!parseVec(text, &v, error)) return false; b.x0_W = v; return true; }
        if (key == "linear_velocity") { if (!parseVec(text, &v, error)) return false; b.v0_W = v; return true; }
        if (key == "angular_velocity") { if (!parseVec(text, &v, error)) return false; b.omega0_W = v; return true; }
        if (key == "orientation") {
            QList<double> q;
            if (!parseNumbers(text, 4, &q, error)) return false;
            const Quat quat(q[0], q[1], q[2], q[3]);
            if (quat.coeffs().isZero(0.0)) { *error = QStringLiteral("must not be the zero quaternion"); return false; }
            if (!std::isfinite(quat.coeffs().squaredNorm())) {
                *error = QStringLiteral("its length overflows, so it cannot be normalised");
                return false;
            }
            b.q0_WB = Quat(normalisedAsLoaded(quat.coeffs()));
            return true;
        }
        if (key == "integrator") { b.integrator = text == kScenes ? std::string() : text.trimmed().toStdString(); return true; }
        if (key == "inertia_convention") {
            if (text == kScenes) b.inertiaConvention.reset();
            else if (text == "standard") b.inertiaConvention = InertiaConvention::Standard;
            else if (text == "course-template") b.inertiaConvention = InertiaConvention::CourseTemplate;
            else {
                *error = QStringLiteral("must be \"standard\", \"course-template\" or %1, got %2").arg(kScenes, quoted(text));
                return false;
            }
            return true;
        }
        break;
    }
    case Forces: {
        ForceDef& f = s.forces[element];
        if (key == "body") { f.bodyName = text.toStdString(); f.body = bodyIndex(text); return true; }
        if (key == "point") { if (!parseVec(text, &v, error)) return false; f.p_W = v; return true; }
        if (key == "force") { if (!parseVec(text, &v, error)) return false; f.f_W = v; return true; }
        if (key == "from_step") { if (!parseWhole(text, &n, error)) return false; f.fromStep = n; return true; }
        if (key == "to_step") { if (!parseWhole(text, &n, error)) return false; f.toStep = n; return true; }
        break;
    }
    case Torques: {
        TorqueDef& t = s.torques[element];
        if (key == "body") { t.bodyName = text.toStdString(); t.body = bodyIndex(text); return true; }
        if (key == "torque") { if (!parseVec(text, &v, error)) return false; t.q_W = v; return true; }
        if (key == "from_step") { if (!parseWhole(text, &n, error)) return false; t.fromStep = n; return true; }
        if (key == "to_step") {
            if (text.trimmed().isEmpty() || text.trimmed() == kNever) { t.toStep = kForever; return true; }
            if (!parseWhole(text, &n, error)) return false;
            t.toStep = n;
            return true;
        }
        if (key == "switchable") { t.switchable = value.toBool(); return true; }
        if (key == "enabled") { t.enabledAtStart = value.toBool(); return true; }
        break;
    }
    case Probes: {
        ProbeDef& p = s.probes[element];
        if (key == "body") { p.bodyName = text.toStdString(); p.body = bodyIndex(text); return true; }
        if (key == "point") { if (!parseVec(text, &v, error)) return false; p.p0_W = v; return true; }
        break;
    }
    case Planes: {
        PlaneDef& p = s.planes[element];
        if (key == "name") { p.name = text.toStdString(); return true; }
        if (key == "point") { if (!parseVec(text, &v, error)) return false; p.point_W = v; return true; }
        if (key == "normal") {
            if (!parseVec(text, &v, error)) return false;
            if (v == Vec3::Zero()) { *error = QStringLiteral("must not be the zero vector"); return false; }
            if (!std::isfinite(v.squaredNorm())) { *error = QStringLiteral("its length overflows"); return false; }
            p.n_W = normalisedAsLoaded(v);
            return true;
        }
        break;
    }
    case Pairs: {
        PairOverride& p = s.pairs[element];
        if (key == "bodies[0]") { p.nameA = text.toStdString(); p.bodyA = bodyIndex(text); return true; }
        if (key == "bodies[1]") {
            p.nameB = text.toStdString();
            p.bodyB = bodyIndex(text);
            p.planeB = p.bodyB < 0 ? s.planeIndex(text.toStdString()) : -1;
            return true;
        }
        if (key == "restitution" || key == "friction") {
            std::optional<double>& target = key == "restitution" ? p.restitution : p.friction;
            if (text.trimmed().isEmpty() || text.trimmed() == kScenes) { target.reset(); return true; }
            if (!parseNumber(text, &x, error)) return false;
            target = x;
            return true;
        }
        break;
    }
    default: break;
    }
    *error = QStringLiteral("cannot be edited");
    return false;
}

} // namespace rbw
