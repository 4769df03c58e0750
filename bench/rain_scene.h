// The box rain (issues 11 and 19), shared by every engine of bench_contact.cpp and
// bench_rain.cpp: the initial poses, our scene, and the outcome measured the same way for
// every engine from the boxes' final states.
//
// The scene: N unit boxes (M = 1 kg) in layers of 10 x 10, 1.5 m apart, the lowest layer
// at 3 m, each turned by up to 0.2 rad about a random axis (fixed seed), a ground plane
// y = 0, h = 1/60 s, 600 steps (10 s), mu = 0.5, c = 0.
//
// The outcome after the last step:
//   KE          kinetic energy, sum of 1/2 M |v|^2 + 1/2 omega . I omega            [J]
//   moving      boxes faster than 0.01 m/s (moving01: faster than 0.1 m/s)         [-]
//   sleeping    boxes the engine reports asleep                                      [-]
//   overlap     the deepest box-box overlap: the smallest SAT overlap of each
//               overlapping pair (course/box_box_sat.h), the largest of those        [m]
//   below       how far the lowest box corner is below the ground                   [m]
//   meanHeight  the mean height of the box centres (standing columns of 10: 4.97 m
//               with the contact slop; fallen columns are lower)                     [m]
//   drift       the largest distance a box centre moved in the last second          [m]
#pragma once

#include "physics/engine/collision/broad_phase.h"
#include "physics/engine/course/box_box_sat.h"
#include "physics/engine/scene.h"
#include "physics/engine/world.h"

#include <algorithm>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace rain {

constexpr double kH = 1.0 / 60.0;
constexpr int kSteps = 600;
constexpr int kLastSecond = kSteps - 60;   // the step one second before the end

struct RainBox {
    rbw::Vec3 x_W;
    rbw::Quat q_WB;
};

// The initial poses of the rain, shared by every engine.
inline std::vector<RainBox> rainPoses(int n)
{
    std::mt19937 rng(20261123u);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_real_distribution<double> angle(0.0, 0.2);
    std::vector<RainBox> out;
    for (int i = 0; i < n; ++i) {
        const int layer = i / 100;
        const int k = i % 100;
        // x = 1.5 (ix - 4.5), z = 1.5 (iz - 4.5), y = 3 + 1.5 layer
        const rbw::Vec3 x_W(1.5 * (k % 10 - 4.5), 3.0 + 1.5 * layer, 1.5 * (k / 10 - 4.5));
        rbw::Vec3 axis(unit(rng), unit(rng), unit(rng));
        if (axis.norm() < 1e-6) axis = rbw::Vec3::UnitX();
        const rbw::Quat q_WB(Eigen::AngleAxisd(angle(rng), axis.normalized()));
        out.push_back(RainBox{x_W, q_WB});
    }
    return out;
}

// Our scene of the rain with the given contact model and integrator.
inline rbw::SceneDef rainScene(int n, rbw::ContactModel model, const std::string& integrator = "symplectic-euler")
{
    rbw::SceneDef s;
    s.name = "box rain";
    s.dt = kH;
    s.steps = kSteps;
    s.integrator = integrator;
    s.g_W = rbw::Vec3(0.0, -9.81, 0.0);
    s.restitution = 0.0;
    s.friction = 0.5;
    s.contactModel = model;
    // The course model as issue 11 measured it: with its position correction.
    s.positionCorrection = model == rbw::ContactModel::Course;
    rbw::PlaneDef ground;
    ground.name = "ground";
    s.planes.push_back(ground);
    const std::vector<RainBox> poses = rainPoses(n);
    for (int i = 0; i < n; ++i) {
        rbw::BodyDef b;
        b.name = "b";
        b.name += std::to_string(i);
        b.size = rbw::Vec3::Ones();
        b.mass = 1.0;
        b.x0_W = poses[static_cast<std::size_t>(i)].x_W;
        b.q0_WB = poses[static_cast<std::size_t>(i)].q_WB;
        s.bodies.push_back(b);
    }
    return s;
}

struct FinalBox {
    rbw::BoxPose pose;
    rbw::Vec3 v_W;
    rbw::Vec3 omega_W;
    bool asleep = false;
};

struct Outcome {
    double kineticEnergy = 0.0;
    int moving = 0;      // |v| > 0.01 m/s
    int moving01 = 0;    // |v| > 0.1 m/s
    int sleeping = 0;
    double overlap = 0.0;
    double below = 0.0;
    double meanHeight = 0.0;
    double drift = 0.0;   // NaN-free: 0 when `before` is empty
};

// Our world's boxes, for measure()
inline std::vector<FinalBox> ourBoxes(const rbw::World& world)
{
    std::vector<FinalBox> boxes;
    for (int b = 0; b < static_cast<int>(world.states().size()); ++b) {
        const rbw::BodyState& s = world.states()[static_cast<std::size_t>(b)];
        boxes.push_back(FinalBox{rbw::BoxPose{s.x_W, s.R_WB, rbw::Vec3::Constant(0.5)}, s.v_W, s.omega_W,
                                 world.contactState().sleep.asleep(b)});
    }
    return boxes;
}

// The outcome from the final boxes (and, for the drift, the boxes one second earlier;
// empty: no drift measured), the same measure for every engine (see the top).
inline Outcome measure(const std::vector<FinalBox>& boxes, const std::vector<FinalBox>& before = {})
{
    Outcome o;
    std::vector<rbw::Aabb> aabbs;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const FinalBox& b = boxes[i];
        // KE of a unit cube: 1/2 |v|^2 + 1/2 omega . (1/6 E) omega
        o.kineticEnergy += 0.5 * b.v_W.squaredNorm() + 0.5 * b.omega_W.squaredNorm() / 6.0;
        const double speed = b.v_W.norm();
        if (speed > 0.01) ++o.moving;
        if (speed > 0.1) ++o.moving01;
        if (b.asleep) ++o.sleeping;
        for (const rbw::Vec3& corner_W : rbw::boxCorners(b.pose)) o.below = std::max(o.below, -corner_W.y());
        o.meanHeight += b.pose.c_W.y() / double(boxes.size());
        if (i < before.size()) o.drift = std::max(o.drift, (b.pose.c_W - before[i].pose.c_W).norm());
        aabbs.push_back(rbw::boxAabb(b.pose));
    }
    rbw::AabbTree tree;
    std::vector<std::pair<int, int>> pairs;
    rbw::BroadPhaseStats stats;
    tree.findPairs(aabbs, std::vector<char>(boxes.size(), 1), pairs, stats);
    for (const auto& [i, j] : pairs) {
        const std::optional<rbw::ContactGeometry> hit =
            rbw::collideBoxBoxSAT(boxes[static_cast<std::size_t>(i)].pose, boxes[static_cast<std::size_t>(j)].pose);
        if (hit) o.overlap = std::max(o.overlap, hit->depth);
    }
    return o;
}

} // namespace rain
