// Prints the measured outcome of every case x integrator (not a test: the numbers
// docs/stability.md and tst_stability pin were taken from it).
#include "stability_cases.h"
#include "physics/integrator_registry.h"
#include <cstdio>
#include <sstream>
int main()
{
    using namespace rbw;
    using namespace rbw::stability;
    const Case cases[] = {
        {"mass 1e-6", Vec3(1, 0.6, 0.5), 1e-6, Vec3(0.3, 1.0, 0.2), 0.01, 10000},
        {"mass 1", Vec3(1, 0.6, 0.5), 1.0, Vec3(0.3, 1.0, 0.2), 0.01, 10000},
        {"mass 1e6", Vec3(1, 0.6, 0.5), 1e6, Vec3(0.3, 1.0, 0.2), 0.01, 10000},
        {"needle 1000:1", Vec3(1, 1e-3, 1e-3), 1.0, Vec3(0.3, 1.0, 0.2), 0.01, 10000},
        {"plate 1000:1", Vec3(1, 1, 1e-3), 1.0, Vec3(0.3, 1.0, 0.2), 0.01, 10000},
        {"omega 1e3, h 1e-3", Vec3(1, 0.6, 0.5), 1.0, Vec3(300, 1000, 200), 1e-3, 10000},
        {"omega 1e3, h 1e-5", Vec3(1, 0.6, 0.5), 1.0, Vec3(300, 1000, 200), 1e-5, 10000},
        {"dt 1e-6", Vec3(1, 0.6, 0.5), 1.0, Vec3(0.3, 1.0, 0.2), 1e-6, 10000},
        {"dt 0.1", Vec3(1, 0.6, 0.5), 1.0, Vec3(0.3, 1.0, 0.2), 0.1, 10000},
        {"dt 1", Vec3(1, 0.6, 0.5), 1.0, Vec3(0.3, 1.0, 0.2), 1.0, 10000},
        {"1e6 steps", Vec3(1, 0.6, 0.5), 1.0, Vec3(0.3, 1.0, 0.2), 0.01, 1000000},
    };
    std::istringstream names(integratorNames());
    std::vector<std::string> list;
    for (std::string n; std::getline(names, n, ',');) {
        while (!n.empty() && n.front() == ' ') n.erase(0, 1);
        list.push_back(n);
    }
    for (const Case& c : cases) {
        for (const std::string& n : list) {
            const Outcome o = run(freeBodyScene(c, n));
            std::printf("%-20s %-34s ok=%d step=%ld %-12s maxdT=%.3g endT=%.3g maxdL=%.3g ortho=%.3g\n", c.id,
                        n.c_str(), int(o.ok), o.blowUpStep, o.kind.c_str(), o.maxRelEnergy, o.endRelEnergy,
                        o.maxRelL, o.maxOrtho);
            std::fflush(stdout);
        }
    }
}
