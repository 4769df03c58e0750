// Explicit Euler in exactly the order of the TUM lecture's "Simulation Algorithm 3D"
// (docs/references.md §1), first order. Position and orientation use the OLD v and
// omega; the orientation quaternion is renormalised after its update.
#pragma once

#include "physics/engine/integrator.h"

namespace rbw {

class ExplicitEuler final : public Integrator {
public:
    static constexpr const char* kName = "explicit-euler";
    const char* name() const override { return kName; }
    void advance(const BodyStep& step, BodyState& s) const override;
};

} // namespace rbw
