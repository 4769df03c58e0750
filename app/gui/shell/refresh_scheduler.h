// Which panels do not show the current step yet, and which may catch up now. A step,
// a step back, a reset or a new scene marks them all; the window asks due() when the
// state changes and refreshes what it returns. The pace is PlaybackClock's
// (app/core/playback_clock.h): the quantities table at the panels' rate while playing,
// Check my numbers (it rebuilds a world for the step's start) and the typeset
// derivation (typesetting every frame would cost more than the step) only when paused.
#pragma once

#include "app/core/playback_clock.h"

namespace rbw {

class RefreshScheduler {
public:
    enum Panel : unsigned { Table = 1u, Check = 2u, Derivation = 4u, All = 7u };

    void mark(unsigned panels) { dirty_ |= panels; }
    void done(Panel panel) { dirty_ &= ~static_cast<unsigned>(panel); }
    bool isDirty(Panel panel) const { return (dirty_ & panel) != 0; }

    // The dirty panels that may refresh now: playing or not, and whether the clock
    // says the panels are due (PlaybackClock::panelsDue).
    unsigned due(bool playing, bool panelsDue) const
    {
        unsigned now = 0;
        if (panelsDue) now |= Table;
        if (!playing) now |= Check;
        if (PlaybackClock::derivationDue(playing)) now |= Derivation;
        return dirty_ & now;
    }

private:
    unsigned dirty_ = 0;
};

} // namespace rbw
