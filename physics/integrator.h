// The integrator interface. The world computes the loads of the forces stage (total
// force F and torque q per body) and hands them to the integrators, which advance
// the movable bodies' states by one step of size h and record their own intermediate
// quantities in the trace. Each integrator lives in its own file in integrators/.
//
// A body may choose its own integrator and inertia convention (BodyDef), so one scene
// can run variants side by side. The world then groups the bodies by integrator and
// gives each integrator its group (`active`) and every body's convention
// (`conventions`); an integrator advances exactly the bodies for which advances(b).
#pragma once

#include "physics/body.h"
#include "physics/inertia.h"
#include "physics/trace.h"

#include <vector>

namespace rbw {

// The loads of one step on one body (TUM algorithm step 1).
struct BodyLoad {
    Vec3 F_W = Vec3::Zero();    // total force F = sum f_i (+ M g)
    Vec3 q_W = Vec3::Zero();    // total torque q = sum (p_i - x) x f_i, about the centre of mass
};

struct IntegrationInput {
    double h = 0.0;
    const std::vector<BodyDef>& defs;
    const std::vector<MassProperties>& mass;
    const std::vector<BodyLoad>& loads;
    // The convention of every body, unless `conventions` is given.
    InertiaConvention convention = InertiaConvention::Standard;
    // Per body: the body's own convention (nullptr: `convention` for all).
    const std::vector<InertiaConvention>* conventions = nullptr;
    // Per body: non-zero for the bodies this integrator advances (nullptr: all).
    const std::vector<char>* active = nullptr;

    // Whether this integrator advances body b: not fixed, and in its group.
    bool advances(int b) const { return !defs[b].fixed && (active == nullptr || (*active)[b] != 0); }
    // I^-1 = R I0^-1 R^T (standard) or R^T I0^-1 R (course template), for body b.
    InertiaConvention conventionOf(int b) const
    {
        return conventions != nullptr ? (*conventions)[b] : convention;
    }
};

class Integrator {
public:
    virtual ~Integrator() = default;
    virtual const char* name() const = 0;
    // Advances the state of every body b with in.advances(b). Must leave R_WB, Iinv_W and
    // omega_W consistent with the new state (updateDerived).
    virtual void integrate(const IntegrationInput& in, std::vector<BodyState>& states,
                           StepTrace* trace) const = 0;
};

} // namespace rbw
