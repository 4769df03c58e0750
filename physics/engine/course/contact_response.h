// One contact's response, shared by the box-box and box-plane stages: the pair's c and
// mu (with the resting-contact threshold), the impulse with friction
// (course/impulse.cpp, which records its own numbers), and a queued position
// correction for a penetrating box pair (position_correction).
#pragma once

#include "physics/engine/collision/contact.h"
#include "physics/engine/stages/stage.h"

namespace rbw {

// Resolves one contact between body a and body b (or plane when b < 0 and plane >= 0)
// and records its header and numbers as contact number ctx.scratch.contactCount++.
// resolution: "single-point" (SAT), "per-point" or "average" (planes); pointCount: the
// corners averaged into it.
void resolveContact(StepContext& ctx, const ContactGeometry& g, int a, int b, int plane, const char* resolution,
                    int pointCount);

// The pose of a body as a box: centre, rotation, half extents.
BoxPose poseOf(const StepContext& ctx, int body);

} // namespace rbw
