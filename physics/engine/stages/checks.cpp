#include "physics/engine/stages/checks.h"

#include "physics/engine/diagnostics.h"
#include "physics/engine/quantities.h"
#include "physics/engine/stages/probes_stage.h"

#include <cmath>
#include <cstdio>
#include <type_traits>
#include <variant>

namespace rbw {

namespace {

bool allStatesFinite(const std::vector<BodyState>& states)
{
    // NaN and infinity propagate through a sum, so a finite sum of every component
    // proves all are finite (a finite overflow only sends us to the detailed check).
    // Three partial sums, so that the additions do not wait on one another.
    double state = 0.0;
    double rates = 0.0;
    double derived = 0.0;
    for (const BodyState& s : states) {
        state += s.x_W.sum() + s.q_WB.coeffs().sum();
        rates += s.v_W.sum() + s.L_W.sum() + s.omega_W.sum();
        derived += s.R_WB.sum() + s.Iinv_W.sum();
    }
    return std::isfinite(state + rates + derived);
}

// A magnitude in three significant digits, exponent without "+" or leading zeros:
// 1e308, 1.67e307, 1e-308, inf.
std::string magnitude(double x)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", x);
    std::string s = buf;
    const std::size_t e = s.find('e');
    if (e == std::string::npos) return s;
    std::string exponent = s.substr(e + 1);
    std::string sign;
    if (!exponent.empty() && (exponent[0] == '+' || exponent[0] == '-')) {
        if (exponent[0] == '-') sign = "-";
        exponent.erase(0, 1);
    }
    while (exponent.size() > 1 && exponent[0] == '0') exponent.erase(0, 1);
    return s.substr(0, e + 1) + sign + exponent;
}

// One input named by the edge rule: "|ω0| = 1e308 (bodies[0].angular_velocity)". `large`: too large (reduce it),
// else too small (increase it); `derived`: a constant computed from the inputs.
struct EdgeInput {
    std::string text;
    bool large = true;
    bool derived = false;
};

bool atLargeEdge(double m) { return !(m < kRangeEdge); }   // NaN and infinity count
bool atSmallEdge(double m) { return m <= 1.0 / kRangeEdge; }

// Rule (b) of checks.h for body b: its step-0 magnitudes at the edge, each as
// "SYMBOL = VALUE (FIELD)" with the scene file's field: "|ω0| = 1e308
// (bodies[0].angular_velocity)". The file's own inputs first; the derived constants
// (L0, I0, I0^-1) only when no input is named.
void bodyEdgeInputs(const CheckScope& scope, int b, std::vector<EdgeInput>& out)
{
    const BodyDef& def = scope.scene.bodies[b];
    const MassProperties& mp = scope.mass[b];
    const std::string body = "bodies[" + std::to_string(b) + "]";
    const std::size_t first = out.size();
    const auto add = [&out](const std::string& symbol, double m, const std::string& field, bool large, bool derived) {
        out.push_back({symbol + " = " + magnitude(m) + " (" + field + ")", large, derived});
    };
    // |v| without overflow in the squares (Eigen's stableNorm)
    if (atLargeEdge(def.x0_W.stableNorm())) add("|x0|", def.x0_W.stableNorm(), body + ".position", true, false);
    if (!def.fixed) {
        if (atLargeEdge(def.v0_W.stableNorm())) {
            add("|v0|", def.v0_W.stableNorm(), body + ".linear_velocity", true, false);
        }
        if (atLargeEdge(def.omega0_W.stableNorm())) {
            add("|ω0|", def.omega0_W.stableNorm(), body + ".angular_velocity", true, false);
        }
        if (atLargeEdge(def.mass)) add("M", def.mass, body + ".mass", true, false);
        if (atSmallEdge(def.mass)) add("M", def.mass, body + ".mass", false, false);
    }
    if (atLargeEdge(def.size.maxCoeff())) add("edge", def.size.maxCoeff(), body + ".size", true, false);
    if (atSmallEdge(def.size.minCoeff())) add("edge", def.size.minCoeff(), body + ".size", false, false);
    for (int i = 0; i < static_cast<int>(scope.scene.probes.size()); ++i) {
        const ProbeDef& p = scope.scene.probes[i];
        if (p.body == b && atLargeEdge(p.p0_W.stableNorm())) {
            add("|p0|", p.p0_W.stableNorm(), "probes[" + std::to_string(i) + "].point", true, false);
        }
    }
    if (out.size() > first || def.fixed) return;
    const BodyState s0 = initialState(def, mp, scope.conventions[b]);
    if (atLargeEdge(s0.L_W.stableNorm())) add("|L0|", s0.L_W.stableNorm(), body, true, true);
    if (atLargeEdge(mp.I0_B.cwiseAbs().maxCoeff())) add("I0", mp.I0_B.cwiseAbs().maxCoeff(), body, true, true);
    if (atLargeEdge(mp.I0inv_B.cwiseAbs().maxCoeff())) {
        add("I0⁻¹", mp.I0inv_B.cwiseAbs().maxCoeff(), body, true, true);
    }
}

// The status of a non-finite quantity.
struct Site {
    const char* quantity = "";
    int body = -1;               // the body named; -1: none
    bool worldLevel = false;     // a sum over the bodies; `body` is its largest part
    int index = -1;              // which contact, probe, ... (a trace entry's index)
    IndexKind indexKind = IndexKind::None;
    bool timeOfStep = false;     // the time t_{k+1}: rule (c)
    bool product = false;        // computed from a finite state (an energy, P, a contact number)
};

StepStatus nonFinite(const CheckScope& scope, CheckPoint at, const Site& site)
{
    const SceneDef& scene = scope.scene;
    StepStatus st;
    st.ok = false;
    st.kind = "non-finite";
    st.step = at.step;
    st.initialState = at.initial;
    st.body = site.body;
    st.bodyName = site.body >= 0 ? scene.bodies[site.body].name : std::string();
    st.quantity = site.quantity;
    st.index = site.index;
    st.indexKind = site.index >= 0 ? indexKindName(site.indexKind) : "";

    // What: "angular_velocity of body "box"", "impulse (contact 0) of body "A"",
    // "total_energy of the world (the largest part is body "b")", "time".
    std::string what = site.quantity;
    if (site.index >= 0) what += std::string(" (") + indexKindName(site.indexKind) + " " + std::to_string(site.index) + ")";
    if (site.worldLevel) {
        what += " of the world";
    } else if (site.body >= 0) {
        what += " of body \"" + st.bodyName + "\"";
    }
    if (site.worldLevel && site.body >= 0) what += " (the largest part is body \"" + st.bodyName + "\")";

    // The edge rule (checks.h): which inputs are at the edge of the double range.
    std::vector<EdgeInput> inputs;
    if (site.timeOfStep) {
        inputs.push_back({"h = " + magnitude(scene.dt) + " (dt)", true, false});
    } else {
        const int n = static_cast<int>(scene.bodies.size());
        if (site.body >= 0 && !site.worldLevel) {
            bodyEdgeInputs(scope, site.body, inputs);
        } else {
            for (int b = 0; b < n; ++b) bodyEdgeInputs(scope, b, inputs);
        }
        if (at.initial && inputs.empty() && site.body >= 0 && !site.worldLevel) {
            // an initial-state quantity whose own body has no input at the edge
            for (int b = 0; b < n; ++b) bodyEdgeInputs(scope, b, inputs);
        }
        const double g = scene.g_W.stableNorm();
        if (at.initial && atLargeEdge(g)) inputs.push_back({"|g| = " + magnitude(g) + " (gravity)", true, false});
    }
    st.inputsAtEdge = at.initial || !inputs.empty();

    std::string list;
    bool allLarge = true;
    bool allSmall = true;
    for (const EdgeInput& in : inputs) {
        list += (list.empty() ? "" : ", ") + in.text;
        allLarge = allLarge && in.large && !in.derived;
        allSmall = allSmall && !in.large && !in.derived;
    }
    st.edgeInputs = list;

    const std::string where = at.initial ? "simulation cannot start: " + what +
                                               " is not finite in the initial state (t = 0, before any step)"
                                         : "simulation blew up in step " + std::to_string(st.step) + ": " + what +
                                               " is not finite";
    if (!st.inputsAtEdge) {
        // Grown over the steps from moderate inputs. A product of a finite state may have
        // grown by the physics (a constant force), not by the integrator.
        st.message = where + (site.product ? " (the state is finite; this product of its values overflowed). "
                                             "Try a smaller dt or another integrator, or smaller forces."
                                           : ". Try a smaller dt or another integrator.");
        return st;
    }
    const char* hint = allLarge   ? "reduce them"
                       : allSmall ? "increase them"
                                  : "bring them well inside 1e-150 .. 1e150 in magnitude";
    st.message = where + ": the inputs are at the edge of the double range" + (list.empty() ? "" : ": " + list) + "; " +
                 hint + ".";
    return st;
}

// The first non-finite state quantity, in body order, then x, v, r, R, L, I^-1, omega.
StepStatus describeStates(const CheckScope& scope, const std::vector<BodyState>& states, CheckPoint at)
{
    struct Field {
        const char* id;
        bool finite;
    };
    for (int b = 0; b < static_cast<int>(states.size()); ++b) {
        const BodyState& s = states[b];
        const Field fields[] = {
            {q::position.id, isFinite(s.x_W)},
            {q::linear_velocity.id, isFinite(s.v_W)},
            {q::orientation.id, isFinite(s.q_WB)},
            {q::rotation_matrix.id, isFinite(s.R_WB)},
            {q::angular_momentum.id, isFinite(s.L_W)},
            {q::inverse_inertia_world.id, isFinite(s.Iinv_W)},
            {q::angular_velocity.id, isFinite(s.omega_W)},
        };
        for (const Field& f : fields) {
            if (!f.finite) return nonFinite(scope, at, Site{f.id, b});
        }
    }
    return StepStatus::success();
}

double sumOf(const TraceValue& value)
{
    return std::visit(
        [](const auto& v) -> double {
            using T = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<T, double>) {
                return v;
            } else if constexpr (std::is_same_v<T, Quat>) {
                return v.coeffs().sum();
            } else {
                return v.sum();
            }
        },
        value);
}

// The body whose part of a world-level sum is largest in magnitude; -1 without bodies.
template <class PartOf>
int largestPart(int bodies, PartOf partOf)
{
    int best = -1;
    double largest = -1.0;
    for (int b = 0; b < bodies; ++b) {
        const double m = partOf(b);
        // a non-finite part is the largest of all
        if (best < 0 || !std::isfinite(m) || m > largest) {
            best = b;
            largest = std::isfinite(m) ? m : INFINITY;
            if (!std::isfinite(m)) break;
        }
    }
    return best;
}

} // namespace

StepStatus checkMassProperties(const CheckScope& scope, CheckPoint at)
{
    double sum = 0.0;
    for (const MassProperties& mp : scope.mass) sum += mp.I0_B.sum() + mp.I0inv_B.sum();
    if (std::isfinite(sum)) return StepStatus::success();
    for (int b = 0; b < static_cast<int>(scope.mass.size()); ++b) {
        if (!isFinite(scope.mass[b].I0_B)) return nonFinite(scope, at, Site{q::inertia_body.id, b});
        if (!isFinite(scope.mass[b].I0inv_B)) return nonFinite(scope, at, Site{q::inverse_inertia_body.id, b});
    }
    return StepStatus::success();
}

StepStatus checkStates(const CheckScope& scope, const std::vector<BodyState>& states, CheckPoint at)
{
    if (allStatesFinite(states)) return StepStatus::success();
    return describeStates(scope, states, at);
}

StepStatus checkTime(const CheckScope& scope, double time, CheckPoint at)
{
    if (std::isfinite(time)) return StepStatus::success();
    Site site;
    site.quantity = "time";
    site.timeOfStep = true;
    return nonFinite(scope, at, site);
}

StepStatus checkDerivedOutputs(const CheckScope& scope, const std::vector<BodyState>& states, const Diagnostics& d,
                               CheckPoint at)
{
    const int n = static_cast<int>(states.size());
    const int probes = static_cast<int>(scope.scene.probes.size());
    // One sum over every number: the totals, each body's part and P = M v, the probes.
    double sum = d.kineticTranslational + d.kineticRotational + d.kinetic + d.potential + d.total + d.P_W.sum() +
                 d.L_O_W.sum();
    for (const BodyDiagnostics& db : d.bodies) {
        sum += db.kineticTranslational + db.kineticRotational + db.kinetic + db.L_W.sum() + db.L_norm;
    }
    for (int b = 0; b < n; ++b) sum += linearMomentum(scope.mass[b], states[b]).sum();
    for (int i = 0; i < probes; ++i) {
        const ProbeReading r = readProbe(scope.scene, states, scope.probeOffsets_B, i);
        sum += r.p_W.sum() + r.v_W.sum();
    }
    if (std::isfinite(sum)) return StepStatus::success();

    // Each body's own numbers, in body order.
    for (int b = 0; b < static_cast<int>(d.bodies.size()); ++b) {
        const BodyDiagnostics& db = d.bodies[b];
        struct Field {
            const char* name;
            bool finite;
        };
        const Field fields[] = {
            {"kinetic_energy_translational", std::isfinite(db.kineticTranslational)},
            {"kinetic_energy_rotational", std::isfinite(db.kineticRotational)},
            {"kinetic_energy", std::isfinite(db.kinetic)},
            {"angular_momentum", isFinite(db.L_W)},
            {"angular_momentum_norm", std::isfinite(db.L_norm)},
            {"linear_momentum", b < n && isFinite(Vec3(linearMomentum(scope.mass[b], states[b])))},
        };
        for (const Field& f : fields) {
            if (!f.finite) return nonFinite(scope, at, Site{f.name, b, false, -1, IndexKind::None, false, true});
        }
    }
    for (int i = 0; i < probes; ++i) {
        const ProbeReading r = readProbe(scope.scene, states, scope.probeOffsets_B, i);
        if (!isFinite(r.p_W)) {
            return nonFinite(scope, at, Site{q::probe_position.id, r.body, false, i, IndexKind::Probe, false, true});
        }
        if (!isFinite(r.v_W)) {
            return nonFinite(scope, at, Site{q::point_velocity.id, r.body, false, i, IndexKind::Probe, false, true});
        }
    }
    // The totals: sums over the movable bodies whose parts may each be finite. The body
    // named is the largest part.
    const Vec3 g_W = scope.scene.g_W;
    const auto movable = [&scope](int b) { return scope.mass[b].invM != 0.0; };
    const auto potential = [&](int b) { return movable(b) ? std::abs(scope.mass[b].M * g_W.dot(states[b].x_W)) : 0.0; };
    const auto kineticPart = [&](int b, double BodyDiagnostics::*field) {
        return b < static_cast<int>(d.bodies.size()) ? std::abs(d.bodies[b].*field) : 0.0;
    };
    const auto momentum = [&](int b) { return movable(b) ? Vec3(linearMomentum(scope.mass[b], states[b])).stableNorm() : 0.0; };
    const auto momentOrigin = [&](int b) {
        if (!movable(b)) return 0.0;
        const Vec3 P_b = linearMomentum(scope.mass[b], states[b]);
        const Vec3 L_O = states[b].x_W.cross(P_b) + states[b].L_W;
        return L_O.stableNorm();
    };
    struct Total {
        const char* name;
        bool finite;
        int largest;
    };
    const Total totals[] = {
        {"kinetic_energy_translational", std::isfinite(d.kineticTranslational),
         largestPart(n, [&](int b) { return kineticPart(b, &BodyDiagnostics::kineticTranslational); })},
        {"kinetic_energy_rotational", std::isfinite(d.kineticRotational),
         largestPart(n, [&](int b) { return kineticPart(b, &BodyDiagnostics::kineticRotational); })},
        {"kinetic_energy", std::isfinite(d.kinetic),
         largestPart(n, [&](int b) { return kineticPart(b, &BodyDiagnostics::kinetic); })},
        {"potential_energy", std::isfinite(d.potential), largestPart(n, potential)},
        {"total_energy", std::isfinite(d.total),
         largestPart(n, [&](int b) { return kineticPart(b, &BodyDiagnostics::kinetic) + potential(b); })},
        {"linear_momentum", isFinite(d.P_W), largestPart(n, momentum)},
        {"angular_momentum_origin", isFinite(d.L_O_W), largestPart(n, momentOrigin)},
    };
    for (const Total& t : totals) {
        if (!t.finite) return nonFinite(scope, at, Site{t.name, t.largest, true, -1, IndexKind::None, false, true});
    }
    return StepStatus::success();
}

StepStatus checkTrace(const CheckScope& scope, const StepTrace& trace, CheckPoint at)
{
    double sum = 0.0;
    for (const TraceEntry& e : trace.entries) sum += sumOf(e.value);
    if (std::isfinite(sum)) return StepStatus::success();
    for (const TraceEntry& e : trace.entries) {
        if (std::isfinite(sumOf(e.value))) continue;
        // (the state's own entries were checked by finite_check: this is a product of it)
        Site site{e.info->id, e.body, false, e.index, e.info->indexKind, false, true};
        // A contact's number is named by its first body (a plane's B side has body -1).
        if (e.info->indexKind == IndexKind::Contact && e.index >= 0 &&
            e.index < static_cast<int>(trace.contacts.size())) {
            site.body = trace.contacts[e.index].bodyA;
        }
        if (site.body < 0) site.worldLevel = true;
        return nonFinite(scope, at, site);
    }
    return StepStatus::success();   // a finite overflow of the sum alone
}

StepStatus nonFiniteKineticEnergy(const CheckScope& scope, CheckPoint at, int body)
{
    return nonFinite(scope, at, Site{"kinetic_energy", body, false, -1, IndexKind::None, false, true});
}

void FiniteCheckStage::run(StepContext& ctx)
{
    // Before the contact stages: a NaN pose makes every overlap test pass and would
    // spread the NaN into healthy bodies, and the report would blame them.
    if (!allStatesFinite(ctx.states)) {
        const CheckScope scope{ctx.scene, ctx.mass, ctx.conventions, ctx.probeOffsets_B};
        ctx.status = describeStates(scope, ctx.states, CheckPoint{ctx.k, false});
    }
}

} // namespace rbw
