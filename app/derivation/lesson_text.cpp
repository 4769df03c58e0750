#include "app/derivation/lesson_text.h"

#include "app/output/value_format.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace rbw {

namespace {

// A number as the lesson texts write it: 6 significant digits, a real minus sign.
QString textNumber(double x)
{
    QString s = formatNumber(x, 6);
    s.replace(QLatin1Char('-'), QChar(0x2212));
    return s;
}

QString textTuple(const std::vector<double>& values, QChar open, QChar close)
{
    QStringList parts;
    for (const double x : values) parts << textNumber(x);
    return open + parts.join(QStringLiteral(", ")) + close;
}

std::vector<double> components(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

// The value a key names, as numbers; empty and *problem set if it names nothing.
struct SceneValue {
    std::vector<double> numbers;
    bool quaternion = false;
};

SceneValue sceneValue(const SceneDef& scene, const QString& key, const QString& body, int index, QString* problem)
{
    if (key == QLatin1String("scene:h")) return {{scene.dt}};
    if (key == QLatin1String("scene:g")) return {components(scene.g_W)};
    if (key == QLatin1String("scene:steps")) return {{static_cast<double>(scene.steps)}};
    if (key == QLatin1String("scene:restitution")) return {{scene.restitution}};
    if (key == QLatin1String("scene:friction")) return {{scene.friction}};
    if (key == QLatin1String("scene:force") || key == QLatin1String("scene:point")) {
        if (index < 0 || index >= static_cast<int>(scene.forces.size())) {
            *problem = QStringLiteral("no force #%1 in this scene").arg(index);
            return {};
        }
        const ForceDef& f = scene.forces[index];
        return {components(key == QLatin1String("scene:force") ? f.f_W : f.p_W)};
    }
    if (key == QLatin1String("scene:torque")) {
        if (index < 0 || index >= static_cast<int>(scene.torques.size())) {
            *problem = QStringLiteral("no torque #%1 in this scene").arg(index);
            return {};
        }
        return {components(scene.torques[index].q_W)};
    }
    static const QStringList bodyKeys{"scene:mass", "scene:size", "scene:position", "scene:velocity", "scene:omega", "scene:orientation", "scene:degrees"};
    if (!bodyKeys.contains(key)) {
        *problem = QStringLiteral("unknown key '%1'").arg(key.mid(6));
        return {};
    }
    const int b = scene.bodyIndex(body.toStdString());
    if (body.isEmpty() || b < 0) {
        *problem = body.isEmpty() ? QStringLiteral("which body? add @name") : QStringLiteral("no body named '%1'").arg(body);
        return {};
    }
    const BodyDef& d = scene.bodies[b];
    if (key == QLatin1String("scene:mass")) return {{d.mass}};
    if (key == QLatin1String("scene:size")) return {components(d.size)};
    if (key == QLatin1String("scene:position")) return {components(d.x0_W)};
    if (key == QLatin1String("scene:velocity")) return {components(d.v0_W)};
    if (key == QLatin1String("scene:omega")) return {components(d.omega0_W)};
    if (key == QLatin1String("scene:orientation")) return {{d.q0_WB.w(), d.q0_WB.x(), d.q0_WB.y(), d.q0_WB.z()}, true};
    // degrees: the angle of the turn the scene file gives, 2 acos|w|.
    return {{2.0 * std::acos(std::min(1.0, std::abs(d.q0_WB.w()))) * 180.0 / std::numbers::pi}};
}

// The numbers of a published text ("(1, −0.5, 2)", "0.707107"), each with the
// tolerance its digits stand for: half a unit of the last written decimal, or exact for
// an integer.
struct Published {
    std::vector<double> numbers;
    std::vector<double> tolerance;
};

Published parsePublished(QString text)
{
    text.replace(QChar(0x2212), QLatin1Char('-'));
    static const QRegularExpression number(QStringLiteral(R"(-?\d+(?:\.(\d+))?)"));
    Published p;
    QRegularExpressionMatchIterator it = number.globalMatch(text);
    while (it.hasNext()) {
        const QRegularExpressionMatch m = it.next();
        const double x = m.captured(0).toDouble();
        const int decimals = static_cast<int>(m.captured(1).size());
        p.numbers.push_back(x);
        p.tolerance.push_back(decimals > 0 ? 0.5 * std::pow(10.0, -decimals) * (1.0 + 1e-9)
                                           : 1e-9 * std::max(1.0, std::abs(x)));
    }
    return p;
}

} // namespace

FilledLessonText fillLessonText(const QString& markdown, const SceneDef& scene, bool published)
{
    // {{scene:KEY[@body][#i][.x|.y|.z] = PUBLISHED}}
    static const QRegularExpression placeholder(
        QStringLiteral(R"(\{\{\s*scene:([a-z_]+)(?:@([A-Za-z0-9_.\-]+?))?(?:#(\d+))?(?:\.([xyz]))?\s*=\s*([^}]*?)\s*\}\})"));
    static const QRegularExpression anyPlaceholder(QStringLiteral(R"(\{\{[^}]*\}\})"));
    FilledLessonText out;
    const QStringList lines = markdown.split(QLatin1Char('\n'));
    QStringList filled;
    for (int n = 0; n < lines.size(); ++n) {
        const QString& line = lines[n];
        QString result;
        int from = 0;
        QRegularExpressionMatchIterator it = anyPlaceholder.globalMatch(line);
        while (it.hasNext()) {
            const QRegularExpressionMatch any = it.next();
            result += line.mid(from, any.capturedStart() - from);
            from = any.capturedEnd();
            const QString whole = any.captured(0);
            const QRegularExpressionMatch m = placeholder.match(whole);
            const QString where = QStringLiteral("line %1: %2: ").arg(n + 1).arg(whole);
            if (!m.hasMatch() || m.capturedLength(0) != whole.size()) {
                out.errors << where + QStringLiteral("not {{scene:KEY[@body][#i][.x] = published value}}");
                result += whole;
                continue;
            }
            ++out.placeholders;
            // The lesson text's own placeholder names ("scene:mass"), not the scene file's keys.
            const QString key = QStringLiteral("scene:") + m.captured(1);
            const QString shownPublished = m.captured(5);
            QString problem;
            const SceneValue value = sceneValue(scene, key, m.captured(2), m.captured(3).isEmpty() ? -1 : m.captured(3).toInt(), &problem);
            std::vector<double> numbers = value.numbers;
            if (problem.isEmpty() && !m.captured(4).isEmpty()) {
                if (numbers.size() != 3) {
                    problem = QStringLiteral(".%1 needs a vector").arg(m.captured(4));
                } else {
                    numbers = {numbers[static_cast<std::size_t>(m.captured(4)[0].unicode() - 'x')]};
                }
            }
            const Published p = parsePublished(shownPublished);
            if (problem.isEmpty() && p.numbers.size() != numbers.size()) {
                problem = QStringLiteral("the published value has %1 numbers, the scene's %2")
                              .arg(p.numbers.size()).arg(numbers.size());
            }
            if (!problem.isEmpty()) {
                out.errors << where + problem;
                result += shownPublished;
                continue;
            }
            bool same = true;
            for (std::size_t i = 0; i < numbers.size(); ++i) {
                same = same && std::abs(numbers[i] - p.numbers[i]) <= p.tolerance[i];
            }
            if (same) {
                result += shownPublished;
                continue;
            }
            const QString mine = numbers.size() == 1 ? textNumber(numbers[0])
                                 : value.quaternion  ? textTuple(numbers, QLatin1Char('['), QLatin1Char(']'))
                                                     : textTuple(numbers, QLatin1Char('('), QLatin1Char(')'));
            //: a setup number of a lesson text that differs from the published one
            result += QCoreApplication::translate("LessonText", "**%1** (published: %2)").arg(mine, shownPublished);
            out.changed << QStringLiteral("%1: %2 (published: %3)").arg(whole.section(QLatin1Char('='), 0, 0).mid(8).trimmed(), mine, shownPublished);
        }
        result += line.mid(from);
        filled << result;
    }
    out.ownNumbers = !published || !out.changed.isEmpty();
    if (out.ownNumbers) {
        // After the title (the first "# " line), or at the top.
        int at = 0;
        while (at < filled.size() && !filled[at].startsWith(QLatin1String("# "))) ++at;
        at = at < filled.size() ? at + 1 : 0;
        const QString note = QCoreApplication::translate(
            "LessonText",
            "> **Your numbers.** This scene is not the lesson's published one. Its setup numbers are shown "
            "in **bold**, the published ones in brackets beside them. The values worked out below are "
            "**for the published numbers**: work out yours the same way and compare them with the "
            "quantities table.");
        filled.insert(at, QString());
        filled.insert(at + 1, note);
    }
    out.markdown = filled.join(QLatin1Char('\n'));
    return out;
}

} // namespace rbw
