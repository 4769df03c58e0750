// Cost of one integration step per body for every registered integrator: 1000 free
// asymmetric boxes (size 1 x 0.6 x 0.5, so I0 has three different moments), spinning,
// no forces, no gravity, collisions off, trace off. The world's forces stage runs too
// (it only clears the loads here), so the numbers are what a scene pays per body-step.
// After the runs a table gives ns per body-step and the ratio to explicit Euler.
// Results and machine: docs/integrators.md.
#include "physics/engine/integrator_registry.h"
#include "physics/engine/scene.h"
#include "physics/engine/world.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace {

constexpr int kBodies = 1000;

rbw::SceneDef freeAsymmetricBodies(const std::string& integrator)
{
    rbw::SceneDef s;
    s.name = "bench integrators";
    s.dt = 1e-3;
    s.integrator = integrator;
    s.boxCollisions = false;
    const int side = static_cast<int>(std::ceil(std::sqrt(double(kBodies))));
    for (int i = 0; i < kBodies; ++i) {
        rbw::BodyDef b;
        b.name = "b";
        b.name += std::to_string(i);
        b.size = rbw::Vec3(1.0, 0.6, 0.5);
        b.mass = 2.0;
        b.x0_W = rbw::Vec3(2.0 * (i % side), 0.0, 2.0 * (i / side));
        b.q0_WB = rbw::Quat(Eigen::AngleAxisd(0.3 * i, rbw::Vec3(1, 2, 3).normalized()));
        b.omega0_W = rbw::Vec3(0.1, 2.0, 0.3);
        b.v0_W = rbw::Vec3(0.0, 1.0, 0.0);
        s.bodies.push_back(b);
    }
    return s;
}

void BM_Integrator(benchmark::State& state, const std::string& name)
{
    rbw::World world(freeAsymmetricBodies(name));
    for (auto _ : state) {
        world.step(nullptr);
        benchmark::DoNotOptimize(world.states().data());
    }
    state.SetItemsProcessed(state.iterations() * kBodies);   // body-steps
    state.counters["ns_per_body_step"] = benchmark::Counter(
        double(state.iterations()) * kBodies, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// Console output as usual, and the ns per body-step of each run kept for the table.
class TableReporter : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override
    {
        for (const Run& r : runs) {
            if (r.run_type == Run::RT_Iteration && !r.error_occurred && r.iterations > 0) {
                // CPU time per iteration (seconds) / bodies -> ns per body-step (CPU time, as
                // the ns_per_body_step counter, so a busy shared machine skews it less)
                const double seconds = r.cpu_accumulated_time / double(r.iterations);
                nsPerBodyStep[r.benchmark_name()] = seconds * 1e9 / kBodies;
            }
        }
        ConsoleReporter::ReportRuns(runs);
    }
    std::map<std::string, double> nsPerBodyStep;
};

} // namespace

int main(int argc, char** argv)
{
    std::vector<std::string> names;
    for (const rbw::IntegratorInfo& info : rbw::integratorCatalogue()) {
        names.emplace_back(info.name);
        benchmark::RegisterBenchmark(("BM_Integrator/" + names.back()).c_str(), BM_Integrator, names.back());
    }
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) {
        return 1;
    }
    TableReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);

    // ns per body-step and the ratio to explicit Euler, as a Markdown table
    double euler = 0.0;
    for (const auto& [key, ns] : reporter.nsPerBodyStep) {
        if (key == "BM_Integrator/explicit-euler") {
            euler = ns;
        }
    }
    std::printf("\n| integrator | ns per body-step | ratio to explicit-euler |\n| --- | ---: | ---: |\n");
    for (const std::string& name : names) {
        for (const auto& [key, ns] : reporter.nsPerBodyStep) {
            if (key.size() >= name.size() + 1 && key.compare(key.size() - name.size() - 1, std::string::npos,
                                                             "/" + name) == 0) {
                std::printf("| `%s` | %.1f | %.2f |\n", name.c_str(), ns, euler > 0.0 ? ns / euler : 0.0);
            }
        }
    }
    benchmark::Shutdown();
    return 0;
}
