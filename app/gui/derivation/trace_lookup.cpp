#include "app/gui/derivation/trace_lookup.h"

#include "physics/quantities.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace rbw {

const std::vector<const QuantityInfo*>& quantityCatalogue()
{
    static const std::vector<const QuantityInfo*> all = {
        &q::gravity_force, &q::applied_force, &q::application_point, &q::lever_arm, &q::force,
        &q::applied_torque, &q::torque,
        &q::position, &q::linear_velocity, &q::orientation, &q::angular_momentum, &q::inertia_body,
        &q::inverse_inertia_body, &q::rotation_matrix, &q::inverse_inertia_world, &q::angular_velocity,
        &q::probe_position, &q::point_velocity,
        &q::pairs_tested, &q::pairs_overlapping, &q::contact_point, &q::contact_normal, &q::contact_depth,
        &q::x_a, &q::x_b, &q::velocity_a, &q::velocity_b, &q::relative_velocity, &q::normal_velocity,
        &q::restitution, &q::numerator, &q::inv_mass_a, &q::inv_mass_b, &q::rotational_a, &q::rotational_b,
        &q::denominator, &q::impulse, &q::friction_impulse, &q::friction_coefficient, &q::sliding,
        &q::delta_v_a, &q::delta_v_b, &q::delta_L_a, &q::delta_L_b, &q::linear_velocity_a,
        &q::linear_velocity_b, &q::angular_momentum_a, &q::angular_momentum_b, &q::angular_velocity_a,
        &q::angular_velocity_b, &q::kinetic_energy_before, &q::kinetic_energy_after,
        &q::correction_a, &q::correction_b,
    };
    return all;
}

const QuantityInfo* catalogueInfo(std::string_view id)
{
    for (const QuantityInfo* info : quantityCatalogue()) {
        if (id == info->id) return info;
    }
    return nullptr;
}

IndexKind indexKindOf(std::string_view id)
{
    if (id == "applied_force" || id == "application_point" || id == "lever_arm") return IndexKind::Force;
    if (id == "applied_torque") return IndexKind::Torque;
    if (id == "pairs_tested" || id == "pairs_overlapping") return IndexKind::None;
    const QuantityInfo* info = catalogueInfo(id);
    if (info == nullptr) return IndexKind::None;
    switch (info->stage) {
    case Stage::Probes: return IndexKind::Probe;
    case Stage::Collision: return IndexKind::Contact;
    case Stage::Correction: return IndexKind::Correction;
    case Stage::Forces:
    case Stage::Integration: return IndexKind::None;
    }
    return IndexKind::None;
}

IndexKind indexKindFromName(const QString& name)
{
    if (name == QLatin1String("force")) return IndexKind::Force;
    if (name == QLatin1String("torque")) return IndexKind::Torque;
    if (name == QLatin1String("probe")) return IndexKind::Probe;
    if (name == QLatin1String("contact")) return IndexKind::Contact;
    if (name == QLatin1String("correction")) return IndexKind::Correction;
    return IndexKind::None;
}

QString indexKindName(IndexKind kind)
{
    switch (kind) {
    case IndexKind::Force: return QStringLiteral("force");
    case IndexKind::Torque: return QStringLiteral("torque");
    case IndexKind::Probe: return QStringLiteral("probe");
    case IndexKind::Contact: return QStringLiteral("contact");
    case IndexKind::Correction: return QStringLiteral("correction");
    case IndexKind::None: break;
    }
    return QString();
}

int LookupContext::indexFor(IndexKind kind) const
{
    switch (kind) {
    case IndexKind::Force: return force;
    case IndexKind::Torque: return torque;
    case IndexKind::Probe: return probe;
    case IndexKind::Contact: return contact;
    case IndexKind::Correction: return correction;
    case IndexKind::None: break;
    }
    return -1;
}

void LookupContext::setIndex(IndexKind kind, int index)
{
    switch (kind) {
    case IndexKind::Force: force = index; break;
    case IndexKind::Torque: torque = index; break;
    case IndexKind::Probe: probe = index; break;
    case IndexKind::Contact: contact = index; break;
    case IndexKind::Correction: correction = index; break;
    case IndexKind::None: break;
    }
}

LookupResult lookupEntry(const StepTrace& trace, std::string_view id, const LookupContext& context,
                         int explicitIndex, int explicitBody)
{
    const IndexKind kind = indexKindOf(id);
    const bool anyIndex = explicitIndex < 0 && kind != IndexKind::None && context.indexFor(kind) < 0;
    const int index = explicitIndex >= 0 ? explicitIndex : (kind == IndexKind::None ? -1 : context.indexFor(kind));
    const bool anyBody =
        explicitBody < 0 && (kind == IndexKind::Contact || kind == IndexKind::Correction || context.body < 0);
    const int body = explicitBody >= 0 ? explicitBody : context.body;

    std::vector<const TraceEntry*> hits;
    for (const TraceEntry& e : trace.entries) {
        if (id != e.info->id) continue;
        if (!anyIndex && e.index != index) continue;
        if (!anyBody && e.body != body) continue;
        hits.push_back(&e);
    }
    LookupResult r;
    if (hits.size() == 1) {
        r.entry = hits.front();
    } else if (hits.empty()) {
        r.missing = true;
        r.problem = QStringLiteral("not computed in this step");
    } else if (anyIndex) {
        r.problem = QStringLiteral("ambiguous: there are several, choose one with [i] or @foreach %1")
                        .arg(indexKindName(kind));
    } else {
        r.problem = QStringLiteral("ambiguous: several bodies have it, choose one with @name or @foreach body");
    }
    return r;
}

const TraceEntry* valueBeforeContact(const StepTrace& trace, std::string_view id, int body, int contact)
{
    if (body < 0) return nullptr;
    const std::string base(id);
    const std::string a = base + "_a";
    const std::string b = base + "_b";
    const TraceEntry* latest = nullptr;
    for (const TraceEntry& e : trace.entries) {
        const bool collision = e.info->stage == Stage::Collision;
        if (collision && e.index >= contact) break;   // contact `contact` starts here
        if (e.body != body) continue;
        const std::string_view eid = e.info->id;
        if ((!collision && eid == base) || (collision && (eid == a || eid == b))) latest = &e;
    }
    return latest;
}

std::vector<int> indicesOf(const StepTrace& trace, std::string_view id, int body)
{
    std::vector<int> out;
    for (const TraceEntry& e : trace.entries) {
        if (id != e.info->id || e.index < 0) continue;
        if (body >= 0 && e.body != body) continue;
        if (std::find(out.begin(), out.end(), e.index) == out.end()) out.push_back(e.index);
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<int> bodiesInTrace(const StepTrace& trace)
{
    std::vector<int> out;
    for (const TraceEntry& e : trace.entries) {
        if (e.body >= 0 && std::find(out.begin(), out.end(), e.body) == out.end()) out.push_back(e.body);
    }
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace rbw

namespace rbw {
bool isFiniteValue(const TraceValue& value)
{
    return std::visit(
        [](const auto& v) -> bool {
            using T = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<T, double>) {
                return std::isfinite(v);
            } else if constexpr (std::is_same_v<T, Quat>) {
                return v.coeffs().allFinite();
            } else {
                return v.allFinite();
            }
        },
        value);
}
} // namespace rbw
