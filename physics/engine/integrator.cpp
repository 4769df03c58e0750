#include "physics/engine/integrator.h"

namespace rbw {

void Integrator::integrate(const IntegrationInput& in, std::vector<BodyState>& states, StepTrace* trace) const
{
    const bool fromMatrix = derivedFrom() == Derived::FromMatrix;
    for (int b = 0; b < static_cast<int>(states.size()); ++b) {
        if (!in.advances(b)) {
            continue;
        }
        const BodyStep step{b, in.h, in.mass[b], in.loads[b], in.conventionOf(b), trace};
        BodyState& s = states[b];
        // The integrator's own update of x, v, r (or R) and L.
        advance(step, s);
        // R = R(r), I^-1 = R I0^-1 R^T (or R^T I0^-1 R), omega = I^-1 L, and their rows.
        if (fromMatrix) {
            updateDerivedFromMatrix(step.mp, s, step.convention, trace, b);
        } else {
            updateDerived(step.mp, s, step.convention, trace, b);
        }
    }
}

} // namespace rbw
