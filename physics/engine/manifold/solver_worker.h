// A second thread for the soft step's lanes (solver_islands.h): one persistent worker,
// started the first time a step has lanes worth solving apart, woken once per step and
// joined when its world goes. run(count, task) runs task(0) ... task(count - 1), each
// once, and returns when all have run: the caller runs the first half of the lanes, the
// worker the second (the same lanes on the same core from step to step), and each then
// takes what the other has not claimed yet, from the back (an atomic claim per lane), so
// a worker slowed by another process on its core leaves its lanes to the caller. If the
// worker has not started on the step by the time the caller has run every lane, the
// caller closes the step without it and does not wait; a late worker then finds it
// closed and touches nothing. Lanes touch disjoint data and what a lane computes does not depend on
// the thread that runs it, so a world steps to the same bits with one thread or two.
#pragma once

#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>

namespace rbw {

class SolverWorker {
public:
    static constexpr int kMaxLanes = 16;

    SolverWorker() = default;
    SolverWorker(const SolverWorker&) = delete;
    SolverWorker& operator=(const SolverWorker&) = delete;
    ~SolverWorker();

    // task(0) ... task(count - 1), each once, here and on the worker; all done on return.
    // count <= kMaxLanes.
    void run(int count, const std::function<void(int)>& task);

private:
    void loop();
    // Runs its own lanes (the caller's [0, half), the worker's [half, count)), then
    // takes what is left of the other's, from the back.
    void work(bool caller, std::int64_t step, int count, const std::function<void(int)>& task);
    bool claim(int lane, std::int64_t step) { return claimed_[static_cast<std::size_t>(lane)].exchange(step) != step; }

    std::thread thread_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable done_;
    const std::function<void(int)>* task_ = nullptr;
    int count_ = 0;
    std::array<std::atomic<std::int64_t>, kMaxLanes> claimed_{};   // per lane: the last step that claimed it
    // The worker's part in step `issued_`: 4 issued + {0 open, 1 joined, 2 closed}
    std::atomic<std::int64_t> part_{0};
    std::int64_t issued_ = 0;     // steps handed out
    std::int64_t finished_ = 0;   // the last step the worker joined and finished
    bool stop_ = false;
};

} // namespace rbw
