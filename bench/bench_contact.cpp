// The box rain of issue 11, in both contact models and, when Bullet is found, in Bullet
// 3.24 in the same run: N unit boxes (M = 1 kg) in layers of 10 x 10, 1.5 m apart, the
// lowest layer at 3 m, each turned by up to 0.2 rad about a random axis (fixed seed),
// a ground plane, h = 1/60 s, 600 steps (10 s), mu = 0.5, c = 0, symplectic Euler (the
// integrator Bullet uses). Bullet: btDiscreteDynamicsWorld with the default
// btSequentialImpulseConstraintSolver, btDbvtBroadphase, btStaticPlaneShape ground,
// friction sqrt(0.5) per body (Bullet multiplies them: 0.5 per pair), no sleeping.
//
// Each benchmark runs the 600 steps once and reports ms/step and the outcome after 10 s,
// measured the same way for every engine from the final poses and velocities:
//   KE        kinetic energy, sum of 1/2 M |v|^2 + 1/2 omega . I omega          [J]
//   moving    boxes faster than 0.01 m/s (and moving_01: faster than 0.1 m/s)   [-]
//   overlap   the deepest box-box overlap: the smallest SAT overlap of each
//             overlapping pair (course/box_box_sat.h), the largest of those      [m]
//   below     how far the lowest box corner is below the ground                 [m]
// The scene and the outcome: rain_scene.h (shared with bench_rain.cpp, which also times
// Rapier and reports sleeping, mean height and drift).
// Results and machine: docs/performance.md, "Contacts: the box rain".
// Run: ./build/bench/rbw_bench_contact   (about a minute)
#include "bench/rain_scene.h"
#include "physics/engine/world.h"

#include <benchmark/benchmark.h>

#ifdef RBW_HAVE_BULLET
#include <btBulletDynamicsCommon.h>
#endif

#include <algorithm>
#include <ctime>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

namespace {

// CPU time of this thread [s]: the machine is shared, so wall time is not the cost.
double threadSeconds()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

using rain::FinalBox;
using rain::kH;
using rain::kSteps;
using rain::measure;
using rain::Outcome;
using rain::RainBox;
using rain::rainPoses;
using rain::rainScene;

void report(benchmark::State& state, double seconds, const Outcome& o)
{
    state.counters["ms_per_step"] = 1000.0 * seconds / kSteps;   // CPU time of the 600 steps
    state.counters["KE_J"] = o.kineticEnergy;
    state.counters["moving"] = o.moving;
    state.counters["moving_01"] = o.moving01;
    state.counters["overlap_m"] = o.overlap;
    state.counters["below_m"] = o.below;
}

void BM_RainOurs(benchmark::State& state, rbw::ContactModel model)
{
    const int n = static_cast<int>(state.range(0));
    for (auto _ : state) {
        state.PauseTiming();
        rbw::World world(rainScene(n, model));
        state.ResumeTiming();
        const double start = threadSeconds();
        for (int k = 0; k < kSteps; ++k) world.step(nullptr);
        const double seconds = threadSeconds() - start;
        state.PauseTiming();
        std::vector<FinalBox> boxes;
        for (int b = 0; b < n; ++b) {
            const rbw::BodyState& s = world.states()[static_cast<std::size_t>(b)];
            boxes.push_back(FinalBox{rbw::BoxPose{s.x_W, s.R_WB, rbw::Vec3::Constant(0.5)}, s.v_W, s.omega_W});
        }
        report(state, seconds, measure(boxes));
        state.ResumeTiming();
    }
}

#ifdef RBW_HAVE_BULLET
void BM_RainBullet(benchmark::State& state)
{
    const int n = static_cast<int>(state.range(0));
    for (auto _ : state) {
        state.PauseTiming();
        btDefaultCollisionConfiguration config;
        btCollisionDispatcher dispatcher(&config);
        btDbvtBroadphase broadphase;
        btSequentialImpulseConstraintSolver solver;
        btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
        world.setGravity(btVector3(0.0, -9.81, 0.0));
        const btScalar friction = std::sqrt(0.5);
        btStaticPlaneShape groundShape(btVector3(0, 1, 0), 0);
        btRigidBody ground(0.0, nullptr, &groundShape);
        ground.setFriction(friction);
        ground.setRestitution(0.0);
        world.addRigidBody(&ground);
        btBoxShape boxShape(btVector3(0.5, 0.5, 0.5));
        btVector3 inertia(0, 0, 0);
        boxShape.calculateLocalInertia(1.0, inertia);
        std::vector<std::unique_ptr<btDefaultMotionState>> motions;
        std::vector<std::unique_ptr<btRigidBody>> bodies;
        for (const RainBox& r : rainPoses(n)) {
            const btTransform t(btQuaternion(r.q_WB.x(), r.q_WB.y(), r.q_WB.z(), r.q_WB.w()),
                                btVector3(r.x_W.x(), r.x_W.y(), r.x_W.z()));
            motions.push_back(std::make_unique<btDefaultMotionState>(t));
            btRigidBody::btRigidBodyConstructionInfo info(1.0, motions.back().get(), &boxShape, inertia);
            bodies.push_back(std::make_unique<btRigidBody>(info));
            bodies.back()->setFriction(friction);
            bodies.back()->setRestitution(0.0);
            bodies.back()->setActivationState(DISABLE_DEACTIVATION);
            world.addRigidBody(bodies.back().get());
        }
        state.ResumeTiming();
        const double start = threadSeconds();
        for (int k = 0; k < kSteps; ++k) world.stepSimulation(kH, 1, kH);
        const double seconds = threadSeconds() - start;
        state.PauseTiming();
        std::vector<FinalBox> boxes;
        for (const std::unique_ptr<btRigidBody>& b : bodies) {
            const btTransform& t = b->getWorldTransform();
            const btQuaternion q = t.getRotation();
            const rbw::Quat q_WB(q.w(), q.x(), q.y(), q.z());
            const rbw::Vec3 x_W(t.getOrigin().x(), t.getOrigin().y(), t.getOrigin().z());
            const btVector3& v = b->getLinearVelocity();
            const btVector3& w = b->getAngularVelocity();
            boxes.push_back(FinalBox{rbw::BoxPose{x_W, q_WB.toRotationMatrix(), rbw::Vec3::Constant(0.5)},
                                     rbw::Vec3(v.x(), v.y(), v.z()), rbw::Vec3(w.x(), w.y(), w.z())});
        }
        report(state, seconds, measure(boxes));
        for (const std::unique_ptr<btRigidBody>& b : bodies) world.removeRigidBody(b.get());
        world.removeRigidBody(&ground);
        state.ResumeTiming();
    }
}
BENCHMARK(BM_RainBullet)->Arg(10)->Arg(100)->Arg(1000)->Iterations(1)->Unit(benchmark::kMillisecond);
#endif

BENCHMARK_CAPTURE(BM_RainOurs, manifold, rbw::ContactModel::Manifold)
    ->Arg(10)->Arg(100)->Arg(1000)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RainOurs, course, rbw::ContactModel::Course)
    ->Arg(10)->Arg(100)->Arg(1000)->Iterations(1)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
