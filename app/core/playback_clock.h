// The pacing of Play: how many steps one tick of the play timer takes so that the
// simulation keeps to real time at the chosen speed, and when the panels that are
// expensive to repaint (quantities table, status line) are due. The window only
// asks; no widget and no step here, so it is tested without a display.
//
// Symbols and units:
//   s      playback speed: simulated seconds per wall-clock second; 0 = one step per
//          tick, -1 = as many steps as fit in the tick's budget
//   h      time step of the scene [s]
//   Δt     wall time since the previous tick [ms], capped at kMaxTickWallMs
//   debt   simulated time owed to real time [s]: debt += s Δt, steps = floor(debt / h)
#pragma once

#include <QElapsedTimer>
#include <QtGlobal>

namespace rbw {

class PlaybackClock {
public:
    static constexpr int kTickIntervalMs = 16;          // the play timer, ~60 Hz
    static constexpr double kTickBudgetMs = 12.0;       // work per tick: the GUI never freezes
    static constexpr double kMaxTickWallMs = 100.0;     // a stall (a dialog, a drag) is no burst
    static constexpr qint64 kPanelIntervalMs = 250;     // table and status while playing: 4 Hz
    static constexpr double kOneStepPerTick = 0.0;
    static constexpr double kAsFastAsPossible = -1.0;

    // A new speed drops what is owed at the old one.
    void setSpeed(double speed);
    double speed() const { return speed_; }
    // Simulated seconds owed to real time.
    double debt() const { return debt_; }

    // Play starts: nothing owed, the wall clock runs from now.
    void start();

    // --- one tick ---
    // The steps this tick asks for, from the wall time since the previous tick:
    // 0 when less than one step is owed (take none this tick); INT_MAX as fast as
    // possible (the budget stops the batch).
    int stepsDue(double wallMs, double h);
    // The same with the wall time the clock measured since start() or the last tick.
    int stepsDue(double h);
    // The session took `taken` of the `due` steps within the budget. Taken steps pay
    // the debt; when it could not keep up, the backlog is dropped (at most one step
    // stays owed) so the run does not race to catch up later.
    void stepsTaken(int due, int taken, double h);
    double budgetMs() const { return kTickBudgetMs; }

    // --- panels ---
    // While paused, always; while playing, once per kPanelIntervalMs.
    static bool panelsDue(bool playing, qint64 msSinceRefresh);
    bool panelsDue(bool playing) const;
    void panelsRefreshed();
    // The typeset derivation costs more than a step: only when the run pauses.
    static bool derivationDue(bool playing) { return !playing; }

private:
    double speed_ = 1.0;
    double debt_ = 0.0;
    QElapsedTimer tickClock_;
    QElapsedTimer panelClock_;
};

} // namespace rbw
