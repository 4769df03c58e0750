#include "app/core/playback_clock.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rbw {

void PlaybackClock::setSpeed(double speed)
{
    speed_ = speed;
    debt_ = 0.0;
}

void PlaybackClock::start()
{
    debt_ = 0.0;
    tickClock_.start();
}

int PlaybackClock::stepsDue(double wallMs, double h)
{
    if (speed_ < 0.0) {
        return std::numeric_limits<int>::max();
    }
    if (speed_ == 0.0) {
        return 1;
    }
    // debt += s Δt, with Δt capped so that a stall does not trigger a burst.
    const double wall = std::min(kMaxTickWallMs, std::max(0.0, wallMs)) * 1e-3;
    debt_ += speed_ * wall;
    // steps = floor(debt / h)
    return static_cast<int>(std::floor(debt_ / h));
}

int PlaybackClock::stepsDue(double h)
{
    if (!tickClock_.isValid()) {
        tickClock_.start();
    }
    return stepsDue(static_cast<double>(tickClock_.restart()), h);
}

void PlaybackClock::stepsTaken(int due, int taken, double h)
{
    if (speed_ <= 0.0) {
        return;
    }
    debt_ -= taken * h;
    if (taken < due) {
        debt_ = std::min(debt_, h);   // cannot keep up: drop the backlog
    }
}

bool PlaybackClock::panelsDue(bool playing, qint64 msSinceRefresh)
{
    return !playing || msSinceRefresh >= kPanelIntervalMs;
}

bool PlaybackClock::panelsDue(bool playing) const
{
    return panelsDue(playing, panelClock_.isValid() ? panelClock_.elapsed() : kPanelIntervalMs);
}

void PlaybackClock::panelsRefreshed()
{
    panelClock_.start();
}

} // namespace rbw
