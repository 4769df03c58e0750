// What the scene-validation tests share (tst_scene_validation, tst_scene_rules): a valid
// base scene as a file (kBase) and the same scene built in code (codeBase()), and the
// helpers that build the pieces a row adds.
#pragma once

#include "app/scene/scene_loader.h"
#include "physics/engine/scene.h"

#include <QMetaType>
#include <QStringList>

#include <functional>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

// Breaks one rule in a SceneDef built in code.
using SceneEdit = std::function<void(rbw::SceneDef&)>;
Q_DECLARE_METATYPE(SceneEdit)

namespace validation_base {

using rbw::Vec3;

// A valid scene; rows replace one fragment of it to make it invalid.
inline const char* const kBase = R"({
  "name": "validation base",
  "dt": 0.1, "steps": 2, "integrator": "explicit-euler",
  "gravity": [0, -9.81, 0],
  "bodies": [
    { "name": "a", "size": [1, 0.6, 0.5], "mass": 2,
      "orientation": { "axis": [0, 0, 1], "degrees": 90 } },
    { "name": "b", "size": [1, 1, 1], "mass": 1, "position": [3, 0, 0] }
  ],
  "forces": [ { "body": "a", "point": [0.3, 0.5, 0.25], "force": [1, 1, 0] } ],
  "probes": [ { "body": "b", "point": [3.5, 0, 0] } ]
})";

// kBase, built in code.
inline rbw::SceneDef codeBase()
{
    rbw::SceneDef s;
    s.name = "validation base";
    s.dt = 0.1;
    s.steps = 2;
    s.integrator = "explicit-euler";
    s.g_W = Vec3(0, -9.81, 0);
    rbw::BodyDef a;
    a.name = "a";
    a.size = Vec3(1, 0.6, 0.5);
    a.mass = 2;
    a.q0_WB = rbw::Quat(Eigen::AngleAxisd(std::numbers::pi / 2, Vec3::UnitZ()));
    rbw::BodyDef b;
    b.name = "b";
    b.size = Vec3(1, 1, 1);
    b.mass = 1;
    b.x0_W = Vec3(3, 0, 0);
    s.bodies = {a, b};
    rbw::ForceDef f;
    f.body = 0;
    f.p_W = Vec3(0.3, 0.5, 0.25);
    f.f_W = Vec3(1, 1, 0);
    s.forces = {f};
    rbw::ProbeDef p;
    p.body = 1;
    p.p0_W = Vec3(3.5, 0, 0);
    s.probes = {p};
    return s;
}

inline rbw::PlaneDef plane(const std::string& name, const Vec3& n = Vec3::UnitY())
{
    return rbw::PlaneDef{name, Vec3::Zero(), n};
}

// A pair as a scene built in code names it: by name, resolved as the loader does.
inline rbw::PairOverride pair(const rbw::SceneDef& s, const std::string& first, const std::string& second,
                       std::optional<double> c, std::optional<double> mu)
{
    rbw::PairOverride o;
    o.nameA = first;
    o.nameB = second;
    o.bodyA = s.bodyIndex(first);
    o.bodyB = s.bodyIndex(second);
    o.planeB = o.bodyB < 0 ? s.planeIndex(second) : -1;
    o.restitution = c;
    o.friction = mu;
    return o;
}

inline QStringList lines(const std::vector<rbw::SceneIssue>& issues)
{
    QStringList out;
    for (const rbw::SceneIssue& i : issues) out << QString::fromStdString(i.path + ": " + i.reason);
    return out;
}

} // namespace validation_base
