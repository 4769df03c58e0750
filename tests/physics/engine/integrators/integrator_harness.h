// Helpers for the integrator tests: one free body driven directly through the
// Integrator interface (no World), so that any principal moments can be used, also
// ones no box has, such as the Dzhanibekov case I = (3, 5, 9).
#pragma once

#include "physics/engine/body.h"
#include "physics/engine/integrator.h"
#include "physics/engine/integrator_registry.h"

#include <QString>

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace rbw::test {

using rbw::BodyState;
using rbw::IntegrationInput;
using rbw::Integrator;
using rbw::Mat3;
using rbw::Quat;
using rbw::StepTrace;
using rbw::Vec3;

// u = 2^-53, the unit roundoff of double.
inline const double u = std::numeric_limits<double>::epsilon() / 2.0;

// M and I0 = diag(I) given directly (not from a box).
inline MassProperties principalMass(const Vec3& I, double M = 1.0)
{
    MassProperties mp;
    mp.M = M;
    mp.invM = 1.0 / M;
    mp.I0_B = I.asDiagonal();
    mp.I0inv_B = I.cwiseInverse().asDiagonal();
    return mp;
}

// One body and everything IntegrationInput refers to.
struct OneBody {
    std::vector<BodyDef> defs{1};
    std::vector<MassProperties> mass{1};
    std::vector<BodyLoad> loads{1};
    std::vector<BodyState> states{1};
    InertiaConvention convention = InertiaConvention::Standard;

    BodyState& s() { return states[0]; }
    const MassProperties& mp() const { return mass[0]; }
};

// A free body with principal moments I at orientation q0, with body-frame angular
// momentum L0_B (so L_W = R0 L0_B), position x0 and velocity v0.
inline OneBody freeBody(const Vec3& I, const Quat& q0, const Vec3& L0_B, const Vec3& x0 = Vec3::Zero(),
                        const Vec3& v0 = Vec3::Zero(), InertiaConvention convention = InertiaConvention::Standard,
                        double M = 1.0)
{
    OneBody b;
    b.convention = convention;
    b.mass[0] = principalMass(I, M);
    BodyState& s = b.states[0];
    s.x_W = x0;
    s.v_W = v0;
    s.q_WB = q0.normalized();
    s.L_W = s.q_WB * L0_B;
    updateDerived(b.mass[0], s, convention);
    return b;
}

inline void step(const Integrator& integrator, OneBody& b, double h, StepTrace* trace = nullptr)
{
    const IntegrationInput in{h, b.defs, b.mass, b.loads, b.convention};
    integrator.integrate(in, b.states, trace);
}

inline void run(const Integrator& integrator, OneBody& b, double h, long steps)
{
    for (long k = 0; k < steps; ++k) {
        step(integrator, b, h);
    }
}

// T = 1/2 omega . L
inline double energy(const BodyState& s) { return 0.5 * s.omega_W.dot(s.L_W); }

// L_B = R^T L with R read from the state (the primary R for the rotation-matrix methods).
inline Vec3 bodyL(const BodyState& s) { return s.R_WB.transpose() * s.L_W; }

// The rotation angle between two orientations: 2 atan2(|vec(a^-1 b)|, |w(a^-1 b)|).
inline double angleBetween(const Quat& a, const Quat& b)
{
    const Quat d = a.conjugate() * b;
    return 2.0 * std::atan2(d.vec().norm(), std::abs(d.w()));
}

inline std::unique_ptr<Integrator> integratorNamed(const QString& name)
{
    return makeIntegrator(name.toStdString());
}

} // namespace rbw::test
