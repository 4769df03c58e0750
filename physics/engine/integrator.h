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

#include "physics/engine/body.h"
#include "physics/engine/inertia.h"
#include "physics/engine/trace.h"

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

// One body's step, as the base hands it to an integrator's update.
struct BodyStep {
    int body;                       // index in the world, for the trace rows
    double h;                       // step size [s]
    const MassProperties& mp;       // M, 1/M, I0, I0^-1
    const BodyLoad& load;           // F and q of this step
    InertiaConvention convention;   // I^-1 = R I0^-1 R^T or R^T I0^-1 R
    StepTrace* trace;               // nullptr: record nothing

    // Records a row of this body, on the line that computes the value.
    template <class T>
    void record(const QuantityInfo& info, const T& value, int index = -1,
                std::source_location where = std::source_location::current()) const
    {
        rbw::record(trace, info, body, value, index, where);
    }
};

// The base owns what every integrator shares: the loop over the bodies of its group,
// then the derived quantities (R = R(r), I^-1, omega = I^-1 L) and their trace rows
// (updateDerived in body.cpp). An integrator implements only its update of x, v, r
// and L for one body, and records its own rows, so each file reads like its formula.
class Integrator {
public:
    virtual ~Integrator() = default;
    virtual const char* name() const = 0;
    // Advances the state of every body b with in.advances(b) and leaves R_WB, Iinv_W and
    // omega_W consistent with the new state.
    void integrate(const IntegrationInput& in, std::vector<BodyState>& states, StepTrace* trace) const;

    // What the base derives after advance(): from the orientation quaternion r (R, I^-1
    // and omega), or from the rotation matrix R that advance() left as the state (I^-1
    // and omega only: the rotation-matrix integrators). Public so that a derivation can
    // write out the rows the base adds.
    enum class Derived { FromQuaternion, FromMatrix };
    virtual Derived derivedFrom() const { return Derived::FromQuaternion; }

protected:
    // One body's update of x, v, r (or R) and L, with its own trace rows.
    virtual void advance(const BodyStep& step, BodyState& s) const = 0;
};

} // namespace rbw
