// The typeset derivation as a SessionPanel (app/core/session_panel.h): the shell tells it
// of every scene, step and rewind like the other panels; it catches up only when the
// run is paused (typesetting with KaTeX costs more than a step), and when its dock comes
// into view (the shell's refreshIfDirty). refresh() builds the current step's page
// (app/derivation/derivation_builder.h: the lesson's derivation.md or the generic one)
// and hands it to the DerivationView; before the first step it shows the lesson's intro.
// A many-body scene's page follows one body: the one last grabbed (setFocusBody), else
// the first movable. DerivationView itself knows no session.
#pragma once

#include "app/core/lesson_catalogue.h"
#include "app/core/session_panel.h"

#include <QString>

#include <functional>

namespace rbw {

class DerivationView;
class Session;

class DerivationSessionPanel : public SessionPanel {
public:
    DerivationSessionPanel(DerivationView* view, const Session* session, std::function<const Lesson&()> lesson)
        : view_(view), session_(session), lesson_(std::move(lesson))
    {
    }

    void sceneLoaded(const World&) override {}
    void stepRecorded(const StepTrace&) override {}
    void rewound(long) override {}
    RefreshPace refreshPace() const override { return RefreshPace::WhenPaused; }
    void refresh() override;

    // The body the page should follow (a grab; -1 for a new scene: the first movable);
    // true if that changes the page's body.
    bool setFocusBody(int body);
    // The HTML last handed to the view.
    QString html() const { return html_; }

private:
    DerivationView* view_;
    const Session* session_;
    std::function<const Lesson&()> lesson_;
    int focusBody_ = -1;
    QString html_;
};

} // namespace rbw
