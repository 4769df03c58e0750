// A session: one lesson's world as the student drives it. It owns the world, the
// history behind Step back, the student's changes to the scene's parameters (dt,
// integrator, gravity, restitution, friction) and the interaction (mouse spring,
// keyboard pushes, the K toggle). The views only read it: the 3D view a snapshot,
// the panels and derivation the current trace, the plots one diagnostics sample
// per step. Qt Core only, so it is tested without a window.
#pragma once

#include "app/core/step_history.h"
#include "app/core/step_run.h"
#include "physics/engine/interaction/mouse_spring.h"
#include "physics/engine/scene.h"
#include "physics/engine/trace.h"
#include "physics/engine/world.h"

#include <QObject>
#include <QString>

#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace rbw {

class Session : public QObject {
    Q_OBJECT
public:
    explicit Session(QObject* parent = nullptr);
    ~Session() override;

    // Starts over from this scene (validated by the caller). Emits sessionReset().
    void load(const SceneDef& scene);
    // Back to the loaded scene's initial state, keeping the student's parameters.
    void reset();
    bool isLoaded() const { return world_ != nullptr; }

    const World* world() const { return world_.get(); }
    const SceneDef& baseScene() const { return base_; }
    // The trace of the step that produced the current state; nullptr at step 0.
    const StepTrace* currentTrace() const;
    const StepHistory& history() const { return history_; }
    // The world as it was at the start of the step currentTrace() shows (its state,
    // restored from the history, in the current parameters), for the checker; nullptr
    // at step 0 or when the history no longer holds it.
    std::unique_ptr<World> worldBeforeCurrentStep() const;

    // --- parameters: each rebuilds the world from the edited scene and carries the
    // current state over, so the run continues from where it is ---
    bool setDt(double dt, QString* error = nullptr);
    bool setIntegrator(const QString& name, QString* error = nullptr);
    void setGravityEnabled(bool on);
    bool gravityEnabled() const;
    // The gravity the switch turns on: the scene's, or (0, -9.81, 0) when it has none.
    Vec3 gravityWhenOn() const;
    bool setRestitution(double c, QString* error = nullptr);
    bool setFriction(double mu, QString* error = nullptr);

    // --- stepping ---
    // One step (with the pending interaction forces). False after a blow-up.
    // Emits stepRecorded and stateChanged.
    bool step();
    // Playing: up to maxSteps steps, but stops after budgetMs of wall time so the GUI
    // stays responsive; returns the number of steps taken.
    int advance(int maxSteps, double budgetMs);
    // Restores the previous state and its trace exactly. False if there is none. The
    // later states stay in the history (the scrubber can go to them again) until a
    // step is taken from here, which discards them (editor-undo semantics).
    bool stepBack();
    // The history scrubber: makes the state after step k current (its state and trace
    // exactly as recorded, restored, never recomputed). Within the recorded history
    // this only moves the history's cursor: going back emits rewound(k), going
    // forward emits stepRecorded for each recorded step passed (so plots get their
    // samples back). Beyond the newest recorded step it steps on, at most maxNewSteps
    // new steps, until k or a blow-up. False if k is before the oldest kept state, or
    // the target was not reached (blow-up, limit).
    bool goToStep(long k, long maxNewSteps = 100000);
    const StepStatus& status() const;

    // --- stepping off the GUI thread (step_run.h; the app's Step and Play) ---
    enum class RunStart { Finished, Running, Refused };
    // Takes up to maxSteps steps as advance(maxSteps, budgetMs) does (budgetMs <= 0: no
    // limit), but on a thread of its own, and waits at most waitMs for it. If the run
    // finished by then, its steps are recorded now, exactly as step() would record them
    // (stepRecorded for each, blownUp, stateChanged), runFinished(taken) is emitted and
    // the answer is Finished. Else the answer is Running: busy() is true (busyChanged)
    // and the steps are recorded when the run finishes, from the event loop. Refused
    // (nothing happens) while busy, with nothing loaded, or after a blow-up.
    RunStart startRun(int maxSteps, double budgetMs, int waitMs);
    bool busy() const { return run_ != nullptr; }
    // Drops the running run (busyChanged(false)): the world stays at the last finished
    // step, exactly. Every call above that changes the world or the parameters (step,
    // advance, step back, go to step, reset, load, a parameter, K) cancels it first.
    void cancelRun();
    // The history scrubber's Go (issue 22): goToStep(k, maxNewSteps), but the new steps
    // beyond the recorded history are computed off the GUI thread, in runs of about
    // kGoToSliceMs of work each, recorded as each run finishes (so the history keeps to
    // its budget and the views follow), one run after another until step k, a blow-up
    // or maxNewSteps new steps. Waits at most waitMs in all. Finished: it is over, and
    // goToFinished(k, reached) has been emitted (also for a step in the recorded
    // history, which is restored at once, or a refused k). Running: busy() until it is
    // over, then goToFinished from the event loop; cancelRun() stops it at the last
    // finished step and goToFinished is not emitted.
    RunStart startGoToStep(long k, int waitMs, long maxNewSteps = 100000);
    static constexpr double kGoToSliceMs = 100.0;
    // The step startGoToStep's runs are going to, or -1 when none goes on.
    long goToTarget() const { return goToTarget_; }

    // --- interaction ---
    // The mouse spring: grab a body at a world point, move the target, release.
    void beginGrab(int body, const Vec3& p_W);
    void moveGrab(const Vec3& target_W);
    void endGrab();
    bool isGrabbing() const { return grab_.has_value(); }
    // From the picked point (now) to the target, for drawing.
    std::optional<std::pair<Vec3, Vec3>> springSegment() const;
    // The scene's keyboard push (SceneDef::push) along a world direction; it acts in
    // the next step. False if the scene has no push.
    bool push(const Vec3& direction_W);
    // Turns every switchable torque off if any is on, else on (the K key). False if
    // the scene has none.
    bool toggleTorques();
    bool torquesOn() const;
    // The pushes queued for the next step (p_W, f_W), so the view can draw them
    // before the step that applies them.
    const std::vector<std::pair<Vec3, Vec3>>& pendingPushes() const { return pendingPushes_; }

signals:
    // A new lesson, or reset: views drop what they hold.
    void sessionReset();
    // One step was taken; its trace holds the diagnostics after it. Emitted for every
    // step, also inside advance(), so plots get one sample per step.
    void stepRecorded(const rbw::StepTrace& trace);
    // The history was rewound to the current state (Step back): keep samples up to
    // and including step index `stepIndex`.
    void rewound(long stepIndex);
    // The state or the parameters changed (after a step, a batch, step back, a switch).
    void stateChanged();
    // The scene's parameters changed (a switch above, a new lesson or reset): the
    // controls that show h, the integrator, gravity, c and mu follow. Emitted before
    // the stateChanged of the same change; never for a step.
    void parametersChanged();
    // The run stopped: a non-finite value or an energy jump; the message says where.
    void blownUp(const QString& message);
    // A run started with startRun is computing (true) or over: finished, cancelled
    // or failed (false).
    void busyChanged(bool busy);
    // A run of startRun finished and its `taken` steps are recorded (0 when it failed:
    // blownUp says why).
    void runFinished(int taken);
    // startGoToStep's run is over: step k was reached, or not (a blow-up, the limit of
    // new steps, a step before the oldest kept one; the world is at the last finished
    // step). Not emitted when it was cancelled.
    void goToFinished(long k, bool reached);

private:
    bool rebuild(SceneDef edited, QString* error);
    // One step without stateChanged (advance() emits it once per batch).
    bool stepQuiet();
    // Puts the world and current_ at the history's current entry.
    void restoreCurrentEntry();
    // The grab's force and the queued pushes, on w, for its next step.
    void applyInteraction(World& w) const;
    // Records the finished run's steps (startRun).
    void finishRun();
    // Starts a run of a copy of the world (startRun, startGoToStep's slices).
    void launchRun(int maxSteps, double budgetMs);
    // The next slice of startGoToStep's run, or its end (goToFinished): false at the end.
    bool continueGoTo();
    void setBusy(bool busy);

    SceneDef base_;     // as loaded from the lesson
    SceneDef edited_;   // with the student's parameters
    std::unique_ptr<World> world_;
    StepHistory history_;
    StepTrace scratch_;
    StepTrace current_;          // the current state's trace, unpacked
    bool hasCurrent_ = false;
    std::optional<MouseSpring> grab_;
    std::vector<std::pair<Vec3, Vec3>> pendingPushes_;   // (p_W, f_W)
    std::shared_ptr<StepRun> run_;   // the run being computed (startRun), or none
    std::size_t runPushes_ = 0;      // the pushes its first step applies
    quint64 runSerial_ = 0;          // which run a queued "finished" is about
    bool busySignalled_ = false;     // busyChanged(true) was the last said
    long goToTarget_ = -1;           // startGoToStep's step k while its runs go on, else -1
    long goToLeft_ = 0;              // the new steps it may still take
};

} // namespace rbw
