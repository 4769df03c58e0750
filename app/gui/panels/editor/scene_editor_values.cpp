#include "app/gui/panels/editor/scene_editor_model.h"

#include "app/gui/panels/editor/scene_editor_fields.h"

#include <cmath>

// The values of the editor's rows: each scene-file key's field of the SceneDef as
// text (valueOf), read back from text (setValue) and the choices it offers (optionsOf).

namespace rbw {

using namespace editorfields;
using K = sceneformat::Key;

namespace {

const QString kTrue = QStringLiteral("true");
const QString kFalse = QStringLiteral("false");

// A word of an enumeration typed into a choice, or false with the loader's message
// ("must be \"course\" or \"manifold\", got \"soft\""); `notSet`, when given, is the
// choice that leaves the key out.
template <typename E>
bool readWord(const QString& text, sceneformat::Choices choices, E* out, QString* error, const QString& notSet = {})
{
    if (const std::optional<E> e = sceneformat::fromWord<E>(text)) {
        *out = *e;
        return true;
    }
    *error = QStringLiteral("must be %1, got %2").arg(sceneformat::choiceText(sceneformat::words(choices), notSet), quoted(text));
    return false;
}

} // namespace

QStringList SceneEditorModel::optionsOf(int group, const Field& field) const
{
    const sceneformat::KeyRow& row = sceneformat::row(field.key);
    if (row.type == sceneformat::Type::BodyRef || (row.type == sceneformat::Type::NamePair && field.index == 0)) {
        return bodyNames();
    }
    if (row.type == sceneformat::Type::NamePair) {
        QStringList names = bodyNames();
        for (const PlaneDef& p : scene_.planes) names << QString::fromStdString(p.name);
        return names;
    }
    if (field.key == K::Sleep) return QStringList{kDefault, kTrue, kFalse};
    if (row.choices == sceneformat::Choices::None) return QStringList();
    // A body's own integrator and convention may be the scene's; a manifold key the model's default.
    QStringList names;
    if (group == Bodies) names << kScenes;
    else if (!*row.fallback) names << kDefault;
    return names + sceneformat::words(row.choices);
}

QVariant SceneEditorModel::valueOf(int group, int element, const Field& field, int role) const
{
    const K k = field.key;
    if (isCheckBox(field)) {
        bool on = false;
        if (group == Settings) on = k == K::BoxCollisions ? scene_.boxCollisions : scene_.positionCorrection;
        if (group == Bodies) on = k == K::BodyFixed ? scene_.bodies[element].fixed : scene_.bodies[element].angularResponse;
        if (group == Torques) on = k == K::TorqueSwitchable ? scene_.torques[element].switchable
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
        if (k == K::Name) return QString::fromStdString(s.name);
        if (k == K::Description) return QString::fromStdString(s.description);
        if (k == K::Dt) return num(s.dt);
        if (k == K::Steps) return QString::number(s.steps);
        if (k == K::Integrator) return QString::fromStdString(s.integrator);
        if (k == K::InertiaConvention) return sceneformat::word(s.inertiaConvention);
        if (k == K::Gravity) return vecText(s.g_W);
        if (k == K::Restitution) return num(s.restitution);
        if (k == K::RestitutionThreshold) return num(s.restitutionThreshold);
        if (k == K::Friction) return num(s.friction);
        if (k == K::PlaneContacts) return sceneformat::word(s.planeContacts);
        if (k == K::EnergyJumpFactor) return num(s.energyJumpFactor);
        if (k == K::EnergyJumpFloor) return num(s.energyJumpFloor);
        if (k == K::ContactModel) return sceneformat::word(s.contactModel);
        if (k == K::SolverIterations) return s.solverIterations ? QString::number(*s.solverIterations) : (display ? kDefault : QString());
        if (k == K::Sleep) return s.sleep ? (*s.sleep ? kTrue : kFalse) : kDefault;
        if (k == K::PositionFix) return s.positionFix ? sceneformat::word(*s.positionFix) : kDefault;
        if (k == K::Solver) return s.solver ? sceneformat::word(*s.solver) : kDefault;
        if (k == K::Substeps) return s.substeps ? QString::number(*s.substeps) : (display ? kDefault : QString());
        break;
    case Bodies: {
        const BodyDef& b = s.bodies[element];
        if (k == K::BodyName) return QString::fromStdString(b.name);
        if (k == K::BodySize) return vecText(b.size);
        if (k == K::BodyMass) return b.fixed ? (display ? tr("(fixed: none)") : QString()) : num(b.mass);
        if (k == K::BodyPosition) return vecText(b.x0_W);
        if (k == K::BodyOrientation) {
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
        if (k == K::BodyLinearVelocity) return vecText(b.v0_W);
        if (k == K::BodyAngularVelocity) return vecText(b.omega0_W);
        if (k == K::BodyIntegrator) return b.integrator.empty() ? kScenes : QString::fromStdString(b.integrator);
        if (k == K::BodyInertiaConvention) return b.inertiaConvention ? sceneformat::word(*b.inertiaConvention) : kScenes;
        break;
    }
    case Forces: {
        const ForceDef& f = s.forces[element];
        if (k == K::ForceBody) return bodyRef(f.body, f.bodyName);
        if (k == K::ForcePoint) return vecText(f.p_W);
        if (k == K::ForceForce) return vecText(f.f_W);
        if (k == K::ForceFromStep) return QString::number(f.fromStep);
        if (k == K::ForceToStep) return QString::number(f.toStep);
        break;
    }
    case Torques: {
        const TorqueDef& t = s.torques[element];
        if (k == K::TorqueBody) return bodyRef(t.body, t.bodyName);
        if (k == K::TorqueTorque) return vecText(t.q_W);
        if (k == K::TorqueFromStep) return QString::number(t.fromStep);
        if (k == K::TorqueToStep) return t.toStep == kForever ? (display ? kNever : QString()) : QString::number(t.toStep);
        break;
    }
    case Probes: {
        const ProbeDef& p = s.probes[element];
        if (k == K::ProbeBody) return bodyRef(p.body, p.bodyName);
        if (k == K::ProbePoint) return vecText(p.p0_W);
        break;
    }
    case Planes: {
        const PlaneDef& p = s.planes[element];
        if (k == K::PlaneName) return QString::fromStdString(p.name);
        if (k == K::PlanePoint) return vecText(p.point_W);
        if (k == K::PlaneNormal) return vecText(p.n_W);
        break;
    }
    case Pairs: {
        const PairOverride& p = s.pairs[element];
        if ((k == K::PairBodies && field.index == 0)) return bodyRef(p.bodyA, p.nameA);
        if ((k == K::PairBodies && field.index == 1)) {
            if (p.bodyB >= 0) return bodyRef(p.bodyB, p.nameB);
            if (p.planeB >= 0 && p.planeB < static_cast<int>(s.planes.size())) return QString::fromStdString(s.planes[p.planeB].name);
            return QString::fromStdString(p.nameB);
        }
        if (k == K::PairRestitution) return optional(p.restitution);
        if (k == K::PairFriction) return optional(p.friction);
        break;
    }
    default: break;
    }
    return {};
}

bool SceneEditorModel::setValue(int group, int element, const Field& field, const QVariant& value, QString* error)
{
    const K k = field.key;
    SceneDef& s = scene_;
    const QString text = value.toString();
    double x = 0;
    long n = 0;
    Vec3 v;
    auto bodyIndex = [&](const QString& name) { return s.bodyIndex(name.toStdString()); };
    switch (group) {
    case Settings:
        if (k == K::Name) { s.name = text.toStdString(); return true; }
        if (k == K::Description) { s.description = text.toStdString(); return true; }
        if (k == K::Dt) { if (!parseNumber(text, &x, error)) return false; s.dt = x; return true; }
        if (k == K::Steps) { if (!parseWhole(text, &n, error)) return false; s.steps = n; return true; }
        if (k == K::Integrator) { s.integrator = text.trimmed().toStdString(); return true; }
        if (k == K::InertiaConvention) {
            return readWord(text, sceneformat::Choices::InertiaConvention, &s.inertiaConvention, error);
        }
        if (k == K::Gravity) { if (!parseVec(text, &v, error)) return false; s.g_W = v; return true; }
        if (k == K::BoxCollisions) { s.boxCollisions = value.toBool(); return true; }
        if (k == K::PositionCorrection) { s.positionCorrection = value.toBool(); return true; }
        if (k == K::Restitution) { if (!parseNumber(text, &x, error)) return false; s.restitution = x; return true; }
        if (k == K::RestitutionThreshold) {
            if (!parseNumber(text, &x, error)) return false;
            s.restitutionThreshold = x;
            return true;
        }
        if (k == K::Friction) { if (!parseNumber(text, &x, error)) return false; s.friction = x; return true; }
        if (k == K::PlaneContacts) {
            return readWord(text, sceneformat::Choices::PlaneContacts, &s.planeContacts, error);
        }
        if (k == K::EnergyJumpFactor) { if (!parseNumber(text, &x, error)) return false; s.energyJumpFactor = x; return true; }
        if (k == K::EnergyJumpFloor) { if (!parseNumber(text, &x, error)) return false; s.energyJumpFloor = x; return true; }
        if (k == K::ContactModel) {
            return readWord(text, sceneformat::Choices::ContactModel, &s.contactModel, error);
        }
        if (k == K::SolverIterations) {
            if (text.trimmed().isEmpty() || text.trimmed() == kDefault) { s.solverIterations.reset(); return true; }
            if (!parseWhole(text, &n, error)) return false;
            s.solverIterations = n;
            return true;
        }
        if (k == K::Sleep) {
            if (text == kDefault) s.sleep.reset();
            else if (text == kTrue || text == kFalse) s.sleep = text == kTrue;
            else { *error = QStringLiteral("must be true, false or %1, got %2").arg(kDefault, quoted(text)); return false; }
            return true;
        }
        if (k == K::PositionFix) {
            if (text == kDefault) {
                s.positionFix.reset();
                return true;
            }
            PositionFix fix = PositionFix::Ngs;
            if (!readWord(text, sceneformat::Choices::PositionFix, &fix, error, kDefault)) return false;
            s.positionFix = fix;
            return true;
        }
        if (k == K::Solver) {
            if (text == kDefault) {
                s.solver.reset();
                return true;
            }
            ManifoldSolver solver = ManifoldSolver::SequentialImpulses;
            if (!readWord(text, sceneformat::Choices::ManifoldSolver, &solver, error, kDefault)) return false;
            s.solver = solver;
            return true;
        }
        if (k == K::Substeps) {
            if (text.trimmed().isEmpty() || text.trimmed() == kDefault) { s.substeps.reset(); return true; }
            if (!parseWhole(text, &n, error)) return false;
            s.substeps = n;
            return true;
        }
        break;
    case Bodies: {
        BodyDef& b = s.bodies[element];
        if (k == K::BodyName) { b.name = text.toStdString(); return true; }
        if (k == K::BodySize) { if (!parseVec(text, &v, error)) return false; b.size = v; return true; }
        if (k == K::BodyMass) { if (!parseNumber(text, &x, error)) return false; b.mass = x; return true; }
        if (k == K::BodyFixed) { b.fixed = value.toBool(); return true; }
        if (k == K::BodyAngularResponse) { b.angularResponse = value.toBool(); return true; }
        if (k == K::BodyPosition) { if (!parseVec(text, &v, error)) return false; b.x0_W = v; return true; }
        if (k == K::BodyLinearVelocity) { if (!parseVec(text, &v, error)) return false; b.v0_W = v; return true; }
        if (k == K::BodyAngularVelocity) { if (!parseVec(text, &v, error)) return false; b.omega0_W = v; return true; }
        if (k == K::BodyOrientation) {
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
        if (k == K::BodyIntegrator) { b.integrator = text == kScenes ? std::string() : text.trimmed().toStdString(); return true; }
        if (k == K::BodyInertiaConvention) {
            if (text == kScenes) {
                b.inertiaConvention.reset();
                return true;
            }
            InertiaConvention c = InertiaConvention::Standard;
            if (!readWord(text, sceneformat::Choices::InertiaConvention, &c, error, kScenes)) return false;
            b.inertiaConvention = c;
            return true;
        }
        break;
    }
    case Forces: {
        ForceDef& f = s.forces[element];
        if (k == K::ForceBody) { f.bodyName = text.toStdString(); f.body = bodyIndex(text); return true; }
        if (k == K::ForcePoint) { if (!parseVec(text, &v, error)) return false; f.p_W = v; return true; }
        if (k == K::ForceForce) { if (!parseVec(text, &v, error)) return false; f.f_W = v; return true; }
        if (k == K::ForceFromStep) { if (!parseWhole(text, &n, error)) return false; f.fromStep = n; return true; }
        if (k == K::ForceToStep) { if (!parseWhole(text, &n, error)) return false; f.toStep = n; return true; }
        break;
    }
    case Torques: {
        TorqueDef& t = s.torques[element];
        if (k == K::TorqueBody) { t.bodyName = text.toStdString(); t.body = bodyIndex(text); return true; }
        if (k == K::TorqueTorque) { if (!parseVec(text, &v, error)) return false; t.q_W = v; return true; }
        if (k == K::TorqueFromStep) { if (!parseWhole(text, &n, error)) return false; t.fromStep = n; return true; }
        if (k == K::TorqueToStep) {
            if (text.trimmed().isEmpty() || text.trimmed() == kNever) { t.toStep = kForever; return true; }
            if (!parseWhole(text, &n, error)) return false;
            t.toStep = n;
            return true;
        }
        if (k == K::TorqueSwitchable) { t.switchable = value.toBool(); return true; }
        if (k == K::TorqueEnabled) { t.enabledAtStart = value.toBool(); return true; }
        break;
    }
    case Probes: {
        ProbeDef& p = s.probes[element];
        if (k == K::ProbeBody) { p.bodyName = text.toStdString(); p.body = bodyIndex(text); return true; }
        if (k == K::ProbePoint) { if (!parseVec(text, &v, error)) return false; p.p0_W = v; return true; }
        break;
    }
    case Planes: {
        PlaneDef& p = s.planes[element];
        if (k == K::PlaneName) { p.name = text.toStdString(); return true; }
        if (k == K::PlanePoint) { if (!parseVec(text, &v, error)) return false; p.point_W = v; return true; }
        if (k == K::PlaneNormal) {
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
        if ((k == K::PairBodies && field.index == 0)) { p.nameA = text.toStdString(); p.bodyA = bodyIndex(text); return true; }
        if ((k == K::PairBodies && field.index == 1)) {
            p.nameB = text.toStdString();
            p.bodyB = bodyIndex(text);
            p.planeB = p.bodyB < 0 ? s.planeIndex(text.toStdString()) : -1;
            return true;
        }
        if (k == K::PairRestitution || k == K::PairFriction) {
            std::optional<double>& target = k == K::PairRestitution ? p.restitution : p.friction;
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
