// Builds a world's pipeline from what its scene declares: only the stages the scene
// needs. World::step() runs the list it returns. The order: stages/pipeline_builder.cpp.
#pragma once

#include "physics/engine/stages/stage.h"

#include <memory>
#include <string>
#include <vector>

namespace rbw {

// Creation options of a world that are not part of a scene.
struct WorldOptions {
    // Run every stage whether the scene needs it or not: gravity (also with g = 0), the
    // box-box broad and narrow phases for any two bodies (also with box_collisions off)
    // and the plane tests against the scene's planes. For benchmarks that measure what
    // the minimal pipeline saves; results equal the minimal pipeline's as long as no
    // two bodies touch when box_collisions is off.
    bool allStages = false;
    // Threads the manifold model's soft step may use (1 or 2): with 2, a step with
    // enough contacts solves its islands in lanes shared by two threads
    // (manifold/solver_islands.h). The results are the same bits for 1 and 2.
    int contactThreads = 2;
};

// One entry of the pipeline: the stage object that runs, and its description, read
// from that object (so the description is what runs).
struct PipelineEntry {
    PipelineStage stage;
    std::string integrator;    // Integration only: the integrator's name
    std::vector<int> bodies;   // Integration only: the bodies it advances (movable ones)
    std::unique_ptr<PipelineStep> step;

    explicit PipelineEntry(std::unique_ptr<PipelineStep> s);
    // "integration:rk4" for an integration entry, else the stage name.
    std::string label() const;
};

// The bodies grouped by their integrator's name, in the order the names first appear.
struct IntegratorGroups {
    std::vector<std::string> names;   // per group
    std::vector<int> groupOf;         // per body
};
IntegratorGroups integratorGroups(const SceneDef& scene);

std::vector<PipelineEntry> buildPipeline(const SceneDef& scene, const std::vector<MassProperties>& mass,
                                         const std::vector<char>& movable, const IntegratorGroups& groups,
                                         const WorldOptions& options);

} // namespace rbw
