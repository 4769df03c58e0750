// The generic derivation for a lesson without derivation.md: every traced quantity
// of the step, grouped by stage and then by body (or by contact), as
// "formula = value". Read from the trace only.
#pragma once

#include "physics/engine/scene.h"
#include "physics/engine/trace.h"

#include <QString>

namespace rbw {

// The HTML body (headings and rows, no document skeleton; see derivation_page.h).
QString fallbackDerivationBody(const StepTrace& trace, const SceneDef& scene, int digits = 7);

// "box", or "body 3" when the index has no name; "plane ground" for a plane.
QString bodyLabel(const SceneDef& scene, int body);
QString contactTitle(const SceneDef& scene, const ContactHeader& header, int k);

} // namespace rbw
