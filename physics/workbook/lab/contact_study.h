// The speed/accuracy trade of contacts (issue 11, docs/accuracy-lab.md): one contact
// problem (contact_problems.h) in the course model, in the manifold model's soft step
// (soft_step_solver.h, at its default substeps) and in the manifold model's sequential
// impulses at each chosen solver iteration count: three solvers, at each chosen step
// size h, from t = 0 to T. For each
// run it reports what the contacts got wrong against what the run cost:
//   overlap   the deepest box-box overlap over the run (measured after every step)  [m]
//   below     the deepest corner below the ground over the run                      [m]
//   drift     the largest |x(T) - x(0)| of any box: a resting box and a standing
//             tower should not move (empty for the rain, whose boxes fall)          [m]
//   gained    the most total energy (kinetic + potential) the run ever had above its
//             start, max_k (E_k - E_0): contacts that add energy show here          [J]
//   KE(T)     the kinetic energy at T; moving(T): bodies faster than 0.01 m/s
//   ns/step   the wall time of the steps alone (the measuring is not timed)        [ns]
// `rbw contact-study` writes it as CSV (app/output/study_csv.h).
#pragma once

#include "physics/workbook/lab/contact_problems.h"
#include "physics/workbook/lab/study.h"

#include <atomic>
#include <optional>
#include <string>
#include <vector>

namespace rbw::lab {

struct ContactStudyConfig {
    ContactProblem problem = ContactProblem::RestingBox;
    int rainBoxes = 100;
    bool course = true;                      // also run the course model (once per h)
    bool softStep = true;                    // also run the manifold model's soft step (once per h, its default substeps)
    std::vector<int> iterations{1, 2, 4, 8, 16};   // the manifold model's solver iterations
    std::vector<double> dts{1.0 / 30.0, 1.0 / 60.0, 1.0 / 120.0};
    double tEnd = 10.0;                      // T [s]
};

struct ContactStudyRow {
    std::string model;    // "course", "manifold" (sequential impulses) or "soft-step" (the manifold model's soft step)
    int iterations = 0;   // solver iterations (manifold), substeps (soft step); 0 for the course model
    double dt = 0.0;
    long steps = 0;       // N = round(T/h); for a blown-up run, the steps it took before
    double tEnd = 0.0;
    RunStatus status = RunStatus::Ok;
    long blowUpStep = -1;
    std::string blowUpMessage;
    double deepestOverlap = 0.0;
    double deepestBelow = 0.0;
    std::optional<double> drift;
    double energyGained = 0.0;
    double kineticEnergyEnd = 0.0;
    int movingEnd = 0;
    double nsPerStep = 0.0;

    std::string statusText() const;   // "ok" or "blown up at step k"
};

struct ContactStudyResult {
    std::string problem;
    int runsPlanned = 0;
    bool cancelled = false;
    std::vector<ContactStudyRow> rows;   // course first, then the soft step, then the manifold by iterations; each by h
};

// What is wrong with a configuration: no model to run, iterations < 1, h not > 0 or
// not dividing T into at most kMaxStudySteps steps, T not > 0, rainBoxes out of
// 1..10000. Fields: "iterations", "dt", "t_end", "boxes". Empty: it can run.
std::vector<SceneIssue> validateContactStudy(const ContactStudyConfig& config);

// Runs it. Precondition: validateContactStudy(config) is empty.
ContactStudyResult runContactStudy(const ContactStudyConfig& config, const StudyProgress& progress = {},
                                   const std::atomic<bool>* cancel = nullptr);

} // namespace rbw::lab
