#include "app/core/step_run.h"

#include <atomic>
#include <chrono>
#include <exception>
#include <new>
#include <thread>

namespace rbw {

namespace {

// Runs take turns at the physics (step_run.h): at most one heavy step in memory.
std::mutex& physicsTurn()
{
    static std::mutex m;
    return m;
}

// The threads still computing, for running() and waitForAll().
std::mutex& countMutex()
{
    static std::mutex m;
    return m;
}
std::condition_variable& countChanged()
{
    static std::condition_variable c;
    return c;
}
int& threadCount()
{
    static int n = 0;
    return n;
}

} // namespace

std::shared_ptr<StepRun> StepRun::start(std::unique_ptr<World> world, int maxSteps, double budgetMs,
                                        std::function<void()> onFinished)
{
    std::shared_ptr<StepRun> run(new StepRun);
    run->result_.world = std::move(world);
    run->onFinished_ = std::move(onFinished);
    {
        const std::lock_guard<std::mutex> lock(countMutex());
        ++threadCount();
    }
    // Detached: a cancelled run's thread finishes its step alone; the shared pointer
    // keeps the run (and its world) alive until then.
    std::thread([run, maxSteps, budgetMs]() mutable {
        run->compute(maxSteps, budgetMs);
        run.reset();   // an abandoned run's world goes before the thread counts as done
        {
            const std::lock_guard<std::mutex> lock(countMutex());
            --threadCount();
        }
        countChanged().notify_all();
    }).detach();
    return run;
}

StepRun::~StepRun() = default;

StepRun::HoldForTest::HoldForTest() { physicsTurn().lock(); }
StepRun::HoldForTest::~HoldForTest() { physicsTurn().unlock(); }

void StepRun::compute(int maxSteps, double budgetMs)
{
    using Clock = std::chrono::steady_clock;
    const std::lock_guard<std::mutex> turn(physicsTurn());
    const Clock::time_point begin = Clock::now();
    StepRunResult& r = result_;   // only this thread touches it until finished_
    try {
        for (int taken = 0; taken < maxSteps; ++taken) {
            {
                const std::lock_guard<std::mutex> lock(mutex_);
                if (cancelled_) break;
            }
            StepTrace trace;
            const StepStatus& s = r.world->step(&trace);
            if (!s.ok) {
                r.blewUp = true;   // the blown-up step's numbers are not results: not kept
                break;
            }
            r.states.push_back(r.world->snapshot());
            r.traces.push_back(std::move(trace));
            const double elapsedMs = std::chrono::duration<double, std::milli>(Clock::now() - begin).count();
            if (budgetMs > 0.0 && elapsedMs >= budgetMs) break;
        }
    } catch (const std::bad_alloc&) {
        r.failure = "there is not enough memory to compute this step";
    } catch (const std::exception& e) {
        r.failure = std::string("the step could not be computed: ") + e.what();
    }
    if (!r.failure.empty()) {
        // Nothing of a failed run is taken: the world it stepped may be half-way.
        r.states.clear();
        r.traces.clear();
        r.blewUp = false;
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    finished_ = true;
    done_.notify_all();
    if (!cancelled_ && onFinished_) onFinished_();
}

bool StepRun::waitFor(int ms)
{
    std::unique_lock<std::mutex> lock(mutex_);
    return done_.wait_for(lock, std::chrono::milliseconds(ms < 0 ? 0 : ms), [this] { return finished_; });
}

bool StepRun::finished() const
{
    const std::lock_guard<std::mutex> lock(mutex_);
    return finished_;
}

void StepRun::cancel()
{
    const std::lock_guard<std::mutex> lock(mutex_);
    cancelled_ = true;
    onFinished_ = nullptr;
}

StepRunResult StepRun::take()
{
    const std::lock_guard<std::mutex> lock(mutex_);
    return std::move(result_);
}

int StepRun::running()
{
    const std::lock_guard<std::mutex> lock(countMutex());
    return threadCount();
}

bool StepRun::waitForAll(int ms)
{
    std::unique_lock<std::mutex> lock(countMutex());
    return countChanged().wait_for(lock, std::chrono::milliseconds(ms < 0 ? 0 : ms), [] { return threadCount() == 0; });
}

} // namespace rbw
