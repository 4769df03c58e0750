// A second thread for the soft step's lanes (solver_islands.h): one persistent worker,
// started the first time a step has two lanes worth solving apart, woken once per step
// and joined when its world goes. run(task) calls task(0) on the calling thread and
// task(1) on the worker and returns when both have returned; the two tasks must touch
// disjoint data (two lanes do). What the lanes compute does not depend on the thread
// that computes it, so a world steps to the same bits with one thread or two.
#pragma once

#include <condition_variable>
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

    // task(0) here and task(1) on the worker, both done on return.
    void run(const std::function<void(int)>& task);

private:
    void loop();

    std::thread thread_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable done_;
    const std::function<void(int)>* task_ = nullptr;
    long issued_ = 0;     // tasks handed to the worker
    long finished_ = 0;   // tasks it has finished
    bool stop_ = false;
};

} // namespace rbw
