// The scenes and trace readers of the manifold solver's tests (tst_contact_solver,
// tst_soft_step_solver): unit cubes over a ground plane, h = 1/60 s, symplectic Euler,
// c = 0, contact_model "manifold" with the sequential impulses (a soft-step row sets its
// own solver).
#pragma once

#include "physics/engine/scene.h"
#include "physics/engine/trace.h"

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace rbw::test::manifold {

using rbw::SceneDef;
using rbw::Vec3;

inline constexpr double kH = 1.0 / 60.0;
inline constexpr double kG = 9.81;

inline SceneDef groundScene(double mu, bool sleep)
{
    SceneDef s;
    s.dt = kH;
    s.steps = 1;
    s.integrator = "symplectic-euler";
    s.g_W = Vec3(0.0, -kG, 0.0);
    s.restitution = 0.0;
    s.friction = mu;
    s.contactModel = rbw::ContactModel::Manifold;
    s.solver = rbw::ManifoldSolver::SequentialImpulses;   // the soft-step rows set theirs
    s.sleep = sleep;
    rbw::PlaneDef ground;
    ground.name = "ground";
    s.planes.push_back(ground);
    return s;
}

inline void addBox(SceneDef& s, const Vec3& x0_W, const Vec3& v0_W = Vec3::Zero(), double mass = 1.0)
{
    rbw::BodyDef b;
    b.name = "b";
    b.name += std::to_string(s.bodies.size());   // (not "b" + ...: g++ 12 warns -Wrestrict)
    b.mass = mass;
    b.x0_W = x0_W;
    b.v0_W = v0_W;
    s.bodies.push_back(b);
}

// Every value of one id in a trace, by (body, index).
inline std::vector<double> scalars(const rbw::StepTrace& t, std::string_view id)
{
    std::vector<double> out;
    for (const rbw::TraceEntry& e : t.entries) {
        if (id == e.info->id) out.push_back(std::get<double>(e.value));
    }
    return out;
}

inline double scalar(const rbw::StepTrace& t, std::string_view id, int body = -1)
{
    const rbw::TraceEntry* e = t.find(id, body);
    return e != nullptr ? std::get<double>(e->value) : std::nan("");
}

inline double sum(const std::vector<double>& v)
{
    double s = 0.0;
    for (double x : v) s += x;
    return s;
}

} // namespace rbw::test::manifold
