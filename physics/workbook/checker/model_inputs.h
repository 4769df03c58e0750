// The inputs of the hand calculations of mistakes.h for one step of a world: a body at
// the start of its explicit Euler step, and a contact as this step's trace records it.
#pragma once

#include "physics/workbook/checker/mistakes.h"

namespace rbw {
class World;
}

namespace rbw::checking {

// Body b at the start of the step (`before`: the world then), with the forces, couples
// and probes that act in it.
BodyStepInputs bodyStepInputs(const World& before, int b);

// Contact k of the step: the recorded point velocities enter as v (no spin), I^-1 as
// after the integration (zero for a fixed side or a particle response).
ContactInputs contactStepInputs(const World& before, const StepTrace& trace, int k);

} // namespace rbw::checking
