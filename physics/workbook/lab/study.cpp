#include "physics/workbook/lab/study.h"

#include "physics/engine/integrator_registry.h"
#include "physics/workbook/lab/exact_motion.h"
#include "physics/engine/world.h"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace rbw::lab {

namespace {

// T/h counts as whole within this relative tolerance (0.3/0.1 = 2.9999999999999996).
constexpr double kWholeSteps = 1e-9;

std::string number(double x)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", x);
    return buf;
}

std::vector<std::string> chosenIntegrators(const StudyConfig& config)
{
    if (!config.integrators.empty()) return config.integrators;
    std::vector<std::string> all;
    for (const IntegratorInfo& info : integratorCatalogue()) all.emplace_back(info.name);
    return all;
}

std::vector<double> chosenDts(const StudyConfig& config)
{
    return config.dts.empty() ? defaultStudyDts() : config.dts;
}

double chosenEnd(const SceneDef& scene, const StudyConfig& config)
{
    return config.tEnd ? *config.tEnd : double(scene.steps) * scene.dt;
}

bool cancelled(const std::atomic<bool>* cancel)
{
    return cancel != nullptr && cancel->load(std::memory_order_relaxed);
}

// The scene of one run: the study's scene with this integrator and h.
SceneDef runScene(const SceneDef& scene, const std::string& integrator, double dt, long steps)
{
    SceneDef s = scene;
    s.integrator = integrator;
    s.dt = dt;
    s.steps = steps;
    return s;
}

// Wall time per step with the trace off: repeated short runs from t = 0, each on a
// fresh world (built outside the clock); the fastest repetition is the least
// disturbed by other work on the machine.
std::optional<double> measureNsPerStep(const SceneDef& scene, long steps, const StudyConfig& config,
                                       const std::atomic<bool>* cancel)
{
    using Clock = std::chrono::steady_clock;
    const long n = std::max(1L, std::min(steps, config.timingStepsPerRepeat));
    const Clock::time_point start = Clock::now();
    double best = -1.0;
    for (int rep = 0;; ++rep) {
        if (cancelled(cancel)) return std::nullopt;
        World world(scene);
        const Clock::time_point t0 = Clock::now();
        long k = 0;
        for (; k < n; ++k) {
            if (!world.step(nullptr).ok) break;
        }
        const Clock::time_point t1 = Clock::now();
        if (k > 0) {
            const double ns = std::chrono::duration<double, std::nano>(t1 - t0).count() / double(k);
            best = best < 0.0 ? ns : std::min(best, ns);
        }
        const double elapsed = std::chrono::duration<double>(t1 - start).count();
        if (rep >= 2 && elapsed >= config.timingBudgetSeconds) break;
    }
    if (best < 0.0) return std::nullopt;
    return best;
}

// One run: N steps with the integrator, the drifts along the way, the errors at T.
// Returns false if cancelled.
bool runOne(const SceneDef& scene, const reference::ExactState& atEnd,
            const StudyConfig& config, StudyRow& row, const std::atomic<bool>* cancel)
{
    World world(runScene(scene, row.integrator, row.dt, row.steps));
    const double E0 = world.diagnostics().total;
    const double L0 = world.states()[0].L_W.norm();
    double maxEnergyDrift = 0.0;
    double maxMomentumDrift = 0.0;
    for (long k = 0; k < row.steps; ++k) {
        if (cancelled(cancel)) return false;
        const StepStatus status = world.step(nullptr);
        if (!status.ok) {
            row.status = RunStatus::BlownUp;
            row.blowUpStep = status.step;
            row.blowUpMessage = status.message;
            row.steps = k;
            return true;
        }
        // dE = max |E_k - E_0| / |E_0|,  dL = max ||L_k| - |L_0|| / |L_0|
        const double E = world.diagnostics().total;
        const double L = world.states()[0].L_W.norm();
        if (E0 != 0.0) maxEnergyDrift = std::max(maxEnergyDrift, std::abs(E - E0) / std::abs(E0));
        if (L0 != 0.0) maxMomentumDrift = std::max(maxMomentumDrift, std::abs(L - L0) / L0);
        // A run whose energy overflows has blown up even while x, r, L are finite.
        if (!std::isfinite(maxEnergyDrift) || !std::isfinite(maxMomentumDrift)) {
            row.status = RunStatus::BlownUp;
            row.blowUpStep = k;
            row.blowUpMessage = "the energy or |L| overflowed in step " + std::to_string(k) +
                                ". Try a smaller dt or another integrator.";
            row.steps = k + 1;
            return true;
        }
    }
    const BodyState& s = world.states()[0];
    // e_x = |x(T) - x_exact(T)|, e_q = angle(q_exact^-1 q), e_w = |omega - omega_exact|
    const double ex = (s.x_W - atEnd.x_W).norm();
    const double eq = orientationAngle(atEnd.q_WB, s.q_WB);
    const double ew = (s.omega_W - atEnd.omega_W).norm();
    if (!std::isfinite(ex) || !std::isfinite(eq) || !std::isfinite(ew)) {
        row.status = RunStatus::BlownUp;
        row.blowUpStep = row.steps - 1;
        row.blowUpMessage = "the error at the end time is not finite. Try a smaller dt or another integrator.";
        return true;
    }
    row.positionError = ex;
    row.orientationError = eq;
    row.omegaError = ew;
    if (E0 != 0.0) row.energyDrift = maxEnergyDrift;
    if (L0 != 0.0) row.momentumDrift = maxMomentumDrift;
    row.nsPerStep = measureNsPerStep(runScene(scene, row.integrator, row.dt, row.steps), row.steps, config, cancel);
    return !cancelled(cancel);
}

} // namespace

std::vector<double> defaultStudyDts() { return {0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001}; }

double orientationAngle(const Quat& q_a, const Quat& q_b)
{
    // d = q_a^-1 q_b = [cos(a/2), n sin(a/2)]  =>  a = 2 atan2(|d.vec|, |d.w|)
    // (atan2 stays accurate for small angles, where acos(d.w) loses half the digits)
    const Quat d = q_a.normalized().conjugate() * q_b.normalized();
    return 2.0 * std::atan2(d.vec().norm(), std::abs(d.w()));
}

std::string StudyRow::statusText() const
{
    if (status == RunStatus::BlownUp) return "blown up at step " + std::to_string(blowUpStep);
    return "ok";
}

std::optional<double> StudyRow::totalNs() const
{
    if (!nsPerStep) return std::nullopt;
    return *nsPerStep * double(steps);
}

std::vector<SceneIssue> validateStudy(const SceneDef& scene, const StudyConfig& config)
{
    std::vector<SceneIssue> issues = validate(scene);
    if (!issues.empty()) return issues;

    for (const std::string& name : chosenIntegrators(config)) {
        if (!makeIntegrator(name)) {
            issues.push_back({"integrators", "unknown integrator \"" + name + "\"; known: " + integratorNames()});
        }
    }
    const double T = chosenEnd(scene, config);
    const bool endOk = std::isfinite(T) && T > 0.0;
    if (!endOk) {
        issues.push_back({"t_end", "must be a finite number > 0, got " + number(T) +
                                       (config.tEnd ? "" : " (the scene's steps x dt)")});
    }
    for (double dt : chosenDts(config)) {
        if (!(std::isfinite(dt) && dt > 0.0)) {
            issues.push_back({"dt", "must be a finite number > 0, got " + number(dt)});
            continue;
        }
        if (!endOk) continue;
        // N = T/h must be a whole number, so every run ends at the same T.
        const double n = T / dt;
        if (n > double(kMaxStudySteps)) {
            issues.push_back({"dt", number(dt) + " needs " + number(n) + " steps to reach t_end = " + number(T) +
                                        ", more than the limit " + std::to_string(kMaxStudySteps)});
        } else if (std::abs(n - std::round(n)) > kWholeSteps * n || std::round(n) < 1.0) {
            issues.push_back({"dt", number(dt) + " does not divide t_end = " + number(T) + " into whole steps (" +
                                        number(n) + " steps)"});
        }
    }
    if (!(config.timingBudgetSeconds >= 0.0) || config.timingStepsPerRepeat < 1) {
        issues.push_back({"timing", "the timing budget must be >= 0 s and the steps per repetition >= 1"});
    }
    std::vector<SceneIssue> reasons;
    if (!ExactMotion::fromScene(scene, reasons)) {
        issues.insert(issues.end(), reasons.begin(), reasons.end());
    }
    return issues;
}

StudyResult runStudy(const SceneDef& scene, const StudyConfig& config, const StudyProgress& progress,
                     const std::atomic<bool>* cancel)
{
    assert(validateStudy(scene, config).empty());
    std::vector<SceneIssue> reasons;
    const std::optional<ExactMotion> exact = ExactMotion::fromScene(scene, reasons);
    const std::vector<std::string> integrators = chosenIntegrators(config);
    const std::vector<double> dts = chosenDts(config);

    StudyResult result;
    result.sceneName = scene.name;
    result.reference = exact->describe();
    result.tEnd = chosenEnd(scene, config);
    result.runsPlanned = int(integrators.size() * dts.size());
    // The exact state at T, the same for every run.
    const reference::ExactState atEnd = exact->at(result.tEnd);

    int done = 0;
    for (const std::string& name : integrators) {
        for (double dt : dts) {
            StudyRow row;
            row.integrator = name;
            row.dt = dt;
            row.steps = std::lround(result.tEnd / dt);
            row.tEnd = result.tEnd;
            if (!runOne(scene, atEnd, config, row, cancel)) {
                result.cancelled = true;
                return result;
            }
            result.rows.push_back(std::move(row));
            ++done;
            if (progress) progress(done, result.runsPlanned);
        }
    }
    return result;
}

} // namespace rbw::lab
