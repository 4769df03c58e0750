// A second thread for the soft step's lanes (solver_islands.h): one persistent worker,
// started the first time a step has lanes worth solving apart, woken once per step and
// joined when its world goes. run(count, task) runs task(0) ... task(count - 1), each
// once, on the calling thread and on the worker, whichever claims a lane first (an
// atomic counter), and returns when all have run. If the worker has not started on the
// step by the time the caller has run every lane (the other core is busy), the caller
// closes the step without it and does not wait; a late worker then finds it closed and
// touches nothing. Lanes touch disjoint data and what a lane computes does not depend on
// the thread that runs it, so a world steps to the same bits with one thread or two.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>

namespace rbw {

class SolverWorker {
public:
    SolverWorker() = default;
    SolverWorker(const SolverWorker&) = delete;
    SolverWorker& operator=(const SolverWorker&) = delete;
    ~SolverWorker();

    // task(0) ... task(count - 1), each once, here and on the worker; all done on return.
    void run(int count, const std::function<void(int)>& task);

private:
    void loop();
    // Claims lanes and runs them until none is left.
    void work(int count, const std::function<void(int)>& task);

    std::thread thread_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable done_;
    const std::function<void(int)>* task_ = nullptr;
    int count_ = 0;
    std::atomic<int> next_{0};   // the next lane to claim
    // The worker's part in step `issued_`: 4 issued + {0 open, 1 joined, 2 closed}
    std::atomic<std::int64_t> part_{0};
    std::int64_t issued_ = 0;     // steps handed out
    std::int64_t finished_ = 0;   // the last step the worker joined and finished
    bool stop_ = false;
};

} // namespace rbw
