// The cases of the stability tests (docs/stability.md): free bodies at the extremes of
// mass, shape, spin, step size and run length, each run through World::step so that
// the blow-up detection a user sees (non-finite value, energy jump) is part of it.
#pragma once

#include "physics/engine/scene.h"
#include "physics/engine/world.h"


#include <cmath>
#include <string>

namespace rbw::stability {

struct Case {
    const char* id;
    Vec3 size;          // box edges [m]
    double mass;        // [kg]
    Vec3 omega0_W;      // [rad/s]
    double dt;          // [s]
    long steps;
};

// The cases of docs/stability.md, one table for the test that asserts the outcomes
// and for the program that measured them, so the two cannot drift apart.
inline const Case kCases[] = {
    {"mass 1e-6", Vec3(1, 0.6, 0.5), 1e-6, Vec3(0.3, 1.0, 0.2), 0.01, 10000},
    {"mass 1", Vec3(1, 0.6, 0.5), 1.0, Vec3(0.3, 1.0, 0.2), 0.01, 10000},
    {"mass 1e6", Vec3(1, 0.6, 0.5), 1e6, Vec3(0.3, 1.0, 0.2), 0.01, 10000},
    {"needle 1000:1", Vec3(1, 1e-3, 1e-3), 1.0, Vec3(0.3, 1.0, 0.2), 0.01, 10000},
    {"plate 1000:1", Vec3(1, 1, 1e-3), 1.0, Vec3(0.3, 1.0, 0.2), 0.01, 10000},
    {"omega 1e3, h 1e-3", Vec3(1, 0.6, 0.5), 1.0, Vec3(300, 1000, 200), 1e-3, 10000},
    {"omega 1e3, h 1e-5", Vec3(1, 0.6, 0.5), 1.0, Vec3(300, 1000, 200), 1e-5, 10000},
    {"dt 1e-6", Vec3(1, 0.6, 0.5), 1.0, Vec3(0.3, 1.0, 0.2), 1e-6, 10000},
    {"dt 0.1", Vec3(1, 0.6, 0.5), 1.0, Vec3(0.3, 1.0, 0.2), 0.1, 10000},
    {"dt 1", Vec3(1, 0.6, 0.5), 1.0, Vec3(0.3, 1.0, 0.2), 1.0, 10000},
    {"1e6 steps", Vec3(1, 0.6, 0.5), 1.0, Vec3(0.3, 1.0, 0.2), 0.01, 1000000},
};

// The body starts turned by 0.7 rad about (1, 2, 2) so that no principal axis is along
// a world axis, at rest, with omega0; no forces, no gravity, nothing to collide.
inline SceneDef freeBodyScene(const Case& c, const std::string& integrator)
{
    SceneDef s;
    s.name = c.id;
    s.dt = c.dt;
    s.steps = c.steps;
    s.integrator = integrator;
    BodyDef b;
    b.name = "body";
    b.size = c.size;
    b.mass = c.mass;
    b.q0_WB = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 2).normalized()));
    b.omega0_W = c.omega0_W;
    s.bodies.push_back(b);
    return s;
}

struct Outcome {
    bool ok = true;
    long blowUpStep = -1;
    std::string kind;           // "non-finite" / "energy-jump"
    double maxRelEnergy = 0.0;  // max_n |T_n - T_0| / T_0
    double maxRelL = 0.0;       // max_n ||L_n| - |L_0|| / |L_0|
    double endRelEnergy = 0.0;  // (T_N - T_0) / T_0, signed
    double maxOrtho = 0.0;      // max_n ||R^T R - E|| (max abs entry)
};

inline Outcome run(const SceneDef& scene)
{
    World world(scene);
    Outcome o;
    const double T0 = world.diagnostics().bodies[0].kinetic;
    const double L0 = world.diagnostics().bodies[0].L_norm;
    double T = T0;
    for (long k = 0; k < scene.steps; ++k) {
        const StepStatus st = world.step();
        if (!st.ok) {
            o.ok = false;
            o.blowUpStep = st.step;
            o.kind = st.kind;
            break;
        }
        const BodyState& s = world.states()[0];
        T = bodyDiagnostics(world.massProperties()[0], s).kinetic;
        o.maxRelEnergy = std::max(o.maxRelEnergy, std::abs(T - T0) / T0);
        o.maxRelL = std::max(o.maxRelL, std::abs(s.L_W.norm() - L0) / L0);
        const Mat3 E = s.R_WB.transpose() * s.R_WB - Mat3::Identity();
        o.maxOrtho = std::max(o.maxOrtho, E.cwiseAbs().maxCoeff());
    }
    o.endRelEnergy = (T - T0) / T0;
    return o;
}

} // namespace rbw::stability
