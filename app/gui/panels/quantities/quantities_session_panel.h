// The quantities table as a SessionPanel (app/core/session_panel.h): the shell tells it of
// every scene, step and rewind like the other panels, and it catches up at the panels'
// rate (4 Hz while playing, every change when paused). A new scene shows its start
// state at once (every body's x, v, q, … in the Before column); refresh() shows the
// session's current step, or the start state when no step is recorded. The model
// (TraceModel) itself knows no session.
#pragma once

#include "app/core/session_panel.h"

namespace rbw {

class Session;
class TraceModel;

class QuantitiesSessionPanel : public SessionPanel {
public:
    QuantitiesSessionPanel(TraceModel* model, const Session* session) : model_(model), session_(session) {}

    void sceneLoaded(const World& world) override;
    void stepRecorded(const StepTrace&) override {}
    void rewound(long) override {}
    RefreshPace refreshPace() const override { return RefreshPace::PanelRate; }
    void refresh() override;

private:
    TraceModel* model_;
    const Session* session_;
};

} // namespace rbw
