// Prints the measured outcome of every case x integrator (not a test: the numbers
// docs/stability.md and tst_stability pin were taken from it).
#include "stability_cases.h"
#include "physics/engine/integrator_registry.h"
#include <cstdio>
#include <sstream>
int main()
{
    using namespace rbw;
    using namespace rbw::stability;
    std::istringstream names(integratorNames());
    std::vector<std::string> list;
    for (std::string n; std::getline(names, n, ',');) {
        while (!n.empty() && n.front() == ' ') n.erase(0, 1);
        list.push_back(n);
    }
    for (const Case& c : kCases) {
        for (const std::string& n : list) {
            const Outcome o = run(freeBodyScene(c, n));
            std::printf("%-20s %-34s ok=%d step=%ld %-12s maxdT=%.3g endT=%.3g maxdL=%.3g ortho=%.3g\n", c.id,
                        n.c_str(), int(o.ok), o.blowUpStep, o.kind.c_str(), o.maxRelEnergy, o.endRelEnergy,
                        o.maxRelL, o.maxOrtho);
            std::fflush(stdout);
        }
    }
}
