// Cost of one explicit Euler step, per body, with the trace off and on, and for a
// world of many free bodies. Results and machine: docs/performance.md.
#include "physics/scene.h"
#include "physics/trace.h"
#include "physics/world.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

// N spinning, pushed boxes on a grid; no gravity, no contacts.
rbw::SceneDef freeBodies(int n, bool withForce)
{
    rbw::SceneDef s;
    s.name = "bench";
    s.dt = 1e-3;
    const int side = static_cast<int>(std::ceil(std::sqrt(double(n))));
    for (int i = 0; i < n; ++i) {
        rbw::BodyDef b;
        b.name = "b" + std::to_string(i);
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

void BM_FreeBodies(benchmark::State& state)
{
    const int n = static_cast<int>(state.range(0));
    rbw::World world(freeBodies(n, false));
    for (auto _ : state) {
        world.step(nullptr);
        benchmark::DoNotOptimize(world.states().data());
    }
    state.SetItemsProcessed(state.iterations() * n);
    state.counters["ns_per_body_step"] = benchmark::Counter(
        double(state.iterations()) * n,
        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

} // namespace

BENCHMARK_CAPTURE(BM_EulerStep, trace_off, false)->Arg(1);
BENCHMARK_CAPTURE(BM_EulerStep, trace_on, true)->Arg(1);
BENCHMARK(BM_FreeBodies)->Arg(1000);

BENCHMARK_MAIN();
