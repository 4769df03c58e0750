// The JSON documents `rbw run --format json` prints (docs/cli.md). Everything is read
// from the world's state and the step traces; nothing here computes physics.
#pragma once

#include "physics/diagnostics.h"
#include "physics/step_status.h"
#include "physics/trace.h"
#include "physics/world.h"

#include <QJsonObject>
#include <QString>

#include <vector>

namespace rbw {

// The totals, and bodies[] with each body's own part (named when scene is given).
QJsonObject diagnosticsToJson(const Diagnostics& d, const SceneDef* scene = nullptr);

// { step, time, quantities: [ {id, stage, body, index?, symbol, formula, frame, unit, kind, value} ] }
QJsonObject traceToJson(const StepTrace& trace, const SceneDef& scene);

// The whole run: scene info, final time, bodies, probes, diagnostics and the traces.
QJsonObject runToJson(const World& world, const std::vector<StepTrace>& traces,
                      const QString& sceneFile);

QJsonObject blowUpToJson(const StepStatus& status, const QString& sceneFile);

} // namespace rbw
