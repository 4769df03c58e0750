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

    static StepStatus success() { return {}; }
};

} // namespace rbw
