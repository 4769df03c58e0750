// The outcome of a step. A blow-up names the step, the body and the quantity, and
// says what to try, so no front end ever shows a non-finite number as a result.
#pragma once

#include <string>

namespace rbw {

struct StepStatus {
    bool ok = true;
    long step = -1;          // the step k in which the blow-up was detected (0 for the initial state)
    int body = -1;           // the body named; -1 when none is (the time)
    std::string bodyName;
    std::string quantity;    // trace id (e.g. "angular_velocity") or diagnostics name (e.g. "total_energy")
    std::string message;     // one readable sentence with a suggestion
    // For a trace entry with an index (which contact, probe, force, ...): the index and
    // what it counts (indexKindName, e.g. "contact"); -1 and "" otherwise.
    int index = -1;
    std::string indexKind;

    // What was detected: "non-finite" (the first NaN or infinity) or "energy-jump"
    // (a body's kinetic energy grew beyond the bound in one step; World::step).
    std::string kind;
    // Found in the initial state, before step 0 (World::checkOutputs before the first
    // step), rather than in step k.
    bool initialState = false;
    // A non-finite quantity whose cause is an input at the edge of the double range, not
    // growth over the steps (the rule: stages/checks.h). edgeInputs names them, e.g.
    // "|ω0| = 1e308"; empty when none is named.
    bool inputsAtEdge = false;
    std::string edgeInputs;
    // For an energy jump: the body's T before and after the step and the bound T_max
    // it exceeded [J]. All finite; zero for a non-finite blow-up.
    double kineticBefore = 0.0;
    double kineticAfter = 0.0;
    double kineticBound = 0.0;

    static StepStatus success() { return {}; }
};

} // namespace rbw
