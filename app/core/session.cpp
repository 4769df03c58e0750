#include "app/core/session.h"

#include "physics/engine/integrator_registry.h"

#include <QElapsedTimer>
#include <QMetaObject>

#include <algorithm>
#include <cmath>

namespace rbw {

Session::Session(QObject* parent) : QObject(parent) {}

Session::~Session()
{
    if (run_) run_->cancel();   // its thread finishes alone and never calls back
}

void Session::load(const SceneDef& scene)
{
    cancelRun();
    base_ = scene;
    edited_ = scene;
    grab_.reset();
    reset();
}

void Session::reset()
{
    cancelRun();
    grab_.reset();
    pendingPushes_.clear();
    history_.clear();
    world_ = std::make_unique<World>(edited_);
    history_.push(HistoryEntry{world_->snapshot(), CompactTrace{}, false});
    hasCurrent_ = false;
    emit sessionReset();
    emit parametersChanged();
    emit stateChanged();
}

const StepTrace* Session::currentTrace() const
{
    return hasCurrent_ ? &current_ : nullptr;
}

std::unique_ptr<World> Session::worldBeforeCurrentStep() const
{
    if (!world_ || !hasCurrent_ || history_.cursor() < 1) {
        return nullptr;
    }
    auto before = std::make_unique<World>(edited_);
    before->restore(history_.at(history_.cursor() - 1).state);
    return before;
}

const StepStatus& Session::status() const
{
    static const StepStatus none;
    return world_ ? world_->status() : none;
}

bool Session::rebuild(SceneDef edited, QString* error)
{
    const std::vector<SceneIssue> issues = validate(edited);
    if (!issues.empty()) {
        if (error != nullptr) {
            *error = QString::fromStdString(issues.front().path + ": " + issues.front().reason);
        }
        return false;
    }
    cancelRun();
    edited_ = std::move(edited);
    // An edit is a new branch: the recorded steps after this one were computed with
    // the old parameters, so they go (as stepping on from here would drop them).
    history_.discardAfterCursor();
    if (world_) {
        // Carry the current state over into a world built from the edited scene.
        const WorldSnapshot now = world_->snapshot();
        world_ = std::make_unique<World>(edited_);
        world_->restore(now);
    } else {
        world_ = std::make_unique<World>(edited_);
    }
    emit parametersChanged();
    emit stateChanged();
    return true;
}

bool Session::setDt(double dt, QString* error)
{
    SceneDef s = edited_;
    s.dt = dt;
    return rebuild(std::move(s), error);
}

bool Session::setIntegrator(const QString& name, QString* error)
{
    SceneDef s = edited_;
    s.integrator = name.toStdString();
    return rebuild(std::move(s), error);
}

Vec3 Session::gravityWhenOn() const
{
    return base_.hasGravity() ? base_.g_W : Vec3(0.0, -9.81, 0.0);
}

void Session::setGravityEnabled(bool on)
{
    SceneDef s = edited_;
    s.g_W = on ? gravityWhenOn() : Vec3::Zero();
    rebuild(std::move(s), nullptr);
}

bool Session::gravityEnabled() const { return edited_.hasGravity(); }

bool Session::setRestitution(double c, QString* error)
{
    SceneDef s = edited_;
    s.restitution = c;
    return rebuild(std::move(s), error);
}

bool Session::setFriction(double mu, QString* error)
{
    SceneDef s = edited_;
    s.friction = mu;
    return rebuild(std::move(s), error);
}

void Session::applyInteraction(World& w) const
{
    if (grab_) {
        const int b = grab_->body;
        const Vec3 f_W = grab_->force(w.massProperties()[b], w.states()[b], edited_.dt);
        w.applyForceOnce(b, w.bodyToWorld(b, grab_->p_B), f_W);
    }
    for (const auto& [p_W, f_W] : pendingPushes_) {
        w.applyForceOnce(edited_.push.body, p_W, f_W);
    }
}

bool Session::step()
{
    cancelRun();
    const bool ok = stepQuiet();
    if (ok) {
        emit stateChanged();
    }
    return ok;
}

bool Session::stepQuiet()
{
    if (!world_ || !world_->status().ok) {
        return false;
    }
    applyInteraction(*world_);
    pendingPushes_.clear();
    const StepStatus s = world_->step(&scratch_);
    if (!s.ok) {
        // The blown-up step's numbers are not results: keep the last good state in the
        // history, so Step back still works, and say what happened.
        emit blownUp(QString::fromStdString(s.message));
        emit stateChanged();
        return false;
    }
    history_.push(HistoryEntry{world_->snapshot(), CompactTrace(scratch_), true});
    current_ = scratch_;
    hasCurrent_ = true;
    emit stepRecorded(current_);
    return true;
}

int Session::advance(int maxSteps, double budgetMs)
{
    cancelRun();
    QElapsedTimer clock;
    clock.start();
    int taken = 0;
    while (taken < maxSteps) {
        if (!stepQuiet()) {
            break;
        }
        ++taken;
        if (static_cast<double>(clock.nsecsElapsed()) * 1e-6 >= budgetMs) {
            break;
        }
    }
    if (taken > 0) {
        emit stateChanged();
    }
    return taken;
}

void Session::restoreCurrentEntry()
{
    // The world at the recorded state, exactly: its snapshot holds every body's state,
    // the step counter, the time, the switches and the status.
    const HistoryEntry& entry = history_.current();
    world_->restore(entry.state);
    hasCurrent_ = entry.hasTrace;
    current_ = hasCurrent_ ? entry.trace.unpack() : StepTrace{};
    pendingPushes_.clear();
}

bool Session::stepBack()
{
    cancelRun();
    if (!world_ || !history_.pop()) {
        return false;
    }
    restoreCurrentEntry();
    emit rewound(world_->stepIndex());
    emit stateChanged();
    return true;
}

bool Session::goToStep(long k, long maxNewSteps)
{
    cancelRun();
    if (!world_ || history_.empty() || k < history_.firstStep()) {
        return false;
    }
    const long now = world_->stepIndex();
    if (k == now) {
        return true;
    }
    if (k < now) {
        history_.seek(static_cast<std::size_t>(history_.indexOfStep(k)));
        restoreCurrentEntry();
        emit rewound(k);
        emit stateChanged();
        return true;
    }
    // Forward through the recorded steps: each becomes current again, as when it was
    // first taken, so every view that follows stepRecorded gets its sample back.
    const long recordedTarget = std::min(k, history_.lastStep());
    bool moved = false;
    while (world_->stepIndex() < recordedTarget) {
        history_.seek(history_.cursor() + 1);
        restoreCurrentEntry();
        moved = true;
        if (hasCurrent_) {
            emit stepRecorded(current_);
        }
    }
    // Beyond the recorded history: new steps.
    long taken = 0;
    bool ok = true;
    while (world_->stepIndex() < k) {
        if (taken >= maxNewSteps || !stepQuiet()) {
            ok = false;
            break;
        }
        ++taken;
        moved = true;
    }
    if (moved) {
        emit stateChanged();
    }
    return ok && world_->stepIndex() == k;
}

Session::RunStart Session::startRun(int maxSteps, double budgetMs, int waitMs)
{
    if (run_ || !world_ || !world_->status().ok || maxSteps < 1) {
        return RunStart::Refused;
    }
    launchRun(maxSteps, budgetMs);
    if (run_->waitFor(waitMs)) {
        finishRun();
        return RunStart::Finished;
    }
    setBusy(true);
    return RunStart::Running;
}

Session::RunStart Session::startGoToStep(long k, int waitMs, long maxNewSteps)
{
    cancelRun();
    if (!world_ || history_.empty() || k < history_.firstStep() || k <= history_.lastStep() ||
        !world_->status().ok || maxNewSteps < 1) {
        // Nothing to compute: the recorded history (restored at once), or refused.
        const bool reached = goToStep(k, 0);
        emit goToFinished(k, reached);
        return RunStart::Finished;
    }
    goToStep(history_.lastStep(), 0);   // the recorded steps first, as goToStep passes them
    goToTarget_ = k;
    goToLeft_ = maxNewSteps;
    QElapsedTimer waited;
    waited.start();
    continueGoTo();
    // A light scene's steps finish within the wait, slice after slice, and nothing shows.
    while (run_) {
        const qint64 left = static_cast<qint64>(waitMs) - waited.elapsed();
        if (left < 0 || !run_->waitFor(static_cast<int>(left))) break;
        finishRun();   // records the slice, starts the next one or ends (goToFinished)
    }
    if (!run_) {
        return RunStart::Finished;
    }
    setBusy(true);
    return RunStart::Running;
}

bool Session::continueGoTo()
{
    const long k = goToTarget_;
    if (k < 0) {
        return false;
    }
    const long now = world_->stepIndex();
    if (now < k && goToLeft_ > 0 && world_->status().ok) {
        // A slice: at most what the history keeps, and about kGoToSliceMs of work, so
        // its steps are recorded (and the views follow) before the next one starts.
        const long most = std::min({k - now, goToLeft_, static_cast<long>(StepHistory::kDefaultCapacity) - 1});
        launchRun(static_cast<int>(most), kGoToSliceMs);
        return true;
    }
    goToTarget_ = -1;
    goToLeft_ = 0;
    emit goToFinished(k, now == k);
    return false;
}

void Session::launchRun(int maxSteps, double budgetMs)
{
    // The run steps a copy (a fresh world of the same scene, restored: bit for bit the
    // same steps), so this world stays at the last finished step for the views.
    auto copy = std::make_unique<World>(edited_);
    copy->restore(world_->snapshot());
    applyInteraction(*copy);
    runPushes_ = pendingPushes_.size();
    const quint64 serial = ++runSerial_;
    run_ = StepRun::start(std::move(copy), maxSteps, budgetMs, [this, serial] {
        // On the run's thread: the result is taken on this object's (the GUI) thread.
        QMetaObject::invokeMethod(
            this, [this, serial] {
                if (run_ && serial == runSerial_) finishRun();
            },
            Qt::QueuedConnection);
    });
}

void Session::setBusy(bool busy)
{
    if (busy != busySignalled_) {
        busySignalled_ = busy;
        emit busyChanged(busy);
    }
}

void Session::cancelRun()
{
    goToTarget_ = -1;   // a Go to that is cancelled is not finished: no goToFinished
    goToLeft_ = 0;
    if (!run_) {
        return;
    }
    run_->cancel();
    run_.reset();
    setBusy(false);
}

void Session::finishRun()
{
    const std::shared_ptr<StepRun> run = std::move(run_);
    run_.reset();
    StepRunResult r = run->take();
    const bool goingOn = goToTarget_ >= 0;   // a Go to's slice: busy until its last one
    if (!goingOn) {
        setBusy(false);
    }
    if (!r.failure.empty()) {
        // Nothing was computed: the world stays at the last finished step.
        goToLeft_ = 0;
        emit blownUp(QString::fromStdString("step " + std::to_string(world_->stepIndex()) + ": " + r.failure));
        emit runFinished(0);
        if (goingOn && !continueGoTo()) setBusy(false);
        return;
    }
    const int taken = static_cast<int>(r.traces.size());
    if (taken > 0 || r.blewUp) {
        // The pushes the run's first step applied are spent; later ones wait.
        pendingPushes_.erase(pendingPushes_.begin(),
                             pendingPushes_.begin() + static_cast<long>(std::min(runPushes_, pendingPushes_.size())));
    }
    world_ = std::move(r.world);
    for (int i = 0; i < taken; ++i) {
        history_.push(HistoryEntry{std::move(r.states[i]), CompactTrace(r.traces[i]), true});
        current_ = std::move(r.traces[i]);
        hasCurrent_ = true;
        emit stepRecorded(current_);
    }
    if (r.blewUp) {
        emit blownUp(QString::fromStdString(world_->status().message));
    }
    if (taken > 0 || r.blewUp) {
        emit stateChanged();
    }
    emit runFinished(taken);
    if (goingOn) {
        goToLeft_ -= taken;
        // A handler above may have cancelled it (goToTarget_ is -1 then): it ends here.
        if (goToTarget_ < 0 || !continueGoTo()) setBusy(false);
    }
}

void Session::beginGrab(int body, const Vec3& p_W)
{
    if (!world_ || body < 0 || body >= static_cast<int>(edited_.bodies.size()) || edited_.bodies[body].fixed) {
        return;
    }
    MouseSpring spring;
    spring.body = body;
    spring.p_B = world_->worldToBody(body, p_W);
    spring.target_W = p_W;
    grab_ = spring;
    emit stateChanged();
}

void Session::moveGrab(const Vec3& target_W)
{
    if (grab_) {
        grab_->target_W = target_W;
        emit stateChanged();
    }
}

void Session::endGrab()
{
    if (grab_) {
        grab_.reset();
        emit stateChanged();
    }
}

std::optional<std::pair<Vec3, Vec3>> Session::springSegment() const
{
    if (!grab_ || !world_) {
        return std::nullopt;
    }
    return std::make_pair(world_->bodyToWorld(grab_->body, grab_->p_B), grab_->target_W);
}

bool Session::push(const Vec3& direction_W)
{
    if (!world_ || edited_.push.body < 0 || direction_W.norm() == 0.0) {
        return false;
    }
    const Vec3 p_W = world_->bodyToWorld(edited_.push.body, edited_.push.p_B);
    pendingPushes_.emplace_back(p_W, edited_.push.magnitude * direction_W.normalized());
    emit stateChanged();   // the view draws the push before the step that applies it
    return true;
}

bool Session::toggleTorques()
{
    if (!world_ || !world_->hasSwitchableTorque()) {
        return false;
    }
    cancelRun();
    const bool on = !torquesOn();
    for (int i = 0; i < static_cast<int>(edited_.torques.size()); ++i) {
        world_->setTorqueEnabled(i, on);
    }
    emit stateChanged();
    return true;
}

bool Session::torquesOn() const
{
    if (!world_) {
        return false;
    }
    for (int i = 0; i < static_cast<int>(edited_.torques.size()); ++i) {
        if (edited_.torques[i].switchable && world_->torqueEnabled(i)) {
            return true;
        }
    }
    return false;
}

} // namespace rbw
