// The one small interface of the panels that follow the session's run (the plots, the
// quantities table, Check my numbers, the derivation): the shell keeps a list of them
// and tells each what happened, instead of calling each panel by name. A panel takes
// what it needs from the physics' own records (the world's diagnostics, the step's
// trace); it computes nothing physical.
//
//   sceneLoaded(world)    a scene was started or reset: the world at its first state
//   stepRecorded(trace)   the session took a step and recorded its trace
//   rewound(k)            the session went back to state k: later samples go
//   refresh()             the panel is due to catch up with the current step, at the
//                         pace it asks for (refreshPace(); the shell's RefreshScheduler,
//                         app/gui/shell/refresh_scheduler.h, keeps it)
#pragma once

namespace rbw {

class World;
struct StepTrace;

class SessionPanel {
public:
    // How often refresh() may run once the step has changed (PlaybackClock, app/core/
    // playback_clock.h, says when the panels are due while playing).
    enum class RefreshPace {
        AsItGoes,    // the panel draws in stepRecorded itself (the plots throttle themselves)
        PanelRate,   // while playing at the panels' rate (4 Hz), every change when paused
        WhenPaused,  // only when paused: the refresh costs more than a step
    };

    virtual ~SessionPanel() = default;

    virtual void sceneLoaded(const World& world) = 0;
    virtual void stepRecorded(const StepTrace& trace) = 0;
    // k is the world's step index after the rewind (state k, its trace is step k - 1's).
    virtual void rewound(long stepIndex) = 0;
    virtual RefreshPace refreshPace() const { return RefreshPace::AsItGoes; }
    virtual void refresh() {}
};

} // namespace rbw
