// The busy state of a step being computed off the GUI thread (Session::startRun,
// app/core/step_run.h): under the 3D view, "Computing step k … 2.4 s" with a running
// bar and Cancel. It shows only while the session is busy, which happens only when a
// step (or a tick's batch of Play) takes longer than the window waits for it; the
// window, its menus, the history and Quit answer meanwhile. A Go to step beyond the
// recording shows "Going to step k …" and the step it has reached so far.
//
// Cancel drops the run: the world stays at the last finished step, exactly (the run
// stepped a copy of it). The window connects cancelled() to stop playing.
#pragma once

#include <QElapsedTimer>
#include <QWidget>

class QLabel;
class QProgressBar;
class QPushButton;
class QTimer;

namespace rbw {

class Session;

class RunBusyBar : public QWidget {
    Q_OBJECT
public:
    explicit RunBusyBar(Session* session, QWidget* parent = nullptr);

    // How long Step and a tick of Play wait for their run before the window returns to
    // its events and this bar shows (a short freeze is no freeze; most steps take
    // microseconds and are recorded at once). Tests set 0: every run is then busy.
    int stepWaitMs() const { return stepWaitMs_; }
    int playWaitMs() const { return playWaitMs_; }
    // Go to a step beyond the recording (Session::startGoToStep) waits a little longer:
    // it asks for many steps at once, and a light scene's hundreds take a blink.
    int goWaitMs() const { return goWaitMs_; }
    // Sets the three waits (Go to waits as Step, unless given).
    void setWaitMs(int stepWaitMs, int playWaitMs, int goWaitMs = -1);

    QLabel* label() const { return label_; }
    QPushButton* cancelButton() const { return cancelButton_; }

public slots:
    // Drops the running step (Session::cancelRun); nothing when none runs.
    void cancel();

signals:
    // The student cancelled: the world is at step `stepIndex`, the last finished one.
    void cancelled(long stepIndex);

private:
    void onBusyChanged(bool busy);
    void updateText();

    Session* session_;
    QLabel* label_ = nullptr;
    QProgressBar* bar_ = nullptr;
    QPushButton* cancelButton_ = nullptr;
    QTimer* ticker_ = nullptr;
    QElapsedTimer since_;
    int stepWaitMs_ = 200;
    int playWaitMs_ = 50;
    int goWaitMs_ = 500;
};

} // namespace rbw
