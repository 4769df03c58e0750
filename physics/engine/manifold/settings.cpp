#include "physics/engine/manifold/settings.h"

#include "physics/engine/scene_words.h"

#include <string>

namespace rbw {

ManifoldSettings manifoldSettings(const SceneDef& scene)
{
    // The defaults are ManifoldSettings' own (settings.h); a scene's key replaces one.
    ManifoldSettings s;
    if (scene.solverIterations) s.iterations = static_cast<int>(*scene.solverIterations);
    if (scene.sleep) s.sleep = *scene.sleep;
    if (scene.positionFix) s.positionFix = *scene.positionFix;
    if (scene.solver) s.solver = *scene.solver;
    if (scene.substeps) s.substeps = static_cast<int>(*scene.substeps);
    return s;
}

// The contact model's keys (docs/scene-format.md, "contact_model"): the manifold
// model's own keys only with it, the course model's correction switches only without it,
// and an iteration count a step can afford.
void checkContactModel(std::vector<SceneIssue>& out, const SceneDef& scene)
{
    if (scene.contactModel != ContactModel::Course && scene.contactModel != ContactModel::Manifold) {
        out.push_back({"contact_model", "must be " + sceneWordChoices<ContactModel>()});
        return;
    }
    if (scene.contactModel == ContactModel::Course) {
        const std::string hint = " belongs to the manifold model; add \"contact_model\": \"" +
                                 std::string(sceneWord(ContactModel::Manifold)) + "\" or leave it out";
        if (scene.solverIterations) out.push_back({"solver_iterations", std::string("the key") + hint});
        if (scene.sleep) out.push_back({"sleep", std::string("the key") + hint});
        if (scene.positionFix) out.push_back({"position_fix", std::string("the key") + hint});
        if (scene.solver) out.push_back({"solver", std::string("the key") + hint});
        if (scene.substeps) out.push_back({"substeps", std::string("the key") + hint});
        return;
    }
    if (scene.solverIterations && !(*scene.solverIterations >= 1 && *scene.solverIterations <= 1000)) {
        out.push_back({"solver_iterations", "must be a whole number from 1 to 1000, got " +
                                                std::to_string(*scene.solverIterations)});
    }
    if (scene.positionFix && *scene.positionFix != PositionFix::Ngs && *scene.positionFix != PositionFix::Baumgarte &&
        *scene.positionFix != PositionFix::None) {
        out.push_back({"position_fix", "must be " + sceneWordChoices<PositionFix>()});
    }
    if (scene.solver && *scene.solver != ManifoldSolver::SequentialImpulses && *scene.solver != ManifoldSolver::SoftStep) {
        out.push_back({"solver", "must be " + sceneWordChoices<ManifoldSolver>()});
    }
    // The solver the scene runs: its own "solver" or the default (the soft step)
    const bool softStep = (scene.solver ? *scene.solver : ManifoldSettings{}.solver) == ManifoldSolver::SoftStep;
    if (softStep) {
        // The soft step has its own iterations (one solve and one relax per substep) and
        // its own position correction (the push-out inside the substeps).
        const std::string which = scene.solver ? "" : " (the manifold model's default solver)";
        const std::string hint = scene.solver ? ""
                                              : "; add \"solver\": \"" +
                                                    std::string(sceneWord(ManifoldSolver::SequentialImpulses)) +
                                                    "\" to use it";
        if (scene.solverIterations) {
            out.push_back({"solver_iterations", "belongs to the sequential impulses; the soft step" + which +
                                                    " iterates once per substep (\"substeps\")" + hint});
        }
        if (scene.positionFix) {
            out.push_back({"position_fix", "belongs to the sequential impulses; the soft step" + which +
                                               " pushes overlap out inside its substeps" + hint});
        }
    } else if (scene.substeps) {
        out.push_back({"substeps", "belongs to the soft step; add \"solver\": \"" +
                                    std::string(sceneWord(ManifoldSolver::SoftStep)) + "\""});
    }
    if (scene.substeps && !(*scene.substeps >= 1 && *scene.substeps <= 64)) {
        out.push_back({"substeps", "must be a whole number from 1 to 64, got " + std::to_string(*scene.substeps)});
    }
    if (scene.positionCorrection) {
        out.push_back({"position_correction", "belongs to the course model; the manifold model fixes positions "
                                              "itself (\"position_fix\")"});
    }
    if (scene.planeContacts != PlaneContactMode::PerPoint) {
        out.push_back({"plane_contacts", "belongs to the course model; the manifold model keeps every corner "
                                         "below a plane as a point of its manifold"});
    }
}

} // namespace rbw
