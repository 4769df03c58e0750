#include "app/exercise/exercise_mistakes.h"

#include "app/exercise/exercise_draw.h"
#include "app/exercise/scene_path.h"
#include "physics/workbook/checker/mistakes.h"
#include "physics/workbook/checker/model_inputs.h"
#include "physics/workbook/checker/tolerance.h"
#include "physics/engine/integrators/explicit_euler.h"
#include "physics/engine/world.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <map>
#include <optional>
#include <string_view>

namespace rbw {

namespace {

// The checker's tolerance (checker.h: relTol) and the one the models are compared at.
constexpr double kRel = 1e-3;

struct Model {
    Mistake mistake;
    int variant;
    QString name;
};

std::vector<Model> catalogueModels()
{
    std::vector<Model> models;
    for (const MistakeInfo& m : mistakeCatalogue()) {
        for (int v = 0; v < m.variants; ++v) {
            QString name = QString::fromLatin1(m.id);
            if (m.variants > 1) name += " (variant " + QString::number(v) + ")";
            models.push_back(Model{m.mistake, v, name});
        }
    }
    return models;
}

QString partName(const SceneDef& s, int body, int plane)
{
    if (body >= 0) return QString::fromStdString(s.bodies[body].name);
    if (plane >= 0) return QString::fromStdString(s.planes[plane].name);
    return QStringLiteral("?");
}

// "angular_momentum (box)", "impulse (A–B)": a body's name or a contact's pair; a
// separating contact's (v_rel . n > 0, J = 0) is a row of its own, "impulse (edge–ground,
// separating)", since the impulse models that check separation give its right J = 0.
QString rowOf(const SceneDef& s, const StepTrace& t, const TraceEntry& e)
{
    const QString id = QString::fromLatin1(e.info->id);
    if (e.info->indexKind == IndexKind::Contact) {
        const ContactHeader& c = t.contacts[e.index];
        return id + " (" + partName(s, c.bodyA, -1) + QStringLiteral("–") + partName(s, c.bodyB, c.plane) +
               (c.separating ? QStringLiteral(", separating)") : QStringLiteral(")"));
    }
    QString who = e.body >= 0 ? partName(s, e.body, -1) : QString();
    if (e.index >= 0) who += (who.isEmpty() ? "#" : " #") + QString::number(e.index);
    return who.isEmpty() ? id : id + " (" + who + ")";
}

// The drawn values of a seed, "dt = 1, bodies[0].mass = 2".
QString drawnValues(const ExerciseSpec& spec, const GeneratedExercise& g)
{
    const QJsonValue doc = QJsonDocument::fromJson(g.sceneJson).object();
    QStringList parts;
    for (const ExerciseVary& rule : spec.vary) {
        const std::optional<QJsonValue> v = sceneValueAt(doc, *parseScenePath(rule.paths.front()));
        if (!v) continue;
        const QByteArray text = v->isArray() ? QJsonDocument(v->toArray()).toJson(QJsonDocument::Compact)
                                             : QJsonDocument(QJsonArray{*v}).toJson(QJsonDocument::Compact).mid(1).chopped(1);
        parts << rule.paths.front() + " = " + QString::fromUtf8(text);
    }
    return parts.join(", ");
}

// One draw: every model's value of every answer of the key (nothing: it does not compute it).
struct Draw {
    std::uint64_t seed = 0;
    QString values;
    QStringList rows;                                      // per key entry
    std::vector<checking::Values> right;                   // per key entry
    std::vector<std::vector<std::optional<checking::Values>>> model;   // [model][entry]
};

Draw measureDraw(const std::vector<Model>& models, const ExerciseSpec& spec, const GeneratedExercise& g)
{
    Draw d;
    d.seed = g.seed;
    d.values = drawnValues(spec, g);
    World before(*g.scene);
    while (before.stepIndex() < g.answerStep) before.step();
    const StepTrace& t = g.answerTrace;
    for (const TraceEntry& e : g.key) {
        d.rows << rowOf(*g.scene, t, e);
        d.right.push_back(traceValueComponents(e.value));
    }
    std::map<int, BodyStepInputs> bodies;
    std::map<int, ContactInputs> contacts;
    for (const TraceEntry& e : g.key) {
        if (e.info->indexKind == IndexKind::Contact) {
            if (!contacts.count(e.index)) contacts.emplace(e.index, checking::contactStepInputs(before, t, e.index));
        } else if (e.body >= 0 && std::string_view(before.integratorOf(e.body).name()) == ExplicitEuler::kName) {
            // the body models are hand calculations of the explicit Euler step (diagnosis.cpp)
            if (!bodies.count(e.body)) bodies.emplace(e.body, checking::bodyStepInputs(before, e.body));
        }
    }
    for (const Model& m : models) {
        std::map<int, HandEulerStep> steps;
        std::map<int, HandImpulse> impulses;
        for (const auto& [b, in] : bodies) steps.emplace(b, handEulerStep(in, m.mistake, m.variant));
        for (const auto& [k, in] : contacts) impulses.emplace(k, handImpulse(in, m.mistake));
        std::vector<std::optional<checking::Values>> values;
        for (const TraceEntry& e : g.key) {
            TraceValue v;
            bool ok = false;
            if (e.info->indexKind == IndexKind::Contact) {
                ok = impulses.at(e.index).value(e.info->id, v);
            } else if (steps.count(e.body)) {
                ok = steps.at(e.body).value(e.info->id, e.index, v);
            }
            values.push_back(ok ? std::optional<checking::Values>(traceValueComponents(v)) : std::nullopt);
        }
        d.model.push_back(std::move(values));
    }
    return d;
}

bool same(const checking::Values& a, const checking::Values& b)
{
    return a.size() == b.size() && checking::matches(a, b, kRel) && checking::matches(b, a, kRel);
}

bool shown(const Draw& d, size_t m, size_t e)
{
    return d.model[m][e].has_value() && !same(*d.model[m][e], d.right[e]);
}

// Models m and n give the same numbers in every answer of the draw that either computes.
bool indistinguishable(const Draw& d, size_t m, size_t n)
{
    for (size_t e = 0; e < d.right.size(); ++e) {
        const std::optional<checking::Values>& a = d.model[m][e];
        const std::optional<checking::Values>& b = d.model[n][e];
        if (!a && !b) continue;
        if (!same(a.value_or(d.right[e]), b.value_or(d.right[e]))) return false;
    }
    return true;
}

bool showsAnything(const Draw& d, size_t m)
{
    for (size_t e = 0; e < d.right.size(); ++e) {
        if (shown(d, m, e)) return true;
    }
    return false;
}

QString seedText(const Draw& d)
{
    return "seed " + QString::number(d.seed) + " (" + d.values + ")";
}

} // namespace

QStringList ExerciseMistakeReport::failures() const
{
    QStringList out = errors;
    for (const ModelVisibility& m : models) {
        for (const QString& h : m.hiddenAt) out << lessonId + ": " + m.model + ": " + h;
        for (const QString& c : m.coincidences) out << lessonId + ": " + m.model + ": " + c;
    }
    return out;
}

QString ExerciseMistakeReport::markdown() const
{
    QString s = "### " + lessonId + "\n\n";
    QStringList cannot;
    QString table = "| mistake | shows in | the same numbers as |\n| --- | --- | --- |\n";
    for (const ModelVisibility& m : models) {
        if (m.shownIn.isEmpty()) {
            cannot << '`' + m.model + '`';
            continue;
        }
        QStringList same;
        for (const QString& o : m.sameAs) same << '`' + o + '`';
        table += "| `" + m.model + "` | " + m.shownIn.join(", ") + " | " + same.join(", ") + " |\n";
    }
    s += table;
    s += "\nCannot show: " + (cannot.isEmpty() ? QStringLiteral("nothing") : cannot.join(", ")) + ".\n";
    return s;
}

ExerciseMistakeReport measureExerciseMistakes(const ExerciseSpec& spec, const std::vector<std::uint64_t>& seeds)
{
    ExerciseMistakeReport report;
    report.lessonId = spec.lessonId;
    report.seeds = seeds;
    const std::vector<Model> models = catalogueModels();
    std::vector<Draw> draws;
    for (std::uint64_t seed : seeds) {
        const GeneratedExercise g = generateExercise(spec, seed);
        if (!g.ok()) {
            report.errors << g.errors;
            continue;
        }
        draws.push_back(measureDraw(models, spec, g));
    }
    for (size_t m = 0; m < models.size(); ++m) {
        ModelVisibility v;
        v.model = models[m].name;
        // Per row (an answer's quantity and subject): in how many draws shown and hidden.
        QStringList rows;
        std::map<QString, std::pair<int, int>> counts;
        std::map<QString, QString> firstHidden;
        for (const Draw& d : draws) {
            for (size_t e = 0; e < d.right.size(); ++e) {
                if (!d.model[m][e]) continue;
                if (!rows.contains(d.rows[e])) rows << d.rows[e];
                auto& [nShown, nHidden] = counts[d.rows[e]];
                if (shown(d, m, e)) {
                    ++nShown;
                } else {
                    ++nHidden;
                    if (!firstHidden.count(d.rows[e])) {
                        firstHidden[d.rows[e]] = seedText(d) + ": " + d.rows[e] + " is the right number under it";
                    }
                }
            }
        }
        for (const QString& r : rows) {
            const auto [nShown, nHidden] = counts[r];
            if (nShown > 0 && nHidden == 0) v.shownIn << r;
            if (nShown > 0 && nHidden > 0) v.hiddenAt << firstHidden[r];
        }
        // Told apart from every other model where both show something.
        for (size_t n = 0; n < models.size(); ++n) {
            if (n == m) continue;
            int nSame = 0, nApart = 0;
            QString firstSame;
            for (const Draw& d : draws) {
                if (!showsAnything(d, m) || !showsAnything(d, n)) continue;
                if (indistinguishable(d, m, n)) {
                    ++nSame;
                    if (firstSame.isEmpty()) firstSame = seedText(d) + ": the same numbers as " + models[n].name;
                } else {
                    ++nApart;
                }
            }
            if (nSame > 0 && nApart == 0) v.sameAs << models[n].name;
            if (nSame > 0 && nApart > 0) v.coincidences << firstSame;
        }
        report.models.push_back(std::move(v));
    }
    return report;
}

} // namespace rbw
