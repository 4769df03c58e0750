// Cost of loading a scene file through the real loader (parseScene: JSON, the raw
// scan for duplicate keys, the structural pass, validate()) and taking one step, for
// N = 1 000, 10 000 and 100 000 bodies or planes. Results and machine:
// docs/performance.md, "Loading large scenes".
//
//   ./build/bench/rbw_bench_load
//   /usr/bin/time -v ./build/bench/rbw_bench_load --benchmark_filter='bodies/100000'   # peak memory
#include "app/scene/scene_loader.h"
#include "physics/engine/world.h"

#include <benchmark/benchmark.h>

#include <QByteArray>
#include <QString>

#include <cmath>

namespace {

// N spinning boxes named b0 ... b(N-1) on a grid 2 m apart, each pushed by a force
// that names it, so the loader resolves N names. Collisions off: the step is forces
// and integration only, and the figures are the loader's.
QByteArray bodiesScene(int n)
{
    const int side = static_cast<int>(std::ceil(std::sqrt(double(n))));
    QByteArray text;
    text.reserve(200 * qsizetype(n) + 100);
    text += R"({"name": "load bench", "dt": 0.001, "steps": 1, "box_collisions": false, "bodies": [)";
    for (int i = 0; i < n; ++i) {
        const QByteArray x = QByteArray::number(2 * (i % side));
        const QByteArray z = QByteArray::number(2 * (i / side));
        text += (i == 0 ? "" : ",") + QByteArray("\n{\"name\": \"b") + QByteArray::number(i) +
                R"(", "size": [1, 0.6, 0.5], "mass": 2, "position": [)" + x + ", 0, " + z +
                R"(], "angular_velocity": [0.1, 0.2, 0.3]})";
    }
    text += "],\n\"forces\": [";
    for (int i = 0; i < n; ++i) {
        text += (i == 0 ? "" : ",") + QByteArray("\n{\"body\": \"b") + QByteArray::number(i) +
                R"(", "point": [0.3, 0.5, 0.25], "force": [1, 1, 0]})";
    }
    text += "]}";
    return text;
}

// One box above N planes p0 ... p(N-1), each with a pair ["box", "p<i>"] that names
// it, so the loader resolves N plane names and validate() checks N pairs for repeats.
QByteArray planesScene(int n)
{
    QByteArray text;
    text.reserve(150 * qsizetype(n) + 200);
    text += R"({"name": "load bench", "dt": 0.001, "steps": 1,
"bodies": [{"name": "box", "size": [1, 1, 1], "mass": 1, "position": [0, 5, 0]}],
"planes": [)";
    for (int i = 0; i < n; ++i) {
        text += (i == 0 ? "" : ",") + QByteArray("\n{\"name\": \"p") + QByteArray::number(i) +
                R"(", "point": [0, )" + QByteArray::number(-1 - i) + R"(, 0], "normal": [0, 1, 0]})";
    }
    text += "],\n\"pairs\": [";
    for (int i = 0; i < n; ++i) {
        text += (i == 0 ? "" : ",") + QByteArray("\n{\"bodies\": [\"box\", \"p") + QByteArray::number(i) +
                R"("], "friction": 0.1})";
    }
    text += "]}";
    return text;
}

// One iteration: load the text, build the world, take one step (trace off).
void BM_LoadAndStep(benchmark::State& state, QByteArray (*scene)(int))
{
    const int n = static_cast<int>(state.range(0));
    const QByteArray text = scene(n);
    for (auto _ : state) {
        rbw::SceneLoadResult loaded = rbw::parseScene(text, QStringLiteral("bench.json"));
        if (!loaded.ok()) {
            state.SkipWithError(qPrintable(loaded.errors.join('\n')));
            return;
        }
        rbw::World world(std::move(*loaded.scene));
        world.step(nullptr);
        benchmark::DoNotOptimize(world.states().data());
    }
    state.SetBytesProcessed(state.iterations() * text.size());
    state.counters["file_MB"] = double(text.size()) / 1e6;
}

// The loader alone (parseScene), without the world and its step.
void BM_Load(benchmark::State& state, QByteArray (*scene)(int))
{
    const int n = static_cast<int>(state.range(0));
    const QByteArray text = scene(n);
    for (auto _ : state) {
        rbw::SceneLoadResult loaded = rbw::parseScene(text, QStringLiteral("bench.json"));
        if (!loaded.ok()) {
            state.SkipWithError(qPrintable(loaded.errors.join('\n')));
            return;
        }
        benchmark::DoNotOptimize(loaded.scene->bodies.data());
    }
    state.SetBytesProcessed(state.iterations() * text.size());
}

} // namespace

BENCHMARK_CAPTURE(BM_LoadAndStep, bodies, bodiesScene)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LoadAndStep, planes, planesScene)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Load, bodies, bodiesScene)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Load, planes, planesScene)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
