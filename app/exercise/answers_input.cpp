#include "app/exercise/answers_input.h"
#include "app/scene/scene_format.h"

#include "app/scene/strict_json_scan.h"
#include "physics/engine/quantity_catalogue.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>

#include <algorithm>
#include <cmath>

namespace rbw {

bool readInputFile(const QString& path, QByteArray* out, QString* error, qint64 limit)
{
    if (QFileInfo(path).isDir()) {
        *error = QStringLiteral("%1: cannot read: it is a directory").arg(path);
        return false;
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("%1: cannot open: %2").arg(path, file.errorString());
        return false;
    }
    // One byte more than the limit tells a file at the limit from a larger one.
    QByteArray bytes;
    while (bytes.size() <= limit) {
        const QByteArray chunk = file.read(limit + 1 - bytes.size());
        if (chunk.isEmpty()) break;
        bytes += chunk;
    }
    if (file.error() != QFileDevice::NoError) {
        *error = QStringLiteral("%1: cannot read: %2").arg(path, file.errorString());
        return false;
    }
    if (bytes.size() > limit) {
        *error = QStringLiteral("%1: larger than %2 bytes (%3 MiB), the most read from an input file")
                     .arg(path)
                     .arg(limit)
                     .arg(static_cast<double>(limit) / (1 << 20), 0, 'g', 3);
        return false;
    }
    *out = bytes;
    return true;
}

QString shownText(const QString& s, int max)
{
    QString out;
    int shown = 0;
    for (const QChar c : s) {
        if (shown == max) {
            out += QChar(0x2026);
            break;
        }
        const ushort u = c.unicode();
        if (u == '\n') out += QStringLiteral("\\n");
        else if (u == '\t') out += QStringLiteral("\\t");
        else if (u == '\r') out += QStringLiteral("\\r");
        else if (u < 0x20 || u == 0x7f || (u >= 0x80 && u < 0xa0)) out += QStringLiteral("\\x%1").arg(u, 2, 16, QLatin1Char('0'));
        else out += c;
        ++shown;
    }
    return out;
}

AnswersInput readAnswersInput(const QByteArray& json, const QString& label, const SceneDef& scene,
                              std::optional<long> stepOption)
{
    AnswersInput in;
    if (json.trimmed().isEmpty()) {
        in.errors << QStringLiteral("%1: the file is empty (an answers file is a JSON object with \"answers\")").arg(label);
        return in;
    }
    // A key given twice: QJsonDocument keeps the last silently, so the strict scan
    // looks at the raw text that QJsonDocument read without error.
    QJsonParseError pe;
    QJsonDocument::fromJson(json, &pe);
    if (pe.error == QJsonParseError::NoError) {
        if (const auto finding = scenefile::scanJson(json, json.size(), false)) {
            in.errors << QStringLiteral("%1: %2: %3").arg(label, shownText(finding->path, 200), shownText(finding->reason, 300));
            return in;
        }
    }
    in.file = parseAnswers(json, label, scene);
    if (!in.file.ok()) {
        in.errors = in.file.errors;
        return in;
    }
    if (in.file.answers.empty()) {
        in.errors << QStringLiteral("%1: answers: there are no answers (the list is empty; give at least one)").arg(label);
        return in;
    }
    in.step = stepOption.value_or(in.file.step.value_or(0));
    const QString where = stepOption ? QStringLiteral("--step") : QStringLiteral("step");
    if (in.step >= scene.steps) {
        QString reason = scene.steps == 0
                             ? QStringLiteral("the scene has no steps (\"%1\": 0)").arg(sceneformat::key(sceneformat::Key::Steps))
                             : QStringLiteral("step %1 is beyond the scene's %2 steps (the last is step %3)")
                                   .arg(in.step)
                                   .arg(scene.steps)
                                   .arg(scene.steps - 1);
        if (scene.steps > 0 && in.step == scene.steps) {
            reason += QStringLiteral("; steps count from 0: did you mean step %1?").arg(scene.steps - 1);
        }
        in.errors << QStringLiteral("%1: %2: %3").arg(label, where, reason);
    }
    return in;
}

namespace {

// Which probes belong to a body: "0, 2", or empty.
QStringList probesOf(const SceneDef& scene, int body)
{
    QStringList out;
    for (size_t i = 0; i < scene.probes.size(); ++i) {
        if (scene.probes[i].body == body) out << QString::number(i);
    }
    return out;
}

QString probeHint(const SceneDef& scene, const Answer& a)
{
    const QuantityInfo* info = findQuantity(a.quantity);
    if (info == nullptr || info->indexKind != IndexKind::Probe || a.body < 0) return {};
    const QString body = shownText(QString::fromStdString(scene.bodies[a.body].name));
    const QStringList mine = probesOf(scene, a.body);
    if (mine.isEmpty()) return QStringLiteral("%1 has no probes").arg(body);
    if (a.index < 0) return QStringLiteral("it needs \"index\": the probes of %1 are %2").arg(body, mine.join(", "));
    return QStringLiteral("probe indices count over the whole scene, not per body: the probes of %1 are %2")
        .arg(body, mine.join(", "));
}

} // namespace

QStringList answersProblems(const AnswersInput& in, const StepTrace& trace, const SceneDef& scene, const QString& label)
{
    QStringList out;
    for (size_t i = 0; i < in.file.answers.size(); ++i) {
        const Answer& a = in.file.answers[i];
        const std::string problem = answerProblem(trace, a);
        if (problem.empty()) continue;
        QString message = QStringLiteral("%1: %2: %3").arg(label, in.file.paths[i], shownText(QString::fromStdString(problem), 300));
        const QString hint = probeHint(scene, a);
        if (!hint.isEmpty()) message += QStringLiteral(" (%1)").arg(hint);
        out << message;
    }
    return out;
}

bool StepStates::prepare(std::vector<long> steps, QString* error)
{
    std::sort(steps.begin(), steps.end());
    steps.erase(std::unique(steps.begin(), steps.end()), steps.end());
    steps.erase(std::remove_if(steps.begin(), steps.end(), [this](long k) { return has(k); }), steps.end());
    if (steps.empty()) return true;
    ++simulations_;
    World world(scene_);
    size_t next = 0;
    for (long k = 0; k <= steps.back(); ++k) {
        if (steps[next] == k) {
            State s;
            s.before = world.snapshot();
            const StepStatus& st = world.step(&s.trace);
            if (!st.ok) {
                if (error) *error = QString::fromStdString(st.message);
                return false;
            }
            states_.emplace(k, std::move(s));
            ++next;
        } else {
            const StepStatus& st = world.step();
            if (!st.ok) {
                if (error) *error = QString::fromStdString(st.message);
                return false;
            }
        }
    }
    return true;
}

std::unique_ptr<World> StepStates::worldBefore(long step) const
{
    auto world = std::make_unique<World>(scene_);
    world->restore(states_.at(step).before);
    return world;
}

QString slipHint(const Answer& a, const AnswerResult& r, double tolerance)
{
    if (r.verdict != Verdict::Wrong || a.value.size() != 4 || r.expected.size() != 4) return {};
    // [x, y, z, w] read as [w, x, y, z]: the student's last number is w.
    const std::vector<double> wxyz = {a.value[3], a.value[0], a.value[1], a.value[2]};
    double scale = 0.0;
    double diff = 0.0;
    for (size_t i = 0; i < 4; ++i) {
        scale = std::max(scale, std::abs(r.expected[i]));
        diff = std::max(diff, std::abs(wxyz[i] - r.expected[i]));
    }
    if (diff > tolerance * scale) return {};
    return QStringLiteral("quaternions are [w, x, y, z]: your numbers are right in the order [x, y, z, w]");
}

QString stepSlipHint(const std::vector<Answer>& answers, const std::vector<AnswerResult>& results, long step,
                     const StepStates& states, double tolerance)
{
    const auto allRight = [](const std::vector<AnswerResult>& rs) {
        return std::all_of(rs.begin(), rs.end(), [](const AnswerResult& r) { return countsAsCorrect(r.verdict); });
    };
    const long earlier = step - 1;
    if (step <= 0 || answers.empty() || allRight(results) || !states.has(earlier)) return {};
    const StepTrace& trace = states.trace(earlier);
    for (const Answer& a : answers) {
        if (!answerProblem(trace, a).empty()) return {};
    }
    if (!allRight(checkAnswers(*states.worldBefore(earlier), trace, answers, tolerance))) return {};
    return QStringLiteral("steps count from 0: did you mean step %1? (every answer is right for step %1)").arg(earlier);
}

} // namespace rbw
