// An exercise drawn from a seed (docs/exercises.md): every vary rule of the spec gets a
// value from its grid (value_grid.h), the scene goes through the scene loader
// (parseScene) and is run by the physics; one that fails to load, blows up or loses the
// lesson's point (a "require") is replaced by the next sub-seed's, a bounded number of
// times. The answer key is the physics' own trace of the lesson's step: nothing here
// recomputes a physical quantity.
#pragma once

#include "app/exercise/exercise_spec.h"
#include "physics/engine/scene.h"
#include "physics/engine/trace.h"

#include <QByteArray>
#include <QStringList>

#include <cstdint>
#include <optional>
#include <vector>

namespace rbw {

struct GeneratedExercise {
    QByteArray sceneJson;        // the new scene file, indented JSON
    std::optional<SceneDef> scene;
    std::uint64_t seed = 0;
    int attempt = 0;             // which sub-seed gave it (0: the seed itself)
    long answerStep = 0;
    std::vector<BodyState> startStates;   // every body's state at the start of that step (the physics')
    StepTrace answerTrace;       // the physics' trace of that step
    std::vector<TraceEntry> key; // the answer-table entries of that trace, in trace order
    QStringList errors;          // why no scene could be made; empty on success
    bool ok() const { return errors.isEmpty() && scene.has_value(); }
};

// The same bytes for a seed on every machine and standard library.
GeneratedExercise generateExercise(const ExerciseSpec& spec, std::uint64_t seed);

} // namespace rbw
