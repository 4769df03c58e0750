// N explicit Euler steps of BM_EulerStep's one-body scene (bench_step.cpp), trace off,
// and nothing else: a fixed amount of work for an instruction count, which, unlike a
// timing, does not change with the load of the machine (docs/performance.md):
//   valgrind --tool=callgrind ./build/bench/rbw_step_driver 100000
//   valgrind --tool=callgrind ./build/bench/rbw_step_driver 200000
// The difference of the two totals over 100 000 is the instruction count of one step.
#include "physics/engine/scene.h"
#include "physics/engine/world.h"

#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv)
{
    const long steps = argc > 1 ? std::atol(argv[1]) : 100000;
    rbw::SceneDef s;
    s.name = "bench";
    s.dt = 1e-3;
    s.boxCollisions = false;
    rbw::BodyDef b;
    b.name = "b0";
    b.size = rbw::Vec3(1.0, 0.6, 0.5);
    b.mass = 2.0;
    b.omega0_W = rbw::Vec3(0.1, 0.2, 0.3);
    b.v0_W = rbw::Vec3(0.0, 1.0, 0.0);
    s.bodies.push_back(b);
    rbw::ForceDef f;
    f.body = 0;
    f.p_W = rbw::Vec3(0.3, 0.5, 0.25);
    f.f_W = rbw::Vec3(1.0, 1.0, 0.0);
    f.fromStep = 0;
    f.toStep = 1L << 40;   // acts in every step
    s.forces.push_back(f);
    rbw::World world(s);
    for (long i = 0; i < steps; ++i) {
        if (!world.step(nullptr).ok) return 1;
    }
    std::printf("x after %ld steps: %.17g\n", steps, world.states()[0].x_W.x());
    return 0;
}
