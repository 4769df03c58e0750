// One step numbering on every screen (docs/user-guide.md, "Step numbers"), the
// course's: steps are numbered k = 0, 1, 2, ...; step k takes the state at t_k to
// t_{k+1}; after n steps the time is t_n and the screen shows the last step taken,
// step k = n - 1. The 3D view's top line, the history slider, the status bar, the
// derivation's heading, Check my numbers and the quantities table all word it here.
#pragma once

#include <QString>

namespace rbw::steps {

// "t₃": t with the state's index n as subscript digits.
QString timeName(long n);

// "step k = 2 (t₂ → t₃)": step k with the times it goes between.
QString stepSpan(long k);

// The state after n steps, by the step that led to it: "after step k = 2"; for n = 0,
// "before step k = 0".
QString stateName(long n);

// The state a step starts from: "before step k = 0".
QString beforeStep(long k);

// "1 step taken", "3 steps taken".
QString stepsTaken(long n);

} // namespace rbw::steps
