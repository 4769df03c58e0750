// reference_simulator.cpp: a rigid-body simulator written the way a careful student
// writes the TUM course algorithm, speaking the workbook's simulator protocol
// (docs/simulator-protocol.md) on stdin/stdout. Standalone C++17: no project code, no
// Eigen; build it on its own with
//   g++ -std=c++17 -O2 -ffp-contract=off reference_simulator.cpp -o reference_simulator
// Its parts, one concept each:
//   vec_math.h             Vec3, quaternion, 3x3 matrix, R(r)
//   mistakes.h             the mistake switches (--mistake ID)
//   box_box_sat.h          the template's box-box test
//   reference_simulator.h  the bodies and the step (integration, impulse)
//   command_line.h         the options and the number syntax
//   this file              the protocol loop: commands in, state answers out
// README.md lists the flags and the mistake models with their equations; `--float`
// computes everything in float, as the template does.
//
// reference_simulator.py is the same program in Python; the two give the same
// numbers because every expression is evaluated in the same order (keep it so).
#include "command_line.h"
#include "reference_simulator.h"
#include "vec_math.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

using rbwref::die;
using rbwref::Fail;
using rbwref::kProgram;
using rbwref::Options;
using rbwref::parseNumber;

template <typename Real>
int run(const Options& options)
{
    using V = rbwref::Vec3<Real>;
    rbwref::ReferenceSimulator<Real> sim(options.mistakes, Real(options.restitution), options.trace);
    const char* const format = sizeof(Real) == sizeof(float) ? "%.9g" : "%.17g";
    int lineNo = 0;
    int stateAnswers = 0;
    bool stepped = false;
    std::string line;
    while (std::getline(std::cin, line)) {
        ++lineNo;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream in(line);
        std::vector<std::string> tokens;
        for (std::string t; in >> t;) tokens.push_back(t);
        if (tokens.empty()) continue;   // blank lines are ignored
        const std::string& command = tokens[0];
        const std::string where = "line " + std::to_string(lineNo) + ": ";

        // The command's arguments: a body index and/or numbers.
        const auto expectCount = [&](size_t count, const char* usage) {
            if (tokens.size() - 1 != count) {
                die(where + command + " needs " + std::to_string(count) + " argument" + (count == 1 ? "" : "s") +
                    " (" + usage + "), got " + std::to_string(tokens.size() - 1));
            }
        };
        const auto number = [&](size_t k) -> Real {
            double value = 0;
            if (!parseNumber(tokens[k], value)) {
                die(where + command + ": '" + tokens[k] + "' is not a finite decimal number");
            }
            return Real(value);
        };
        const auto bodyIndex = [&](size_t k) -> int {
            const std::string& t = tokens[k];
            bool digits = !t.empty() && t.size() < 10;
            for (char ch : t) digits = digits && std::isdigit(static_cast<unsigned char>(ch));
            if (!digits) die(where + command + ": body index '" + t + "' is not a whole number >= 0");
            const int i = std::atoi(t.c_str());
            if (i >= sim.bodyCount()) {
                die(where + command + ": there is no body " + t + " (the scene has " +
                    std::to_string(sim.bodyCount()) + " bod" + (sim.bodyCount() == 1 ? "y" : "ies") + ")");
            }
            return i;
        };
        const auto vec = [&](size_t k) -> V { return V{number(k), number(k + 1), number(k + 2)}; };

        if (command == "reset") {
            expectCount(0, "");
            sim.reset();
        } else if (command == "add_body") {
            expectCount(7, "X Y Z SX SY SZ MASS");
            const V x_W = vec(1);
            const V size = vec(4);
            if (!(size.x > 0 && size.y > 0 && size.z > 0)) die(where + "add_body: the size must be positive");
            const std::string& m = tokens[7];
            bool whole = !m.empty() && m.size() < 10;
            for (size_t k = 0; k < m.size(); ++k)
                whole = whole && (std::isdigit(static_cast<unsigned char>(m[k])) || (k == 0 && m[k] == '+'));
            if (!whole || std::atoi(m.c_str()) <= 0) {
                die(where + "add_body: the mass '" + m + "' is not a whole number > 0 (the template takes an int)");
            }
            sim.addBody(x_W, size, Real(std::atoi(m.c_str())));
        } else if (command == "set_orientation") {
            expectCount(5, "I W X Y Z");
            const int i = bodyIndex(1);
            const rbwref::Quat<Real> q{number(2), number(3), number(4), number(5)};
            if (!(rbwref::norm(q) > 0)) die(where + "set_orientation: the quaternion is zero");
            sim.setOrientation(i, q);
        } else if (command == "set_velocity") {
            expectCount(4, "I VX VY VZ");
            const int i = bodyIndex(1);
            sim.setVelocity(i, vec(2));
        } else if (command == "apply_force") {
            expectCount(7, "I PX PY PZ FX FY FZ");
            const int i = bodyIndex(1);
            sim.applyForce(i, vec(2), vec(5));
        } else if (command == "step") {
            expectCount(1, "H");
            const Real h = number(1);
            if (!(h > 0)) die(where + "step: the time step must be > 0");
            sim.step(h);
            if (!stepped && options.fail == Fail::Exit) {
                std::fprintf(stderr, "%s: --fail exit: exiting with status 1 after the first step\n", kProgram);
                return 1;
            }
            if (!stepped && options.fail == Fail::Hang) {
                // Never answer again, and never exit: a driver must time out.
                for (;;) std::this_thread::sleep_for(std::chrono::hours(1));
            }
            stepped = true;
        } else if (command == "state") {
            expectCount(1, "I");
            const int i = bodyIndex(1);
            ++stateAnswers;
            std::string answer;
            if (options.fail == Fail::Garbage) {
                answer = "hello";
            } else {
                const std::vector<Real> s = sim.state(i);
                for (size_t k = 0; k < s.size(); ++k) {
                    char buffer[64];
                    if (options.fail == Fail::Nan && stateAnswers == 2) {
                        std::snprintf(buffer, sizeof buffer, "nan");
                    } else {
                        std::snprintf(buffer, sizeof buffer, format, double(s[k]));
                    }
                    if (k > 0) answer += ' ';
                    answer += buffer;
                }
            }
            std::printf("%s\n", answer.c_str());
            std::fflush(stdout);
        } else if (command == "quit") {
            expectCount(0, "");
            return 0;
        } else {
            die(where + "unknown command '" + command +
                "' (valid: reset, add_body, set_orientation, set_velocity, apply_force, step, state, quit)");
        }
    }
    return 0;
}

}   // namespace

int main(int argc, char** argv)
{
    const Options options = rbwref::parseOptions(argc, argv);
    return options.useFloat ? run<float>(options) : run<double>(options);
}
