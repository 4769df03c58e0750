#include "app/output/json_output.h"

#include "app/output/json_text.h"
#include "app/output/value_format.h"
#include "physics/engine/diagnostic_catalogue.h"
#include "physics/engine/inertia.h"
#include "physics/engine/quantities.h"
#include "physics/engine/scene_words.h"

#include <QJsonArray>

namespace rbw {

namespace {

QJsonValue bodyName(const SceneDef& scene, int body)
{
    if (body < 0) {
        return QJsonValue::Null;
    }
    return QString::fromStdString(scene.bodies[body].name);
}

// The convention's word, as the scene file spells it (physics/engine/scene_words.h).
QString conventionName(InertiaConvention c)
{
    const std::string_view w = sceneWord(c);
    return QString::fromLatin1(w.data(), static_cast<qsizetype>(w.size()));
}

QString idOf(std::string_view id)
{
    return QString::fromLatin1(id.data(), static_cast<qsizetype>(id.size()));
}

QString idOf(const QuantityInfo& q)
{
    return QString::fromLatin1(q.id);
}

// Every diagnostic of the catalogue (diagnostic_catalogue.h) under its id.
template <typename Of, std::size_t N>
void insertDiagnostics(QJsonObject& o, const DiagnosticInfo<Of> (&table)[N], const Of& d)
{
    for (const DiagnosticInfo<Of>& info : table) {
        if (info.scalar != nullptr) {
            o.insert(idOf(info.id), d.*info.scalar);
        } else {
            o.insert(idOf(info.id), jsonVec3(d.*info.vector));
        }
    }
}

} // namespace

QJsonObject diagnosticsToJson(const Diagnostics& d, const SceneDef* scene)
{
    // bodies[]: each body's own part, in scene order (named when the scene is known).
    QJsonArray bodies;
    for (int b = 0; b < static_cast<int>(d.bodies.size()); ++b) {
        QJsonObject o;
        insertDiagnostics(o, kBodyDiagnostics, d.bodies[b]);
        if (scene != nullptr && b < static_cast<int>(scene->bodies.size())) {
            o.insert("body", bodyName(*scene, b));
        }
        bodies.append(o);
    }
    QJsonObject world;
    insertDiagnostics(world, kWorldDiagnostics, d);
    world.insert("bodies", bodies);
    return world;
}

QJsonObject traceToJson(const StepTrace& trace, const SceneDef& scene)
{
    QJsonArray quantities;
    for (const TraceEntry& e : trace.entries) {
        QJsonObject q{
            {"id", e.info->id},
            {"stage", stageName(e.info->stage)},
            {"body", bodyName(scene, e.body)},
            {"symbol", e.info->symbol},
            {"formula", e.info->formula},
            {"frame", frameName(e.info->frame)},
            {"unit", QString::fromUtf8(e.info->unit)},
            {"kind", valueKind(e.value)},
            {"value", jsonValue(e.value)},
            {"source", QString::fromStdString(sourceText(e))},
        };
        if (e.index >= 0) {
            q.insert("index", e.index);
            q.insert("index_kind", indexKindName(e.info->indexKind));
        }
        quantities.append(q);
    }
    // contacts[]: each contact's header, and its Stage::Collision entries keyed by id.
    QJsonArray contacts;
    for (int k = 0; k < static_cast<int>(trace.contacts.size()); ++k) {
        const ContactHeader& c = trace.contacts[k];
        QJsonArray names{bodyName(scene, c.bodyA)};
        names.append(c.plane >= 0 ? QJsonValue(QString::fromStdString(scene.planes[c.plane].name))
                                  : bodyName(scene, c.bodyB));
        QJsonObject contact{
            {"bodies", names},
            {"feature", c.feature},
            {"resolution", c.resolution},
            {"points_averaged", c.pointCount},
            {"separating", c.separating},
        };
        // and where each was computed: "sources": {"impulse": "physics/engine/course/impulse.cpp:112", ...}
        QJsonObject sources;
        for (const TraceEntry& e : trace.entries) {
            if (e.info->stage == Stage::Collision && e.index == k) {
                contact.insert(QString::fromLatin1(e.info->id), jsonValue(e.value));
                sources.insert(QString::fromLatin1(e.info->id), QString::fromStdString(sourceText(e)));
            }
        }
        contact.insert("sources", sources);
        // iterations[]: the manifold solver's accumulated impulses after each iteration
        if (!c.iterations.empty()) {
            QJsonArray iterations;
            for (const ImpulseIterate& it : c.iterations) {
                iterations.append(QJsonObject{{"normal_impulse", it.lambda_n}, {"tangent_impulse", jsonVec3(it.lambda_t_W)}});
            }
            contact.insert("iterations", iterations);
        }
        contacts.append(contact);
    }
    // start: the state the step started from (StepTrace::start), per body and probe.
    QJsonArray startBodies;
    for (int b = 0; b < static_cast<int>(trace.start.bodies.size()); ++b) {
        const BodyState& s = trace.start.bodies[static_cast<size_t>(b)];
        startBodies.append(QJsonObject{
            {"name", bodyName(scene, b)},
            {idOf(q::position), jsonVec3(s.x_W)},
            {idOf(q::linear_velocity), jsonVec3(s.v_W)},
            {idOf(q::orientation), jsonQuat(s.q_WB)},
            {idOf(q::angular_momentum), jsonVec3(s.L_W)},
            {idOf(q::rotation_matrix), jsonMat3(s.R_WB)},
            {idOf(q::inverse_inertia_world), jsonMat3(s.Iinv_W)},
            {idOf(q::angular_velocity), jsonVec3(s.omega_W)},
        });
    }
    QJsonArray startProbes;
    for (const ProbeSample& p : trace.start.probes) {
        startProbes.append(QJsonObject{
            {"body", bodyName(scene, p.body)},
            {"point", jsonVec3(p.p_W)},
            {"velocity", jsonVec3(p.v_W)},
        });
    }
    return QJsonObject{
        {"step", static_cast<qint64>(trace.step)},
        {"time", trace.time},
        {"start", QJsonObject{{"bodies", startBodies}, {"probes", startProbes}}},
        {"quantities", quantities},
        {"contacts", contacts},
        {"diagnostics", diagnosticsToJson(trace.diagnostics, &scene)},
    };
}

QJsonObject runHeaderToJson(const World& world, const QString& sceneFile)
{
    const SceneDef& scene = world.scene();
    return QJsonObject{
        {"scene", QString::fromStdString(scene.name)},
        {"file", sceneFile},
        {"integrator", QString::fromLatin1(world.integrator().name())},
        {"inertia_convention", conventionName(scene.inertiaConvention)},
        {"dt", scene.dt},
    };
}

QJsonObject runResultToJson(const World& world)
{
    const SceneDef& scene = world.scene();
    QJsonArray bodies;
    for (int b = 0; b < static_cast<int>(scene.bodies.size()); ++b) {
        const BodyState& s = world.states()[b];
        bodies.append(QJsonObject{
            {"name", QString::fromStdString(scene.bodies[b].name)},
            {"fixed", scene.bodies[b].fixed},
            {"integrator", QString::fromLatin1(world.integratorOf(b).name())},
            {"inertia_convention", conventionName(world.conventionOf(b))},
            {idOf(q::position), jsonVec3(s.x_W)},
            {idOf(q::orientation), jsonQuat(s.q_WB)},
            {idOf(q::linear_velocity), jsonVec3(s.v_W)},
            {idOf(q::angular_velocity), jsonVec3(s.omega_W)},
            {idOf(diag::linear_momentum.id), jsonVec3(linearMomentum(world.massProperties()[b], s))},
            {idOf(q::angular_momentum), jsonVec3(s.L_W)},
            {idOf(q::inverse_inertia_world), jsonMat3(s.Iinv_W)},
        });
    }
    QJsonArray probes;
    for (int i = 0; i < static_cast<int>(scene.probes.size()); ++i) {
        const ProbeReading r = world.probe(i);
        probes.append(QJsonObject{
            {"body", bodyName(scene, r.body)},
            {"initial_point", jsonVec3(scene.probes[i].p0_W)},
            {"point", jsonVec3(r.p_W)},
            {"velocity", jsonVec3(r.v_W)},
        });
    }
    return QJsonObject{
        {"steps", static_cast<qint64>(world.stepIndex())},
        {"time", world.time()},
        {"status", "ok"},
        {"bodies", bodies},
        {"probes", probes},
        {"diagnostics", diagnosticsToJson(world.diagnostics(), &scene)},
    };
}

QJsonObject runToJson(const World& world, const std::vector<StepTrace>& traces, const QString& sceneFile)
{
    QJsonObject o = runHeaderToJson(world, sceneFile);
    const QJsonObject result = runResultToJson(world);
    for (auto it = result.begin(); it != result.end(); ++it) o.insert(it.key(), it.value());
    QJsonArray traceArray;
    for (const StepTrace& t : traces) {
        traceArray.append(traceToJson(t, world.scene()));
    }
    o.insert("trace", traceArray);
    return o;
}

QJsonObject blowUpToJson(const StepStatus& status, const QString& sceneFile)
{
    QJsonObject o{
        {"file", sceneFile},
        {"status", "blow-up"},
        {"step", static_cast<qint64>(status.step)},
        {"body", status.body >= 0 ? QJsonValue(QString::fromStdString(status.bodyName)) : QJsonValue::Null},
        {"quantity", QString::fromStdString(status.quantity)},
        {"message", QString::fromStdString(status.message)},
        {"initial_state", status.initialState},
    };
    if (!status.kind.empty()) {
        o.insert("kind", QString::fromStdString(status.kind));
    }
    if (status.index >= 0) {
        o.insert("index", status.index);
        o.insert("index_kind", QString::fromStdString(status.indexKind));
    }
    // A non-finite number: whether the inputs are to blame (stages/checks.h), and which.
    if (status.kind == "non-finite") {
        o.insert("inputs_at_edge", status.inputsAtEdge);
        if (!status.edgeInputs.empty()) o.insert("edge_inputs", QString::fromStdString(status.edgeInputs));
    }
    // An energy jump: T before and after the step and the bound, all finite numbers.
    if (status.kind == "energy-jump") {
        o.insert("kinetic_energy_before", status.kineticBefore);
        o.insert("kinetic_energy_after", status.kineticAfter);
        o.insert("kinetic_energy_bound", status.kineticBound);
    }
    return o;
}

JsonRunWriter::JsonRunWriter(QIODevice& out, const World& world, const QString& sceneFile)
    : out_(out)
    , world_(world)
    , file_(sceneFile)
{
}

void JsonRunWriter::begin()
{
    out_.write("{\n");
    out_.write(jsontext::indentedMembers(runHeaderToJson(world_, file_), 1));
    out_.write(",\n    \"trace\": [");
}

void JsonRunWriter::addTrace(const StepTrace& trace)
{
    // The element as an indented document lays it out, two levels in (8 spaces).
    QByteArray text = traces_ == 0 ? "\n        " : ",\n        ";
    jsontext::appendIndented(text, traceToJson(trace, world_.scene()), 2);
    out_.write(text);
    ++traces_;
}

void JsonRunWriter::closeTrace()
{
    out_.write(traces_ == 0 ? "]" : "\n    ]");
}

void JsonRunWriter::finish()
{
    closeTrace();
    out_.write(",\n");
    out_.write(jsontext::indentedMembers(runResultToJson(world_), 1));
    out_.write("\n}\n");
}

void JsonRunWriter::finishBlowUp(const StepStatus& status)
{
    closeTrace();
    QJsonObject o = blowUpToJson(status, file_);
    o.remove("file");   // in the header already
    out_.write(",\n");
    out_.write(jsontext::indentedMembers(o, 1));
    out_.write("\n}\n");
}

} // namespace rbw
