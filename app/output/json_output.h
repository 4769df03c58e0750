// The JSON documents `rbw run --format json` prints (docs/cli.md). Everything is read
// from the world's state and the step traces; nothing here computes physics.
#pragma once

#include "physics/engine/diagnostics.h"
#include "physics/engine/step_status.h"
#include "physics/engine/trace.h"
#include "physics/engine/world.h"

#include <QIODevice>
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

// Its two halves without the traces: what is known before the first step (scene, file,
// integrator, inertia_convention, dt) and the result after the last (bodies, probes,
// diagnostics, status "ok", steps, time).
QJsonObject runHeaderToJson(const World& world, const QString& sceneFile);
QJsonObject runResultToJson(const World& world);

// { file, status "blow-up", step, body, quantity, message, kind, initial_state,
//   inputs_at_edge (and edge_inputs), index and index_kind (a trace entry with an index),
//   and the kinetic energies of an energy jump }
QJsonObject blowUpToJson(const StepStatus& status, const QString& sceneFile);

// `rbw run --format json`, written while the run goes, so that memory stays flat with
// the number of traced steps (docs/cli.md, "Streaming"). One JSON document, with the
// members of runToJson; only the order of the top-level keys differs:
//   {  <runHeaderToJson members>,
//      "trace": [ <traceToJson of each step, written as it is added> ],
//      <runResultToJson members>                                       (finish)
//   or <blowUpToJson members but "file">                               (finishBlowUp)  }
// Each member and each trace element is laid out as QJsonDocument::Indented lays it out
// in a whole document. Callers write only finite numbers (World::checkOutputs, a traced
// World::step): QJsonDocument would write a NaN or an infinity as null.
class JsonRunWriter {
public:
    JsonRunWriter(QIODevice& out, const World& world, const QString& sceneFile);

    void begin();                        // "{", the header's members, "trace": [
    void addTrace(const StepTrace& trace);
    void finish();                       // "]", the result's members, "}"
    void finishBlowUp(const StepStatus& status);   // "]", the blow-up's members, "}"

    qint64 tracesWritten() const { return traces_; }

private:
    void closeTrace();

    QIODevice& out_;
    const World& world_;
    QString file_;
    qint64 traces_ = 0;
};

} // namespace rbw
