// The derivation of a many-body scene writes out one body at a time: its own rows,
// the world-level rows and the contacts it takes part in. This file says when a
// scene is written out that way, which body it follows, and selects that body's part
// of a trace. A selection of the recorded entries: nothing is recomputed.
#pragma once

#include "physics/engine/scene.h"
#include "physics/engine/trace.h"

namespace rbw {

// Scenes with more bodies than this write out one body (and its contacts) at a time.
inline constexpr int kDerivationAllBodiesMax = 6;

// The body the derivation of this scene follows: -1 when the scene is small enough to
// write out every body; else `wanted` (the body last grabbed) if it is a body of the
// scene, else the first movable body (the last body if all are fixed).
int derivationFocusBody(const SceneDef& scene, int wanted);

// The part of a trace about one body: its own rows, the world-level rows (body -1),
// and the contacts it takes part in, renumbered 0, 1, ... in their order, with their
// headers. Step, time and diagnostics are kept.
StepTrace focusTrace(const StepTrace& trace, int body);

// The contacts focusTrace keeps, by their number in the whole trace: contact c of the
// selection is contact focusContacts(trace, body)[c] of `trace`.
std::vector<int> focusContacts(const StepTrace& trace, int body);

} // namespace rbw
