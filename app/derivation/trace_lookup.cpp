#include "app/derivation/trace_lookup.h"

#include "physics/engine/integrator_registry.h"


#include <algorithm>
#include <cmath>
#include <type_traits>

namespace rbw {

IndexKind indexKindOf(std::string_view id)
{
    const QuantityInfo* info = findQuantity(id);
    return info != nullptr ? info->indexKind : IndexKind::None;
}

IndexKind indexKindFromName(const QString& name)
{
    for (IndexKind k : {IndexKind::Force, IndexKind::Torque, IndexKind::Probe, IndexKind::Contact,
                        IndexKind::RkStage, IndexKind::Correction}) {
        if (name == QLatin1String(indexKindName(k))) return k;
    }
    return IndexKind::None;
}

int LookupContext::indexFor(IndexKind kind) const
{
    switch (kind) {
    case IndexKind::Force: return force;
    case IndexKind::Torque: return torque;
    case IndexKind::Probe: return probe;
    case IndexKind::Contact: return contact;
    case IndexKind::Correction: return correction;
    case IndexKind::RkStage: return stage;
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
    case IndexKind::RkStage: stage = index; break;
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
                        .arg(QLatin1String(indexKindName(kind)));
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
QString tracedIntegrator(const StepTrace& trace, int body)
{
    // The longest name found: an integrator built on another's code
    // (rotation-matrix-orthonormalised on rotation-matrix) also records entries from the
    // other's file.
    static constexpr std::string_view folder = "physics/engine/integrators/";
    std::string best;
    for (const TraceEntry& e : trace.entries) {
        if (e.body != body || e.info->stage != Stage::Integration) continue;
        const std::string_view file = sourceFile(e);
        const std::size_t at = file.rfind(folder);
        if (at == std::string_view::npos || !file.ends_with(".cpp")) continue;
        std::string name(file.substr(at + folder.size(), file.size() - at - folder.size() - 4));
        std::replace(name.begin(), name.end(), '_', '-');
        if (name.size() > best.size() && findIntegrator(name) != nullptr) best = name;
    }
    return QString::fromStdString(best);
}

} // namespace rbw
