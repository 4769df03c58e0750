// Cost of one explicit Euler step, per body, with the trace off and on, and for a
// world of many free bodies. Results and machine: docs/performance.md.
#include "physics/engine/scene.h"
#include "physics/engine/trace.h"
#include "physics/engine/world.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

// N spinning, pushed boxes on a grid 2 m apart (they never touch); no gravity. With
// collisions off the step is forces + integration only.
rbw::SceneDef freeBodies(int n, bool withForce, bool collisions = false)
{
    rbw::SceneDef s;
    s.name = "bench";
    s.dt = 1e-3;
    s.boxCollisions = collisions;
    const int side = static_cast<int>(std::ceil(std::sqrt(double(n))));
    for (int i = 0; i < n; ++i) {
        rbw::BodyDef b;
        b.name = "b";
        b.name += std::to_string(i);   // (not "b" + ...: g++ 12 warns -Wrestrict on it)
        b.size = rbw::Vec3(1.0, 0.6, 0.5);
        b.mass = 2.0;
        b.x0_W = rbw::Vec3(2.0 * (i % side), 0.0, 2.0 * (i / side));
        b.q0_WB = rbw::Quat(Eigen::AngleAxisd(0.3 * i, rbw::Vec3(1, 2, 3).normalized()));
        b.omega0_W = rbw::Vec3(0.1, 0.2, 0.3);
        b.v0_W = rbw::Vec3(0.0, 1.0, 0.0);
        s.bodies.push_back(b);
        if (withForce) {
            rbw::ForceDef f;
            f.body = i;
            f.p_W = b.x0_W + rbw::Vec3(0.3, 0.5, 0.25);
            f.f_W = rbw::Vec3(1.0, 1.0, 0.0);
            f.fromStep = 0;
            f.toStep = 1L << 40;   // acts in every step
            s.forces.push_back(f);
        }
    }
    return s;
}

void BM_EulerStep(benchmark::State& state, bool traceOn)
{
    const int n = static_cast<int>(state.range(0));
    rbw::World world(freeBodies(n, true));
    rbw::StepTrace trace;
    trace.entries.reserve(64 * n);
    for (auto _ : state) {
        world.step(traceOn ? &trace : nullptr);
        benchmark::DoNotOptimize(world.states().data());
    }
    state.SetItemsProcessed(state.iterations() * n);   // body-steps
    state.counters["ns_per_body_step"] = benchmark::Counter(
        double(state.iterations()) * n,
        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_FreeBodies(benchmark::State& state, bool collisions)
{
    const int n = static_cast<int>(state.range(0));
    rbw::World world(freeBodies(n, false, collisions));
    for (auto _ : state) {
        world.step(nullptr);
        benchmark::DoNotOptimize(world.states().data());
    }
    state.SetItemsProcessed(state.iterations() * n);
    state.counters["ns_per_body_step"] = benchmark::Counter(
        double(state.iterations()) * n,
        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// The same free bodies in the minimal pipeline (loads, integration, checks) and with
// every stage forced on (WorldOptions::allStages: gravity with g = 0, the box-box broad
// and narrow phases, and the plane tests against a far plane that nothing reaches).
// The difference is what "model only what a scene requires" saves (docs/performance.md).
void BM_Pipeline(benchmark::State& state, bool allStages, bool energyCheck = true)
{
    const int n = static_cast<int>(state.range(0));
    rbw::SceneDef s = freeBodies(n, false, false);
    if (!energyCheck) {
        s.energyJumpFactor = 0.0;   // the minimal pipeline without the energy-jump check
    }
    if (allStages) {
        s.planes.push_back(rbw::PlaneDef{"far", rbw::Vec3(0, -1e6, 0), rbw::Vec3::UnitY()});
    }
    rbw::World world(s, rbw::WorldOptions{allStages});
    for (auto _ : state) {
        world.step(nullptr);
        benchmark::DoNotOptimize(world.states().data());
    }
    state.SetItemsProcessed(state.iterations() * n);
    state.counters["ns_per_body_step"] = benchmark::Counter(
        double(state.iterations()) * n,
        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// N unit boxes (M = 1) in a square grid 1.5 m apart, 2 m above a ground plane, each
// slightly tilted so they land on edges and corners and tumble; gravity, c = 0.5,
// friction 0.3, position correction on, h = 1/60 (60 Hz).
rbw::SceneDef dropGrid(int n)
{
    rbw::SceneDef s;
    s.name = "drop grid";
    s.dt = 1.0 / 60.0;
    s.g_W = rbw::Vec3(0, -9.81, 0);
    s.restitution = 0.5;
    s.friction = 0.3;
    s.positionCorrection = true;
    s.planes.push_back(rbw::PlaneDef{"ground", rbw::Vec3::Zero(), rbw::Vec3::UnitY()});
    const int side = static_cast<int>(std::ceil(std::sqrt(double(n))));
    for (int i = 0; i < n; ++i) {
        rbw::BodyDef b;
        b.name = "box";
        b.name += std::to_string(i);
        b.size = rbw::Vec3::Ones();
        b.mass = 1.0;
        b.x0_W = rbw::Vec3(1.5 * (i % side), 2.0 + 0.1 * (i % 7), 1.5 * (i / side));
        b.q0_WB = rbw::Quat(Eigen::AngleAxisd(0.2 + 0.05 * (i % 5), rbw::Vec3(1, 0.3 * (i % 3), 0.5).normalized()));
        s.bodies.push_back(b);
    }
    return s;
}

// One iteration = 600 steps (10 s of simulated time) from the initial drop.
void BM_DropGrid(benchmark::State& state)
{
    const int n = static_cast<int>(state.range(0));
    const rbw::SceneDef scene = dropGrid(n);
    constexpr int kSteps = 600;
    double pairsTested = 0.0;
    double pairsOverlapping = 0.0;
    for (auto _ : state) {
        state.PauseTiming();
        rbw::World world(scene);
        state.ResumeTiming();
        for (int k = 0; k < kSteps; ++k) {
            world.step(nullptr);
            pairsTested += double(world.lastBroadPhaseStats().pairsTested);
            pairsOverlapping += double(world.lastBroadPhaseStats().pairsOverlapping);
        }
        benchmark::DoNotOptimize(world.states().data());
    }
    const double steps = double(state.iterations()) * kSteps;
    // time / steps, printed with an SI prefix (e.g. "682u" = 682 microseconds per step)
    state.counters["time_per_step"] = benchmark::Counter(steps, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["pairs_tested_per_step"] = pairsTested / steps;
    state.counters["pairs_overlapping_per_step"] = pairsOverlapping / steps;
}

} // namespace

BENCHMARK(BM_DropGrid)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EulerStep, trace_off, false)->Arg(1);
BENCHMARK_CAPTURE(BM_EulerStep, trace_on, true)->Arg(1);
BENCHMARK_CAPTURE(BM_FreeBodies, collisions_off, false)->Arg(1000);
BENCHMARK_CAPTURE(BM_FreeBodies, collisions_on, true)->Arg(1000);
BENCHMARK_CAPTURE(BM_Pipeline, minimal, false)->Arg(1)->Arg(100)->Arg(1000);
BENCHMARK_CAPTURE(BM_Pipeline, all_stages, true)->Arg(1)->Arg(100)->Arg(1000);
BENCHMARK_CAPTURE(BM_Pipeline, minimal_no_energy_check, false, false)->Arg(1)->Arg(1000);

BENCHMARK_MAIN();
