#include "physics/engine/stages/energy_jump_stage.h"

#include "physics/engine/diagnostics.h"
#include "physics/engine/stages/checks.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace rbw {

namespace {

std::string joules(double x)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", x);
    return buf;
}

// A blow-up of body b in this step that is not a non-finite number: "simulation blew up
// in step k: <quantity> of body "<name>" <what>. Try a smaller dt or another integrator."
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

} // namespace

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
        // A bound that overflowed to infinity cannot be exceeded.
        if (!(T > ctx.scratch.kineticBound[b])) continue;
        if (!std::isfinite(T)) {
            // x, v, L and omega are finite (finite_check), but 1/2 M |v|^2 + 1/2 omega.L
            // overflowed: a non-finite number, not a jump (no infinity in the report).
            const CheckScope scope{ctx.scene, ctx.mass, ctx.conventions, ctx.probeOffsets_B};
            ctx.status = nonFiniteKineticEnergy(scope, CheckPoint{ctx.k, false}, b);
            return;
        }
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
