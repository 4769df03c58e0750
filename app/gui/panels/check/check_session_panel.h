// Check my numbers as a SessionPanel (app/core/session_panel.h): the shell tells it of
// every scene, step and rewind like the other panels; it catches up only when the run
// is paused (refresh() rebuilds the world as it was at the step's start for the
// checker). The lesson's id keys the student's entries (AnswersStore); the panel asks
// for it when it refreshes. CheckPanel itself knows no session.
#pragma once

#include "app/core/session_panel.h"

#include <QString>

#include <functional>

namespace rbw {

class CheckPanel;
class Session;

class CheckSessionPanel : public SessionPanel {
public:
    CheckSessionPanel(CheckPanel* panel, const Session* session, std::function<QString()> lessonId)
        : panel_(panel), session_(session), lessonId_(std::move(lessonId))
    {
    }

    void sceneLoaded(const World&) override {}
    void stepRecorded(const StepTrace&) override {}
    void rewound(long) override {}
    RefreshPace refreshPace() const override { return RefreshPace::WhenPaused; }
    void refresh() override;

private:
    CheckPanel* panel_;
    const Session* session_;
    std::function<QString()> lessonId_;
};

} // namespace rbw
