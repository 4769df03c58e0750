// A run of steps computed off the GUI thread (issue 22, item 4): the app's Step and
// Play hand the physics to a thread of its own, so the window answers, shows that it
// is busy and can Cancel or Quit while a heavy step (a pile of 1 000 boxes) is being
// computed.
//
// The run steps its own World, a copy of the session's (built from the same scene
// and restored from a WorldSnapshot, which steps on bit for bit), so the session's
// world is never touched by the thread: the views keep reading the last finished
// step, and a cancelled run leaves it exactly there. The session takes the run's
// result (every finished step's state and trace, and the copy itself) back on the GUI
// thread (Session::startRun).
//
// Cancel stops the run at its next step boundary; the step being computed cannot be
// interrupted (the physics has no such point), so its thread finishes it in the
// background and drops it. Runs take turns: a new run waits until an abandoned one's
// thread has finished, so a Cancel followed by Step never computes two heavy steps at
// once (memory). running() counts the threads still computing: the app's main() leaves
// with _Exit when one is left at Quit, so Quit never waits for a step.
#pragma once

#include "physics/engine/trace.h"
#include "physics/engine/world.h"

#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace rbw {

struct StepRunResult {
    std::unique_ptr<World> world;        // after the last finished step, or the blown-up one
    std::vector<WorldSnapshot> states;   // after each finished step
    std::vector<StepTrace> traces;       // each finished step's trace
    bool blewUp = false;                 // world->status() says where
    std::string failure;                 // the step could not be computed at all (memory): nothing taken
};

class StepRun {
public:
    // Starts computing up to maxSteps steps of `world` on a thread of its own. The run
    // stops at a step boundary after budgetMs of wall time (<= 0: no limit; the first
    // step is always taken), at a blow-up, or when cancelled. onFinished is called on
    // the run's thread when it finished, unless it was cancelled first.
    static std::shared_ptr<StepRun> start(std::unique_ptr<World> world, int maxSteps, double budgetMs,
                                          std::function<void()> onFinished);

    ~StepRun();
    StepRun(const StepRun&) = delete;
    StepRun& operator=(const StepRun&) = delete;

    // Waits at most ms milliseconds for the run to finish; true if it has.
    bool waitFor(int ms);
    bool finished() const;
    // The run stops at its next step boundary and onFinished is not called; its result
    // is never taken.
    void cancel();
    // The result, once finished() (moved out: call it once).
    StepRunResult take();

    // While one lives, every run waits before its first step (runs take turns at the
    // same lock). For tests: a step that has not finished, whatever the machine's
    // speed. Made and destroyed on one thread; waits for a run that is computing.
    class HoldForTest {
    public:
        HoldForTest();
        ~HoldForTest();
        HoldForTest(const HoldForTest&) = delete;
        HoldForTest& operator=(const HoldForTest&) = delete;
    };

    // Threads still computing, abandoned ones included.
    static int running();
    // Waits (at most ms) until no thread computes; true if none does (tests, exit).
    static bool waitForAll(int ms);

private:
    StepRun() = default;
    void compute(int maxSteps, double budgetMs);

    mutable std::mutex mutex_;
    std::condition_variable done_;
    bool finished_ = false;
    bool cancelled_ = false;
    std::function<void()> onFinished_;
    StepRunResult result_;
};

} // namespace rbw
