// The soft step's second thread; see solver_worker.h.
#include "physics/engine/manifold/solver_worker.h"

namespace rbw {

namespace {

constexpr std::int64_t kOpen = 0;
constexpr std::int64_t kJoined = 1;
constexpr std::int64_t kClosed = 2;

} // namespace

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

void SolverWorker::work(bool caller, std::int64_t step, int count, const std::function<void(int)>& task)
{
    const int half = (count + 1) / 2;
    const int first = caller ? 0 : half;
    const int end = caller ? half : count;
    for (int lane = first; lane < end; ++lane) {
        if (claim(lane, step)) task(lane);
    }
    const int otherFirst = caller ? half : 0;
    const int otherEnd = caller ? count : half;
    for (int lane = otherEnd - 1; lane >= otherFirst; --lane) {
        if (claim(lane, step)) task(lane);
    }
}

void SolverWorker::run(int count, const std::function<void(int)>& task)
{
    if (count <= 0) return;
    if (!thread_.joinable()) thread_ = std::thread(&SolverWorker::loop, this);
    std::int64_t step = 0;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        step = ++issued_;
        task_ = &task;
        count_ = count;
        part_.store(4 * step + kOpen);
    }
    wake_.notify_one();
    work(true, step, count, task);
    // Every lane is claimed. A worker that has not joined this step never will.
    std::int64_t open = 4 * step + kOpen;
    if (part_.compare_exchange_strong(open, 4 * step + kClosed)) return;
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this, step] { return finished_ == step; });
}

void SolverWorker::loop()
{
    std::int64_t seen = 0;
    for (;;) {
        const std::function<void(int)>* task = nullptr;
        int count = 0;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [this, seen] { return stop_ || issued_ != seen; });
            if (stop_) return;
            seen = issued_;
            task = task_;
            count = count_;
        }
        // Join the step unless the caller has closed it (or moved on to the next one)
        std::int64_t open = 4 * seen + kOpen;
        if (!part_.compare_exchange_strong(open, 4 * seen + kJoined)) continue;
        work(false, seen, count, *task);
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            finished_ = seen;
        }
        done_.notify_one();
    }
}

} // namespace rbw
