// One manifold step on a pile of N boxes: time and peak memory (issue 22, item 4;
// docs/performance.md, "Piles: the manifold model's work limits").
//
//   coincident N   N unit boxes at one point on the ground: every bounding box overlaps
//                  every other one. The step stops at the limit of contact pairs per
//                  body (physics/engine/manifold/work_limits.h); before the limits it
//                  built N (N - 1) / 2 manifolds.
//   lattice N      N unit boxes in a touching block 10 boxes wide and deep, on the
//                  ground: a dense pile the limits allow; the step runs in full.
//
// Each case runs in a process of its own, so that its peak resident size
// (getrusage ru_maxrss) is its own: `rbw_bench_pile` with no arguments runs every case
// in a child (fork + exec of itself) and prints one line per case;
// `rbw_bench_pile coincident 1000` runs one. Times are the step's wall time and the
// process's CPU time (the machine is shared).
#include "physics/engine/world.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

namespace {

rbw::SceneDef pileScene(bool coincident, int n)
{
    rbw::SceneDef s;
    s.name = "pile";
    s.dt = 1.0 / 60.0;
    s.steps = 1;
    s.integrator = "symplectic-euler";
    s.g_W = rbw::Vec3(0.0, -9.81, 0.0);
    s.friction = 0.5;
    s.contactModel = rbw::ContactModel::Manifold;
    rbw::PlaneDef ground;
    ground.name = "ground";
    s.planes.push_back(ground);
    for (int i = 0; i < n; ++i) {
        rbw::BodyDef b;
        b.name = "b";
        b.name += std::to_string(i);
        b.size = rbw::Vec3::Ones();
        b.mass = 1.0;
        // lattice: x = i mod 10, z = (i / 10) mod 10, y = 0.5 + i / 100 (faces touch)
        b.x0_W = coincident ? rbw::Vec3(0.0, 0.5, 0.0)
                            : rbw::Vec3(double(i % 10), 0.5 + double(i / 100), double((i / 10) % 10));
        s.bodies.push_back(b);
    }
    return s;
}

double cpuSeconds()
{
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

int runOne(const char* kind, int n)
{
    const bool coincident = std::strcmp(kind, "coincident") == 0;
    rbw::World world(pileScene(coincident, n));
    const auto wall0 = std::chrono::steady_clock::now();
    const double cpu0 = cpuSeconds();
    const rbw::StepStatus status = world.step();
    const double cpu = cpuSeconds() - cpu0;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::printf("%-10s %5d  step %9.1f ms wall %9.1f ms cpu  peak %7.1f MiB  %s\n", kind, n, 1000.0 * wall,
                1000.0 * cpu, double(usage.ru_maxrss) / 1024.0,
                status.ok ? "ok" : (status.kind + " " + status.quantity).c_str());
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc == 3) return runOne(argv[1], std::atoi(argv[2]));
    for (const char* kind : {"coincident", "lattice"}) {
        for (const char* n : {"300", "1000", "2000"}) {
            std::fflush(stdout);
            const pid_t pid = fork();
            if (pid == 0) {
                char* args[] = {argv[0], const_cast<char*>(kind), const_cast<char*>(n), nullptr};
                execv("/proc/self/exe", args);
                _exit(127);
            }
            int wstatus = 0;
            waitpid(pid, &wstatus, 0);
            if (!WIFEXITED(wstatus) || WEXITSTATUS(wstatus) != 0) std::printf("%-10s %5s  failed\n", kind, n);
        }
    }
    return 0;
}
