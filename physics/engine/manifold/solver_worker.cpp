// The soft step's second thread; see solver_worker.h.
#include "physics/engine/manifold/solver_worker.h"

namespace rbw {

SolverWorker::~SolverWorker()
{
    if (!thread_.joinable()) return;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_one();
    thread_.join();
}

void SolverWorker::run(const std::function<void(int)>& task)
{
    if (!thread_.joinable()) thread_ = std::thread(&SolverWorker::loop, this);
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        task_ = &task;
        ++issued_;
    }
    wake_.notify_one();
    task(0);
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return finished_ == issued_; });
    task_ = nullptr;
}

void SolverWorker::loop()
{
    long seen = 0;
    for (;;) {
        const std::function<void(int)>* task = nullptr;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [this, seen] { return stop_ || issued_ != seen; });
            if (stop_) return;
            seen = issued_;
            task = task_;
        }
        (*task)(1);
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            finished_ = seen;
        }
        done_.notify_one();
    }
}

} // namespace rbw
