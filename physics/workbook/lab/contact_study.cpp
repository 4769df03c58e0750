#include "physics/workbook/lab/contact_study.h"

#include "physics/engine/manifold/settings.h"
#include "physics/engine/scene_words.h"
#include "physics/engine/world.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace rbw::lab {

std::string ContactStudyRow::statusText() const
{
    return status == RunStatus::Ok ? std::string("ok") : "blown up at step " + std::to_string(blowUpStep);
}

std::vector<SceneIssue> validateContactStudy(const ContactStudyConfig& config)
{
    std::vector<SceneIssue> issues;
    if (!config.course && !config.softStep && config.iterations.empty()) {
        issues.push_back({"iterations", "no model to run: give solver iterations or keep the course model or the soft step"});
    }
    for (const int it : config.iterations) {
        if (it < 1 || it > 1000) {
            issues.push_back({"iterations", "must be whole numbers from 1 to 1000, got " + std::to_string(it)});
        }
    }
    if (!(config.tEnd > 0.0) || !std::isfinite(config.tEnd)) {
        issues.push_back({"t_end", "must be a finite number > 0"});
    }
    if (config.dts.empty()) issues.push_back({"dt", "give at least one step size"});
    for (const double h : config.dts) {
        if (!(h > 0.0) || !std::isfinite(h)) {
            issues.push_back({"dt", "must be finite numbers > 0"});
        } else if (std::isfinite(config.tEnd) && config.tEnd > 0.0 && config.tEnd / h > double(kMaxStudySteps)) {
            issues.push_back({"dt", "t_end / dt must be at most " + std::to_string(kMaxStudySteps) + " steps"});
        }
    }
    if (config.problem == ContactProblem::Rain && (config.rainBoxes < 1 || config.rainBoxes > 10000)) {
        issues.push_back({"boxes", "must be a whole number from 1 to 10000, got " + std::to_string(config.rainBoxes)});
    }
    return issues;
}

namespace {

// iterations: the sequential impulses' solver iterations; 0 with the course model and
// the soft step (which runs its default substeps)
ContactStudyRow runOne(const ContactStudyConfig& config, ContactModel model, bool softStep, int iterations, double h,
                       const std::atomic<bool>* cancel)
{
    SceneDef scene = contactProblemScene(config.problem, model, config.rainBoxes);
    scene.dt = h;
    // N = T/h, to the nearest step (T = 10, h = 1/60 gives 600)
    const long steps = std::max(1L, std::lround(config.tEnd / h));
    scene.steps = steps;
    if (softStep) {
        scene.solver = ManifoldSolver::SoftStep;
    } else if (model == ContactModel::Manifold) {
        scene.solver = ManifoldSolver::SequentialImpulses;   // not the default any more
        scene.solverIterations = iterations;
    }

    ContactStudyRow row;
    // the model by its scene word (scene_words.h): "course", "manifold", or the soft step's "soft-step"
    row.model = softStep ? std::string(sceneWord(ManifoldSolver::SoftStep)) : std::string(sceneWord(model));
    row.iterations = model == ContactModel::Course ? 0 : (softStep ? manifoldSettings(scene).substeps : iterations);
    row.dt = h;
    row.steps = steps;
    row.tEnd = double(steps) * h;

    World world(scene);
    const std::vector<BodyState> start = world.states();
    // E = T + V; the most it ever rose above E_0
    const double E0 = world.diagnostics().total;
    using Clock = std::chrono::steady_clock;
    Clock::duration stepping{};
    for (long k = 0; k < steps; ++k) {
        if (cancel != nullptr && cancel->load()) break;
        const Clock::time_point t0 = Clock::now();
        const StepStatus& status = world.step(nullptr);
        stepping += Clock::now() - t0;
        if (!status.ok) {
            row.status = RunStatus::BlownUp;
            row.blowUpStep = status.step;
            row.blowUpMessage = status.message;
            row.steps = k;
            return row;
        }
        const ContactMeasure m = measureContacts(scene, world.massProperties(), world.states());
        row.deepestOverlap = std::max(row.deepestOverlap, m.deepestOverlap);
        row.deepestBelow = std::max(row.deepestBelow, m.deepestBelow);
        row.energyGained = std::max(row.energyGained, world.diagnostics().total - E0);
        if (k + 1 == steps) {
            row.kineticEnergyEnd = m.kineticEnergy;
            row.movingEnd = m.moving;
        }
    }
    row.nsPerStep = double(std::chrono::duration_cast<std::chrono::nanoseconds>(stepping).count()) / double(steps);
    if (config.problem != ContactProblem::Rain) {
        double drift = 0.0;
        for (std::size_t b = 0; b < start.size(); ++b) {
            drift = std::max(drift, (world.states()[b].x_W - start[b].x_W).norm());
        }
        row.drift = drift;
    }
    return row;
}

} // namespace

ContactStudyResult runContactStudy(const ContactStudyConfig& config, const StudyProgress& progress,
                                   const std::atomic<bool>* cancel)
{
    ContactStudyResult result;
    result.problem = contactProblemName(config.problem);
    struct Run {
        ContactModel model;
        bool softStep;
        int iterations;
        double h;
    };
    std::vector<Run> runs;
    if (config.course) {
        for (const double h : config.dts) runs.push_back({ContactModel::Course, false, 0, h});
    }
    if (config.softStep) {
        for (const double h : config.dts) runs.push_back({ContactModel::Manifold, true, 0, h});
    }
    for (const int it : config.iterations) {
        for (const double h : config.dts) runs.push_back({ContactModel::Manifold, false, it, h});
    }
    result.runsPlanned = static_cast<int>(runs.size());
    for (const Run& r : runs) {
        if (cancel != nullptr && cancel->load()) {
            result.cancelled = true;
            break;
        }
        result.rows.push_back(runOne(config, r.model, r.softStep, r.iterations, r.h, cancel));
        if (progress) progress(static_cast<int>(result.rows.size()), result.runsPlanned);
    }
    return result;
}

} // namespace rbw::lab
