// The one small interface of the panels that follow the session's run (the plots,
// today): the shell keeps a list of them and tells each what happened, instead of
// calling each panel by name. A panel takes what it needs from the physics' own
// records (the world's diagnostics, the step's trace); it computes nothing physical.
//
//   sceneLoaded(world)    a scene was started or reset: the world at its first state
//   stepRecorded(trace)   the session took a step and recorded its trace
//   rewound(k)            the session went back to state k: later samples go
//   refresh()             the panel is due to catch up (the shell's refresh pace)
#pragma once

namespace rbw {

class World;
struct StepTrace;

class SessionPanel {
public:
    virtual ~SessionPanel() = default;

    virtual void sceneLoaded(const World& world) = 0;
    virtual void stepRecorded(const StepTrace& trace) = 0;
    // k is the world's step index after the rewind (state k, its trace is step k - 1's).
    virtual void rewound(long stepIndex) = 0;
    // By default a panel draws as it goes (the plots throttle themselves).
    virtual void refresh() {}
};

} // namespace rbw
