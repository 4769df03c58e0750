// The integrator interface. The world computes the loads of the forces stage (total
// force F and torque q per body) and hands them to one integrator, which advances
// every movable body's state by one step of size h and records its own intermediate
// quantities in the trace. Each integrator lives in its own file in integrators/.
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
    InertiaConvention convention = InertiaConvention::Standard;
};

class Integrator {
public:
    virtual ~Integrator() = default;
    virtual const char* name() const = 0;
    // Advances the state of every body that is not fixed. Must leave R_WB, Iinv_W and
    // omega_W consistent with the new state (updateDerived).
    virtual void integrate(const IntegrationInput& in, std::vector<BodyState>& states,
                           StepTrace* trace) const = 0;
};

} // namespace rbw
