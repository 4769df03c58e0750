// The box rain of issue 19 (item 6) in every engine in one run: our manifold model's
// solvers, Bullet 3.24 (Debian's libbullet-dev, when CMake finds it) and Rapier (its
// official WebAssembly port, @dimforge/rapier3d-compat pinned in bench/package.json, run
// under Node.js; rapier_rain.mjs). The same initial poses and the same outcome analysis
// for every engine (rain_scene.h): KE, boxes faster than 0.01 and 0.1 m/s, sleeping,
// deepest box-box overlap, deepest corner below the ground, mean height, and the largest
// drift in the last second.
//
// Time: the wall time of the 600 steps around the step calls only (world.step(),
// stepSimulation(), Rapier's world.step() measured inside Node), per step. The machine
// is shared with builds, so the engines run in interleaved rounds (round r runs every
// engine once, in the same order) and the table gives the median and the range over
// the rounds; the load average is printed before and after each round.
//
// Engines that are not available are skipped with what is missing: Bullet without
// libbullet-dev at configure time; Rapier without `node` on the PATH or without the
// package (`npm ci` in bench/, which puts it in bench/node_modules, kept out of git).
//
// Run: ./build/bench/rbw_bench_rain [--rounds R] [--boxes N]   (R = 3, N = 1000)
// Results and method: docs/performance.md, "Three engines"; docs/accuracy-lab.md.
#include "bench/rain_scene.h"
#include "physics/engine/manifold/work_limits.h"
#include "physics/engine/world.h"

#ifdef RBW_HAVE_BULLET
#include "bench/rain_bullet.h"
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

namespace {

using rain::FinalBox;
using rain::ourBoxes;
using rain::RainBox;

// Our solvers: one line each. The manifold model's solver settings go into the scene
// through `configure` (nullptr: the defaults); `threads`: WorldOptions::contactThreads
// (the soft step's islands on two threads; Bullet and Rapier's WebAssembly port run on one).
struct OurSolver {
    const char* name;
    const char* integrator;
    void (*configure)(rbw::SceneDef&);
    int threads = 2;
};
constexpr OurSolver kOurSolvers[] = {
    {"rbw sequential impulses, symplectic Euler", "symplectic-euler",
     [](rbw::SceneDef& s) { s.solver = rbw::ManifoldSolver::SequentialImpulses; }},
    {"rbw sequential impulses, explicit Euler", "explicit-euler",
     [](rbw::SceneDef& s) { s.solver = rbw::ManifoldSolver::SequentialImpulses; }},
    {"rbw soft step, symplectic Euler", "symplectic-euler",
     [](rbw::SceneDef& s) { s.solver = rbw::ManifoldSolver::SoftStep; }},
    {"rbw soft step, explicit Euler", "explicit-euler", [](rbw::SceneDef& s) { s.solver = rbw::ManifoldSolver::SoftStep; }},
    {"rbw soft step, symplectic Euler, 1 thread", "symplectic-euler",
     [](rbw::SceneDef& s) { s.solver = rbw::ManifoldSolver::SoftStep; }, 1},
};

// What one run of one engine gives: ms per step, the boxes one second before the end and
// at the end; or why it was skipped.
struct Run {
    double msPerStep = 0.0;
    std::vector<FinalBox> before;
    std::vector<FinalBox> after;
    std::string skipped;   // non-empty: not run, and why
};

struct Engine {
    std::string name;
    std::function<Run(const std::vector<RainBox>&)> run;
};

double wallSeconds()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string loadAverage()
{
    std::ifstream f("/proc/loadavg");
    std::string one, five, fifteen;
    f >> one >> five >> fifteen;
    return one + " " + five + " " + fifteen;
}

// ---- ours

Run runOurs(const OurSolver& solver, int n)
{
    rbw::SceneDef scene = rain::rainScene(n, rbw::ContactModel::Manifold, solver.integrator);
    if (solver.configure != nullptr) solver.configure(scene);
    rbw::WorldOptions options;
    options.contactThreads = solver.threads;
    rbw::World world(std::move(scene), options);
    Run r;
    double seconds = 0.0;
    for (int k = 1; k <= rain::kSteps; ++k) {
        const double start = wallSeconds();
        const rbw::StepStatus& status = world.step(nullptr);
        seconds += wallSeconds() - start;
        if (!status.ok) {
            r.skipped = "stopped in step " + std::to_string(k) + ": " + status.message;
            return r;
        }
        if (k == rain::kLastSecond) r.before = ourBoxes(world);
    }
    r.msPerStep = 1000.0 * seconds / rain::kSteps;
    r.after = ourBoxes(world);
    return r;
}

// ---- Bullet (as bench_contact.cpp sets it up: default solver, DBVT broad phase, a
// static plane, friction sqrt(0.5) per body so the pair's product is 0.5, no sleeping)

#ifdef RBW_HAVE_BULLET
Run runBullet(const std::vector<RainBox>& poses)
{
    rain::BulletRain bullet(poses);
    Run r;
    double seconds = 0.0;
    for (int k = 1; k <= rain::kSteps; ++k) {
        const double start = wallSeconds();
        bullet.step();
        seconds += wallSeconds() - start;
        if (k == rain::kLastSecond) r.before = bullet.boxes();
    }
    r.msPerStep = 1000.0 * seconds / rain::kSteps;
    r.after = bullet.boxes();
    return r;
}
#endif

// ---- Rapier, in Node.js

// Reads one box a line, "x y z qw qx qy qz vx vy vz wx wy wz asleep", `count` lines.
bool readBoxes(std::istream& in, int count, std::vector<FinalBox>& out)
{
    for (int i = 0; i < count; ++i) {
        double x, y, z, qw, qx, qy, qz, vx, vy, vz, wx, wy, wz;
        int asleep = 0;
        if (!(in >> x >> y >> z >> qw >> qx >> qy >> qz >> vx >> vy >> vz >> wx >> wy >> wz >> asleep)) return false;
        const rbw::Quat q_WB = rbw::Quat(qw, qx, qy, qz).normalized();
        out.push_back(FinalBox{rbw::BoxPose{rbw::Vec3(x, y, z), q_WB.toRotationMatrix(), rbw::Vec3::Constant(0.5)},
                               rbw::Vec3(vx, vy, vz), rbw::Vec3(wx, wy, wz), asleep != 0});
    }
    return true;
}

Run runRapier(const std::vector<RainBox>& poses)
{
    Run r;
    if (std::system("command -v node > /dev/null 2>&1") != 0) {
        r.skipped = "node (Node.js) is not on the PATH";
        return r;
    }
    char posesPath[] = "/tmp/rbw_rain_posesXXXXXX";
    const int fd = mkstemp(posesPath);
    if (fd < 0) {
        r.skipped = "cannot create a temporary file for the poses";
        return r;
    }
    close(fd);
    {
        std::ofstream posesFile(posesPath);
        posesFile.precision(17);
        for (const RainBox& b : poses) {
            posesFile << b.x_W.x() << ' ' << b.x_W.y() << ' ' << b.x_W.z() << ' ' << b.q_WB.w() << ' ' << b.q_WB.x()
                      << ' ' << b.q_WB.y() << ' ' << b.q_WB.z() << '\n';
        }
    }
    char hText[32];
    std::snprintf(hText, sizeof hText, "%.17g", rain::kH);
    const std::string command = std::string("node '") + RBW_SOURCE_DIR + "/bench/rapier_rain.mjs' '" + posesPath +
                                "' " + std::to_string(rain::kSteps) + " " + hText + " 2>&1";
    std::string output;
    FILE* pipe = popen(command.c_str(), "r");
    if (pipe != nullptr) {
        char buf[65536];
        for (std::size_t got; (got = std::fread(buf, 1, sizeof buf, pipe)) > 0;) output.append(buf, got);
    }
    const int status = pipe != nullptr ? pclose(pipe) : -1;
    std::remove(posesPath);
    if (status != 0) {
        r.skipped = WIFEXITED(status) && WEXITSTATUS(status) == 3
                        ? "@dimforge/rapier3d-compat is not installed (npm ci in bench/)"
                        : "node failed: " + output.substr(0, 300);
        return r;
    }
    std::istringstream in(output);
    std::string word;
    int at = 0;
    const int n = static_cast<int>(poses.size());
    if (!(in >> word >> r.msPerStep) || word != "ms_per_step" || !(in >> word >> at) || word != "at" ||
        !readBoxes(in, n, r.before) || !(in >> word >> at) || word != "at" || !readBoxes(in, n, r.after)) {
        r.skipped = "cannot read what rapier_rain.mjs printed: " + output.substr(0, 300);
    }
    return r;
}

// ---- the census of candidate pairs (work_limits.h): per step, the AABBs grown by the
// manifold model's margin (0.02 m), the most pairs of one box and the pairs per box

void pairCensus(int n)
{
    rbw::World world(rain::rainScene(n, rbw::ContactModel::Manifold));
    int mostOfOneBox = 0;
    double mostPerBox = 0.0;
    rbw::AabbTree tree;
    std::vector<rbw::Aabb> aabbs(static_cast<std::size_t>(n));
    std::vector<std::pair<int, int>> pairs;
    rbw::BroadPhaseStats stats;
    const std::vector<char> movable(static_cast<std::size_t>(n), 1);
    for (int k = 0; k < rain::kSteps && world.step(nullptr).ok; ++k) {
        std::vector<int> count(static_cast<std::size_t>(n), 0);
        for (int b = 0; b < n; ++b) {
            const rbw::BodyState& s = world.states()[static_cast<std::size_t>(b)];
            rbw::Aabb box = rbw::boxAabb(rbw::BoxPose{s.x_W, s.R_WB, rbw::Vec3::Constant(0.5)});
            box.min_W -= rbw::Vec3::Constant(0.02);
            box.max_W += rbw::Vec3::Constant(0.02);
            aabbs[static_cast<std::size_t>(b)] = box;
        }
        tree.findPairs(aabbs, movable, pairs, stats);
        for (const auto& [i, j] : pairs) {
            ++count[static_cast<std::size_t>(i)];
            ++count[static_cast<std::size_t>(j)];
        }
        mostOfOneBox = std::max(mostOfOneBox, *std::max_element(count.begin(), count.end()));
        mostPerBox = std::max(mostPerBox, double(pairs.size()) / n);
    }
    std::printf("\nCandidate pairs in our rain (symplectic Euler, margin 0.02 m), the most in any step:\n"
                "  pairs of one box %d (limit %d), pairs per box %.2f (limit %d per movable body)\n",
                mostOfOneBox, rbw::kMaxPairsPerBody, mostPerBox, rbw::kMaxPairsPerBodyAverage);
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    const std::size_t m = v.size() / 2;
    return v.size() % 2 == 1 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

} // namespace

int main(int argc, char** argv)
{
    int rounds = 3;
    int n = 1000;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (std::strcmp(argv[i], "--rounds") == 0) rounds = std::max(1, std::atoi(argv[i + 1]));
        if (std::strcmp(argv[i], "--boxes") == 0) n = std::max(1, std::atoi(argv[i + 1]));
    }
    const std::vector<RainBox> poses = rain::rainPoses(n);
    std::vector<Engine> engines;
    for (const OurSolver& solver : kOurSolvers) {
        engines.push_back(Engine{solver.name, [&solver, n](const std::vector<RainBox>&) { return runOurs(solver, n); }});
    }
#ifdef RBW_HAVE_BULLET
    engines.push_back(Engine{"Bullet 3.24 (Debian), sequential impulses", runBullet});
#else
    std::printf("skipped: Bullet (libbullet-dev was not found when the benchmark was configured)\n");
#endif
    engines.push_back(Engine{"Rapier 0.21.0 (WebAssembly, Node.js), defaults", runRapier});

    std::printf("The box rain: %d boxes, h = 1/60 s, %d steps, %d interleaved rounds\n", n, rain::kSteps, rounds);
    std::vector<std::vector<double>> times(engines.size());
    std::vector<rain::Outcome> outcomes(engines.size());
    std::vector<std::string> skipped(engines.size());
    for (int round = 1; round <= rounds; ++round) {
        std::printf("round %d, load average before: %s\n", round, loadAverage().c_str());
        for (std::size_t e = 0; e < engines.size(); ++e) {
            if (!skipped[e].empty()) continue;
            std::fflush(stdout);
            const Run r = engines[e].run(poses);
            if (!r.skipped.empty()) {
                skipped[e] = r.skipped;
                std::printf("  skipped: %s: %s\n", engines[e].name.c_str(), r.skipped.c_str());
                continue;
            }
            times[e].push_back(r.msPerStep);
            std::printf("  %-48s %7.2f ms/step\n", engines[e].name.c_str(), r.msPerStep);
            if (round == 1) outcomes[e] = rain::measure(r.after, r.before);
        }
    }
    std::printf("load average after: %s\n\n", loadAverage().c_str());
    std::printf("| engine | ms/step, median (range) | KE [J] | > 0.01 m/s | > 0.1 m/s | asleep | box-box overlap [cm] "
                "| below ground [mm] | mean height [m] | drift in the last second [cm] |\n");
    std::printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    for (std::size_t e = 0; e < engines.size(); ++e) {
        if (times[e].empty()) continue;
        const rain::Outcome& o = outcomes[e];
        std::printf("| %s | %.2f (%.2f–%.2f) | %.3g | %d | %d | %d | %.2f | %.1f | %.3f | %.2f |\n", engines[e].name.c_str(),
                    median(times[e]), *std::min_element(times[e].begin(), times[e].end()),
                    *std::max_element(times[e].begin(), times[e].end()), o.kineticEnergy, o.moving, o.moving01,
                    o.sleeping, 100.0 * o.overlap, 1000.0 * o.below, o.meanHeight, 100.0 * o.drift);
    }
    pairCensus(n);
    return 0;
}
