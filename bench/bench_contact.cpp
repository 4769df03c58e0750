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
// The scene and the outcome: rain_scene.h, Bullet's world: rain_bullet.h (shared with bench_rain.cpp, which also times
// Rapier and reports sleeping, mean height and drift).
// Results and machine: docs/performance.md, "Contacts: the box rain".
// Run: ./build/bench/rbw_bench_contact   (about a minute)
#include "bench/rain_scene.h"
#include "physics/engine/world.h"

#include <benchmark/benchmark.h>

#ifdef RBW_HAVE_BULLET
#include "bench/rain_bullet.h"
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
        // One thread: the time is the calling thread's CPU time (threadSeconds), which
        // would not count a second thread's work (bench_rain.cpp times the wall clock)
        rbw::WorldOptions oneThread;
        oneThread.contactThreads = 1;
        rbw::World world(rainScene(n, model), oneThread);
        state.ResumeTiming();
        const double start = threadSeconds();
        for (int k = 0; k < kSteps; ++k) world.step(nullptr);
        const double seconds = threadSeconds() - start;
        state.PauseTiming();
        const std::vector<FinalBox> boxes = rain::ourBoxes(world);
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
        rain::BulletRain bullet(rainPoses(n));
        state.ResumeTiming();
        const double start = threadSeconds();
        for (int k = 0; k < kSteps; ++k) bullet.step();
        const double seconds = threadSeconds() - start;
        state.PauseTiming();
        const std::vector<FinalBox> boxes = bullet.boxes();
        report(state, seconds, measure(boxes));
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
