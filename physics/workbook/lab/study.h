// The accuracy study: every chosen integrator at every chosen step size h on one
// scene with an exact answer (exact_motion.h), from t = 0 to the same end time T.
// For each run it reports the error at T against the exact answer, the largest
// relative drift of the energy and of |L| over the run, the wall time per step and
// the number of steps: the numbers behind the speed/accuracy trade (`rbw study`,
// the app's Accuracy tab, docs/accuracy-lab.md).
//
// Glossary
//   h (dt)       step size of one run                                   [s]
//   T (tEnd)     end time, the same for every run; N = T/h steps         [s]
//   e_x          |x(T) - x_exact(T)|                                     [m]
//   e_q          angle of q_exact(T)^-1 q(T), the orientation error     [rad]
//   e_w          |omega_W(T) - omega_exact,W(T)|                         [rad/s]
//   dE           max_k |E_k - E_0| / |E_0|, E = kinetic + potential      [-]
//   dL           max_k ||L_k| - |L_0|| / |L_0|                           [-]
#pragma once

#include "physics/engine/scene.h"

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rbw::lab {

struct StudyConfig {
    std::vector<std::string> integrators;   // names; empty: every integrator of the catalogue
    std::vector<double> dts;                // step sizes; empty: defaultStudyDts()
    std::optional<double> tEnd;             // T; default: scene.steps * scene.dt
    // Wall-time measurement per run: repeated short runs (trace off) until this much
    // time has passed, at least 3 of them; the fastest repetition counts.
    double timingBudgetSeconds = 0.02;
    long timingStepsPerRepeat = 2000;       // at most this many steps per repetition
};

// 0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001
std::vector<double> defaultStudyDts();

// The largest number of steps one run may take (T/h).
constexpr long kMaxStudySteps = 10'000'000;

// What is wrong with a study before it runs: the scene's own issues (validate()), an
// unknown integrator, a bad h or T, an h that does not divide T into whole steps, and
// a scene without an exact answer (ExactMotion::fromScene's reasons). Empty: it can run.
// Fields are named as on the command line ("integrators", "dt", "t_end") or as in
// the scene file ("bodies", "planes", ...).
std::vector<SceneIssue> validateStudy(const SceneDef& scene, const StudyConfig& config);

enum class RunStatus { Ok, BlownUp };

struct StudyRow {
    std::string integrator;
    double dt = 0.0;
    long steps = 0;          // N = T/h; for a blown-up run, the steps it took before
    double tEnd = 0.0;
    RunStatus status = RunStatus::Ok;
    long blowUpStep = -1;    // the step k that blew up
    std::string blowUpMessage;
    // Empty for a blown-up run (no numbers are shown for it), and where a relative
    // drift has no reference (E0 = 0 or |L0| = 0).
    std::optional<double> positionError;      // e_x [m]
    std::optional<double> orientationError;   // e_q [rad]
    std::optional<double> omegaError;         // e_w [rad/s]
    std::optional<double> energyDrift;        // dE
    std::optional<double> momentumDrift;      // dL
    std::optional<double> nsPerStep;          // wall time per step, trace off [ns]

    // "ok" or "blown up at step k"
    std::string statusText() const;
    // ns per step times N: the cost of reaching T [ns]; empty if not measured
    std::optional<double> totalNs() const;
};

struct StudyResult {
    std::string sceneName;
    std::string reference;    // ExactMotion::describe()
    double tEnd = 0.0;
    int runsPlanned = 0;      // integrators x dts
    bool cancelled = false;   // stopped early: rows holds only the runs that finished
    std::vector<StudyRow> rows;   // integrator-major, each integrator's dts in the given order
};

// Called after each run with (runs finished, runs planned), from the thread that runs
// the study.
using StudyProgress = std::function<void(int done, int total)>;

// Runs the study. Precondition: validateStudy(scene, config) is empty. If cancel is
// set (from any thread) the running run stops within a step and the result is
// returned with cancelled = true.
StudyResult runStudy(const SceneDef& scene, const StudyConfig& config, const StudyProgress& progress = {},
                     const std::atomic<bool>* cancel = nullptr);

// The angle of the rotation q_a^-1 q_b, in [0, pi]  [rad]
double orientationAngle(const Quat& q_a, const Quat& q_b);

} // namespace rbw::lab
