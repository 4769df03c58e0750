// The panels that follow the run (SessionPanel, app/core/session_panel.h), told in turn
// of every new scene, step and rewind, and which of them do not show the current step
// yet. A scene, a step or a rewind marks them all; the window asks refreshDue() when
// the state changes, and each marked panel whose pace is due catches up (refresh()),
// in the order they were added. The pace is the panel's own (refreshPace()) with
// PlaybackClock's timing (app/core/playback_clock.h): the quantities table at the
// panels' rate while playing, Check my numbers (it rebuilds a world for the step's
// start) and the typeset derivation (typesetting every frame would cost more than the
// step) only when paused; the plots draw as they go.
#pragma once

#include "app/core/playback_clock.h"
#include "app/core/session_panel.h"

#include <QList>

namespace rbw {

class RefreshScheduler {
public:
    using Pace = SessionPanel::RefreshPace;

    void add(SessionPanel* panel) { panels_.append({panel, false}); }

    void sceneLoaded(const World& world)
    {
        for (Entry& e : panels_) e.panel->sceneLoaded(world);
        markAll();
    }
    void stepRecorded(const StepTrace& trace)
    {
        for (Entry& e : panels_) e.panel->stepRecorded(trace);
        markAll();
    }
    void rewound(long stepIndex)
    {
        for (Entry& e : panels_) e.panel->rewound(stepIndex);
        markAll();
    }

    // A panel whose content changed for a reason of its own (the derivation's body).
    void mark(const SessionPanel* panel)
    {
        for (Entry& e : panels_)
            if (e.panel == panel) e.dirty = true;
    }
    bool isDirty(const SessionPanel* panel) const
    {
        for (const Entry& e : panels_)
            if (e.panel == panel) return e.dirty;
        return false;
    }

    // Whether a pace lets a panel refresh now: playing or not, and whether the clock
    // says the panels are due (PlaybackClock::panelsDue).
    static bool due(Pace pace, bool playing, bool panelsDue)
    {
        switch (pace) {
        case Pace::AsItGoes: return false;
        case Pace::PanelRate: return panelsDue;
        case Pace::WhenPaused: return PlaybackClock::derivationDue(playing);
        }
        return false;
    }

    // Every marked panel whose pace is due catches up.
    void refreshDue(bool playing, bool panelsDue)
    {
        for (Entry& e : panels_) {
            if (e.dirty && due(e.panel->refreshPace(), playing, panelsDue)) refresh(e);
        }
    }
    // One panel catches up now, whatever its pace (a dock coming into view, a test).
    void refreshNow(SessionPanel* panel)
    {
        for (Entry& e : panels_)
            if (e.panel == panel) refresh(e);
    }
    void refreshIfDirty(SessionPanel* panel)
    {
        if (isDirty(panel)) refreshNow(panel);
    }

private:
    struct Entry {
        SessionPanel* panel = nullptr;
        bool dirty = false;
    };
    void markAll()
    {
        for (Entry& e : panels_) e.dirty = true;
    }
    static void refresh(Entry& e)
    {
        e.dirty = false;
        e.panel->refresh();
    }

    QList<Entry> panels_;
};

} // namespace rbw
