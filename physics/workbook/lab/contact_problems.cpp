#include "physics/workbook/lab/contact_problems.h"

#include "physics/engine/course/box_box_sat.h"
#include "physics/engine/course/box_plane.h"
#include "physics/engine/collision/broad_phase.h"
#include "physics/engine/diagnostics.h"

#include <algorithm>
#include <random>
#include <string>

namespace rbw::lab {

const char* contactProblemName(ContactProblem p)
{
    switch (p) {
    case ContactProblem::RestingBox: return "resting-box";
    case ContactProblem::Tower: return "tower";
    case ContactProblem::Rain: return "rain";
    }
    return "?";
}

std::optional<ContactProblem> contactProblemFromName(std::string_view name)
{
    for (ContactProblem p : {ContactProblem::RestingBox, ContactProblem::Tower, ContactProblem::Rain}) {
        if (name == contactProblemName(p)) return p;
    }
    return std::nullopt;
}

const char* contactProblemNames()
{
    return "resting-box, tower, rain";
}

namespace {

BodyDef unitBox(int i, const Vec3& x_W, const Quat& q_WB = Quat::Identity())
{
    BodyDef b;
    b.name = "box";
    b.name += std::to_string(i);
    b.size = Vec3::Ones();
    b.mass = 1.0;
    b.x0_W = x_W;
    b.q0_WB = q_WB;
    return b;
}

} // namespace

SceneDef contactProblemScene(ContactProblem p, ContactModel model, int rainBoxes)
{
    SceneDef s;
    s.name = contactProblemName(p);
    s.dt = 1.0 / 60.0;
    s.steps = 600;
    s.integrator = "symplectic-euler";
    s.g_W = Vec3(0.0, -9.81, 0.0);
    s.restitution = 0.0;
    s.friction = 0.5;
    s.contactModel = model;
    // The course model as the course uses it: with its position correction.
    s.positionCorrection = model == ContactModel::Course;
    PlaneDef ground;
    ground.name = "ground";
    s.planes.push_back(ground);
    switch (p) {
    case ContactProblem::RestingBox:
        // On the ground: its centre at half its height, y = 0.5.
        s.bodies.push_back(unitBox(0, Vec3(0.0, 0.5, 0.0)));
        break;
    case ContactProblem::Tower:
        // Box i at y = 0.5 + i: each face on the one below.
        for (int i = 0; i < 10; ++i) s.bodies.push_back(unitBox(i, Vec3(0.0, 0.5 + i, 0.0)));
        break;
    case ContactProblem::Rain: {
        std::mt19937 rng(20261123u);
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        std::uniform_real_distribution<double> angle(0.0, 0.2);
        for (int i = 0; i < rainBoxes; ++i) {
            const int layer = i / 100;
            const int k = i % 100;
            // x = 1.5 (ix - 4.5), z = 1.5 (iz - 4.5), y = 3 + 1.5 layer
            const Vec3 x_W(1.5 * (k % 10 - 4.5), 3.0 + 1.5 * layer, 1.5 * (k / 10 - 4.5));
            Vec3 axis(unit(rng), unit(rng), unit(rng));
            if (axis.norm() < 1e-6) axis = Vec3::UnitX();
            s.bodies.push_back(unitBox(i, x_W, Quat(Eigen::AngleAxisd(angle(rng), axis.normalized()))));
        }
        break;
    }
    }
    return s;
}

ContactMeasure measureContacts(const SceneDef& scene, const std::vector<MassProperties>& mass,
                               const std::vector<BodyState>& states)
{
    ContactMeasure m;
    const int n = static_cast<int>(states.size());
    std::vector<BoxPose> poses(static_cast<std::size_t>(n));
    std::vector<Aabb> boxes(static_cast<std::size_t>(n));
    for (int b = 0; b < n; ++b) {
        const BodyState& s = states[static_cast<std::size_t>(b)];
        poses[static_cast<std::size_t>(b)] = BoxPose{s.x_W, s.R_WB, 0.5 * scene.bodies[static_cast<std::size_t>(b)].size};
        boxes[static_cast<std::size_t>(b)] = boxAabb(poses[static_cast<std::size_t>(b)]);
        if (scene.bodies[static_cast<std::size_t>(b)].fixed) continue;
        m.kineticEnergy += kineticEnergy(mass[static_cast<std::size_t>(b)], s);
        if (s.v_W.norm() > 0.01) ++m.moving;
    }
    // The deepest box-box overlap: SAT on every pair whose AABBs overlap.
    for (int a = 0; a < n; ++a) {
        for (int b = a + 1; b < n; ++b) {
            if (!aabbOverlap(boxes[static_cast<std::size_t>(a)], boxes[static_cast<std::size_t>(b)])) continue;
            const std::optional<ContactGeometry> c =
                collideBoxBoxSAT(poses[static_cast<std::size_t>(a)], poses[static_cast<std::size_t>(b)]);
            if (c) m.deepestOverlap = std::max(m.deepestOverlap, c->depth);
        }
    }
    // The deepest corner below a plane.
    std::vector<ContactGeometry> corners;
    for (const PlaneDef& plane : scene.planes) {
        for (const BoxPose& pose : poses) {
            corners.clear();
            collideBoxPlane(pose, plane, corners);
            for (const ContactGeometry& c : corners) m.deepestBelow = std::max(m.deepestBelow, c.depth);
        }
    }
    return m;
}

} // namespace rbw::lab
