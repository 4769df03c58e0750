// Box-plane contacts (Napier practical 6, docs/references.md §4): every corner of a
// movable box below a fixed plane is a contact, resolved one impulse per corner or
// one at the corners' average (scene key plane_contacts).
#pragma once

#include "physics/engine/collision/contact.h"
#include "physics/engine/stages/stage.h"

namespace rbw {

class BoxPlaneStage final : public PipelineStep {
public:
    PipelineStage kind() const override { return PipelineStage::BoxPlane; }
    void run(StepContext& ctx) override;

private:
    std::vector<ContactGeometry> contacts_;   // scratch kept between steps
};

} // namespace rbw
