// The one runner of both study panels (AccuracyPanel, ContactStudyPanel): a study runs
// on the thread pool (QtConcurrent::run with a QPromise, which carries its result back),
// one at a time; every progress report the study makes reaches the GUI thread, in order,
// as progressed(done, total); finished() follows the last one. Cancel sets the flag the
// study polls between steps (physics/workbook/lab/study.h), and the study returns what
// it has: the panels show a cancelled study's finished runs. (QFuture::cancel would
// drop that result, and QPromise's own progress is throttled to 25 reports a second,
// which would skip runs: so the flag and queued calls, and the promise for the result.)
// The destructor cancels and waits, so the study never outlives its panel.
#pragma once

#include "physics/workbook/lab/study.h"

#include <QFutureWatcher>
#include <QObject>
#include <QPromise>
#include <QtConcurrent/QtConcurrentRun>

#include <atomic>
#include <functional>
#include <utility>

namespace rbw {

// The signals (a template cannot declare them).
class StudyRunnerSignals : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

signals:
    void progressed(int done, int total);
    void finished();
};

template <typename Result>
class StudyRunner : public StudyRunnerSignals {
public:
    // The study: called on a pool thread with the progress callback and the cancel flag.
    using Work = std::function<Result(const lab::StudyProgress& progress, const std::atomic<bool>* cancel)>;

    explicit StudyRunner(QObject* parent = nullptr)
        : StudyRunnerSignals(parent)
    {
        connect(&watcher_, &QFutureWatcher<Result>::finished, this, &StudyRunnerSignals::finished);
    }
    ~StudyRunner() override
    {
        cancel();
        watcher_.waitForFinished();
    }

    // Starts the study; false (and nothing started) while one is running.
    bool start(Work work)
    {
        if (isRunning()) return false;
        cancel_ = false;
        watcher_.setFuture(QtConcurrent::run(
            [this](QPromise<Result>& promise, const Work& study) {
                const lab::StudyProgress progress = [this](int done, int total) {
                    QMetaObject::invokeMethod(
                        this, [this, done, total] { emit progressed(done, total); }, Qt::QueuedConnection);
                };
                promise.addResult(study(progress, &cancel_));
            },
            std::move(work)));
        return true;
    }

    // Asks the running study to stop after its current step; finished() still comes.
    void cancel()
    {
        if (isRunning()) cancel_ = true;
    }
    // Blocks until no study runs (a new scene replaces the one studied).
    void wait() { watcher_.waitForFinished(); }
    bool isRunning() const { return watcher_.isRunning(); }
    // The finished study's result (after finished()).
    Result result() const { return watcher_.result(); }

private:
    QFutureWatcher<Result> watcher_;
    std::atomic<bool> cancel_{false};
};

} // namespace rbw
