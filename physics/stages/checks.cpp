#include "physics/stages/checks.h"

#include "physics/diagnostics.h"
#include "physics/quantities.h"

#include <cmath>
#include <cstdio>

namespace rbw {

namespace {

bool allStatesFinite(const std::vector<BodyState>& states)
{
    // NaN and infinity propagate through a sum, so a finite sum of every component
    // proves all are finite (a finite overflow only sends us to the detailed check).
    double sum = 0.0;
    for (const BodyState& s : states) {
        sum += s.x_W.sum() + s.v_W.sum() + s.q_WB.coeffs().sum() + s.L_W.sum() + s.omega_W.sum();
    }
    return std::isfinite(sum);
}

std::string joules(double x)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", x);
    return buf;
}

// A blow-up of body b in this step: "simulation blew up in step k: <quantity> of body
// "<name>" <what>. Try a smaller dt or another integrator."
StepStatus blowUp(const StepContext& ctx, int b, const char* kind, const char* quantity, const std::string& what)
{
    StepStatus st;
    st.ok = false;
    st.kind = kind;
    st.step = ctx.k;
    st.body = b;
    st.bodyName = ctx.scene.bodies[b].name;
    st.quantity = quantity;
    st.message = "simulation blew up in step " + std::to_string(st.step) + ": " + quantity + " of body \"" +
                 st.bodyName + "\" " + what + ". Try a smaller dt or another integrator.";
    return st;
}

// The first non-finite quantity, as a status that names step, body and quantity.
StepStatus describeBlowUp(const StepContext& ctx)
{
    struct Field {
        const char* id;
        bool finite;
    };
    for (int b = 0; b < static_cast<int>(ctx.states.size()); ++b) {
        const BodyState& s = ctx.states[b];
        const Field fields[] = {
            {q::position.id, isFinite(s.x_W)},
            {q::linear_velocity.id, isFinite(s.v_W)},
            {q::orientation.id, isFinite(s.q_WB)},
            {q::angular_momentum.id, isFinite(s.L_W)},
            {q::angular_velocity.id, isFinite(s.omega_W)},
        };
        for (const Field& f : fields) {
            if (!f.finite) return blowUp(ctx, b, "non-finite", f.id, "is not finite");
        }
    }
    return StepStatus::success();
}

} // namespace

void FiniteCheckStage::run(StepContext& ctx)
{
    // Before the contact stages: a NaN pose makes every overlap test pass and would
    // spread the NaN into healthy bodies, and the report would blame them.
    if (!allStatesFinite(ctx.states)) ctx.status = describeBlowUp(ctx);
}

EnergyBoundStage::EnergyBoundStage(const std::vector<MassProperties>& mass)
{
    maxInvInertia_.reserve(mass.size());
    for (const MassProperties& mp : mass) {
        // I0^-1 is diagonal: its largest entry is its largest eigenvalue
        maxInvInertia_.push_back(mp.I0inv_B.diagonal().maxCoeff());
    }
}

void EnergyBoundStage::run(StepContext& ctx)
{
    const double h = ctx.scene.dt;
    const double factor = ctx.scene.energyJumpFactor;
    for (int b = 0; b < static_cast<int>(ctx.states.size()); ++b) {
        if (!ctx.movable[b]) continue;
        const BodyState& s = ctx.states[b];
        const MassProperties& mp = ctx.mass[b];
        const BodyLoad& l = ctx.loads[b];
        // T_n = 1/2 M |v|^2 + 1/2 omega . L
        const double T_n = kineticEnergy(mp, s);
        // W_n: the most work the step's loads can do, from v' = v + h F/M and
        // L' = L + h q with I^-1 unchanged (docs/stability.md):
        //   W_n = h |F.v| + h^2 |F|^2 / (2M) + h |q.omega| + h^2 |q|^2 max(I0^-1) / 2
        const double W_n = h * std::abs(l.F_W.dot(s.v_W)) + 0.5 * h * h * mp.invM * l.F_W.squaredNorm() +
                           h * std::abs(l.q_W.dot(s.omega_W)) +
                           0.5 * h * h * maxInvInertia_[b] * l.q_W.squaredNorm();
        // T_max = factor (T_n + W_n) + floor
        ctx.scratch.kineticBefore[b] = T_n;
        ctx.scratch.kineticBound[b] = factor * (T_n + W_n) + ctx.scene.energyJumpFloor;
    }
}

void EnergyCheckStage::run(StepContext& ctx)
{
    for (int b = 0; b < static_cast<int>(ctx.states.size()); ++b) {
        if (!ctx.movable[b]) continue;
        const double T = kineticEnergy(ctx.mass[b], ctx.states[b]);
        // A bound that overflowed to infinity cannot be exceeded; T is finite here.
        if (!(T > ctx.scratch.kineticBound[b])) continue;
        const double before = ctx.scratch.kineticBefore[b];
        const double bound = ctx.scratch.kineticBound[b];
        ctx.status = blowUp(ctx, b, "energy-jump", "kinetic_energy",
                            "jumped from " + joules(before) + " J to " + joules(T) + " J in one step, above the bound " +
                                joules(bound) + " J");
        ctx.status.kineticBefore = before;
        ctx.status.kineticAfter = T;
        ctx.status.kineticBound = bound;
        return;
    }
}

} // namespace rbw
