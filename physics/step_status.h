// The outcome of a step. A blow-up names the step, the body and the quantity, and
// says what to try, so no front end ever shows a non-finite number as a result.
#pragma once

#include <string>

namespace rbw {

struct StepStatus {
    bool ok = true;
    long step = -1;          // the step k in which the blow-up was detected
    int body = -1;
    std::string bodyName;
    std::string quantity;    // trace id, e.g. "angular_velocity"
    std::string message;     // one readable sentence with a suggestion

    // What was detected: "non-finite" (the first NaN or infinity) or "energy-jump"
    // (a body's kinetic energy grew beyond the bound in one step; World::step).
    std::string kind;
    // For an energy jump: the body's T before and after the step and the bound T_max
    // it exceeded [J]. All finite; zero for a non-finite blow-up.
    double kineticBefore = 0.0;
    double kineticAfter = 0.0;
    double kineticBound = 0.0;

    static StepStatus success() { return {}; }
};

} // namespace rbw
