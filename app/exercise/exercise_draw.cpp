#include "app/exercise/exercise_draw.h"

#include "app/exercise/scene_path.h"
#include "app/exercise/value_grid.h"
#include "app/output/json_text.h"
#include "app/scene/scene_loader.h"
#include "app/scene/scene_format.h"
#include "physics/engine/quantity_catalogue.h"
#include "physics/engine/quantities.h"
#include "physics/engine/world.h"
#include "physics/workbook/checker/checker.h"
#include "physics/workbook/checker/follow_through.h"

#include <QJsonArray>

#include <algorithm>
#include <random>

namespace rbw {

namespace {

// Draws every rule's value into a copy of the base scene. Returns the document.
QJsonObject drawScene(const ExerciseSpec& spec, std::mt19937_64& engine)
{
    QJsonValue scene = spec.scene;
    for (const ExerciseVary& rule : spec.vary) {
        std::vector<double> values;
        for (int redraw = 0; redraw < 100; ++redraw) {
            values.clear();
            bool allZero = true;
            for (size_t c = 0; c < rule.lo.size(); ++c) {
                const std::uint64_t k = uniformIndex(engine, gridCount(rule.lo[c], rule.hi[c], rule.step));
                values.push_back(gridValue(rule.lo[c], k, rule.step, rule.decimals));
                allZero = allZero && values.back() == 0.0;
            }
            const bool avoided = !rule.vector && std::find(rule.avoid.begin(), rule.avoid.end(), values[0]) != rule.avoid.end();
            if ((!rule.nonzero || !allZero) && !avoided) break;
        }
        QJsonValue value;
        if (rule.vector) {
            QJsonArray a;
            for (double x : values) a.append(x);
            value = a;
        } else {
            value = values[0];
        }
        for (const QString& path : rule.paths) scene = withSceneValue(scene, *parseScenePath(path), value);
    }
    return scene.toObject();
}

QString nameOf(const SceneDef& scene, int body, int plane)
{
    if (body >= 0) return QString::fromStdString(scene.bodies[body].name);
    if (plane >= 0) return QString::fromStdString(scene.planes[plane].name);
    return QString();
}

// Runs the candidate: the answer step's trace, and whether every requirement holds.
// Returns an empty string when the candidate keeps the lesson's point, else why not.
QString runCandidate(const ExerciseSpec& spec, const SceneDef& scene, GeneratedExercise& g)
{
    World world(scene);
    std::vector<int> firstPoints(spec.require.size(), -1);
    bool haveAnswer = false;
    StepTrace trace;
    for (long k = 0; k < scene.steps; ++k) {
        trace.clear();
        std::vector<BodyState> before = haveAnswer ? std::vector<BodyState>() : world.states();
        const StepStatus status = world.step(&trace);
        if (!status.ok) return "the scene blows up in step " + QString::number(k) + ": " + QString::fromStdString(status.message);
        const bool separating = std::any_of(trace.contacts.begin(), trace.contacts.end(),
                                            [](const ContactHeader& c) { return c.separating; });
        const bool answerHere = spec.answerAtFirstContact      ? !trace.contacts.empty()
                                : spec.answerAtFirstSeparating ? separating
                                                               : k == spec.answerStep;
        if (answerHere && !haveAnswer) {
            haveAnswer = true;
            g.answerStep = k;
            g.startStates = std::move(before);
            g.answerTrace = trace;
        }
        for (size_t r = 0; r < spec.require.size(); ++r) {
            if (firstPoints[r] >= 0) continue;
            int points = 0;
            for (const ContactHeader& c : trace.contacts) {
                const QString a = nameOf(scene, c.bodyA, -1);
                const QString b = nameOf(scene, c.bodyB, c.plane);
                if ((a == spec.require[r].a && b == spec.require[r].b) || (a == spec.require[r].b && b == spec.require[r].a)) {
                    points += std::max(1, c.pointCount);
                }
            }
            if (points > 0) firstPoints[r] = points;
        }
    }
    if (!haveAnswer) {
        return spec.answerAtFirstContact ? "no contact in the scene's " + QString::number(scene.steps) + " steps"
               : spec.answerAtFirstSeparating
                   ? "no separating contact (v_rel.n > 0) in the scene's " + QString::number(scene.steps) + " steps"
                   : "the scene has no step " + QString::number(spec.answerStep);
    }
    for (size_t r = 0; r < spec.require.size(); ++r) {
        const ExerciseRequire& req = spec.require[r];
        if (firstPoints[r] < 0) {
            return req.jsonPath + ": no contact between " + req.a + " and " + req.b + " in the scene's " +
                   QString::number(scene.steps) + " steps";
        }
        if (req.points > 0 && firstPoints[r] != req.points) {
            return req.jsonPath + ": " + req.a + " and " + req.b + " first touch with " + QString::number(firstPoints[r]) +
                   (firstPoints[r] == 1 ? " contact point" : " contact points") + ", the lesson needs " +
                   QString::number(req.points);
        }
    }
    return QString();
}

// The answer table: the trace entries with the exercise's ids, in trace order. A
// separating contact (v_rel . n > 0) records no impulse; when the table asks for J, its
// row is the checker's own expectation for it (J = 0, checker.h: expectedValue), after
// the contact's last entry, so that the key says "no impulse" and a student who applies
// one anyway (no-separating-check) differs from it.
std::vector<TraceEntry> keyEntries(const ExerciseSpec& spec, const StepTrace& trace)
{
    // where each contact's entries end in the trace
    std::vector<size_t> lastEntry(trace.contacts.size(), trace.entries.size());
    for (size_t i = 0; i < trace.entries.size(); ++i) {
        const TraceEntry& e = trace.entries[i];
        if (e.info->indexKind == IndexKind::Contact && e.index >= 0 && e.index < static_cast<int>(lastEntry.size())) {
            lastEntry[e.index] = i;
        }
    }
    const bool asksImpulse = spec.quantities.contains(QLatin1String(q::impulse.id));
    std::vector<TraceEntry> key;
    for (size_t i = 0; i < trace.entries.size(); ++i) {
        const TraceEntry& e = trace.entries[i];
        if (spec.quantities.contains(QLatin1String(e.info->id))) key.push_back(e);
        if (!asksImpulse || e.info->indexKind != IndexKind::Contact || lastEntry[e.index] != i) continue;
        Answer a;
        a.quantity = q::impulse.id;
        a.contact = e.index;
        const bool recorded = checking::traceEntryOf(trace, checking::AnswerKey{q::impulse.id, -1, e.index, -1}) != nullptr;
        const std::vector<double> J = expectedValue(trace, a);
        if (!recorded && J.size() == 1) {
            key.push_back(TraceEntry{&q::impulse, trace.contacts[e.index].bodyA, e.index, J[0], std::source_location()});
        }
    }
    return key;
}

} // namespace

GeneratedExercise generateExercise(const ExerciseSpec& spec, std::uint64_t seed)
{
    GeneratedExercise g;
    g.seed = seed;
    QString lastReason;
    for (int attempt = 0; attempt < spec.attempts; ++attempt) {
        // Sub-seed a: the seed itself, then the seed xor a multiple of the golden-ratio
        // constant; all arithmetic modulo 2^64, the same everywhere.
        const std::uint64_t subSeed = seed ^ (static_cast<std::uint64_t>(attempt) * 0x9E3779B97F4A7C15ULL);
        std::mt19937_64 engine(subSeed);
        QJsonObject doc = drawScene(spec, engine);
        const QString name = sceneformat::key(sceneformat::Key::Name);
        doc.insert(name, spec.scene.value(name).toString(spec.lessonId) + ", seed " + QString::number(seed));
        if (!spec.description.isEmpty()) doc.insert(sceneformat::key(sceneformat::Key::Description), spec.description);
        // Laid out like the lessons' own files: the name first, then the description
        // (of the scene; a body's or plane's name is the same key), the rest sorted.
        const QByteArray bytes = jsontext::sceneFileText(doc, {name, sceneformat::key(sceneformat::Key::Description)});
        SceneLoadResult loaded = parseScene(bytes, spec.file);
        if (!loaded.ok()) {
            lastReason = "the scene does not load: " + loaded.errors.join("; ");
            continue;
        }
        GeneratedExercise candidate;
        candidate.seed = seed;
        lastReason = runCandidate(spec, *loaded.scene, candidate);
        if (!lastReason.isEmpty()) continue;
        candidate.sceneJson = bytes;
        candidate.scene = std::move(loaded.scene);
        candidate.attempt = attempt;
        candidate.key = keyEntries(spec, candidate.answerTrace);
        return candidate;
    }
    g.errors << spec.file + ": vary: no scene out of " + QString::number(spec.attempts) + " sub-seeds of seed " +
                    QString::number(seed) + " kept the lesson's point; the last: " + lastReason;
    return g;
}

} // namespace rbw
