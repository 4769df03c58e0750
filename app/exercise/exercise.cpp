#include "app/exercise/exercise.h"

#include "app/exercise/answers_file.h"
#include "app/core/lesson_catalogue.h"
#include "app/scene/scene_loader.h"
#include "app/output/value_format.h"
#include "physics/engine/quantity_catalogue.h"
#include "physics/engine/world.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QRegularExpression>

#include <cmath>
#include <limits>
#include <variant>

namespace rbw {

namespace {

// ---- JSON paths into the scene: "bodies[0].mass", "forces[1].force", "dt" ----

struct PathToken {
    QString key;     // an object key, or empty for an array index
    int index = -1;
};

std::optional<std::vector<PathToken>> parsePath(const QString& path)
{
    static const QRegularExpression token(QStringLiteral(R"(^([A-Za-z_][A-Za-z0-9_]*)((?:\[\d+\])*)$)"));
    static const QRegularExpression index(QStringLiteral(R"(\[(\d+)\])"));
    std::vector<PathToken> tokens;
    if (path.isEmpty()) return std::nullopt;
    for (const QString& part : path.split('.')) {
        const QRegularExpressionMatch m = token.match(part);
        if (!m.hasMatch()) return std::nullopt;
        tokens.push_back(PathToken{m.captured(1), -1});
        auto it = index.globalMatch(m.captured(2));
        while (it.hasNext()) tokens.push_back(PathToken{QString(), it.next().captured(1).toInt()});
    }
    return tokens;
}

std::optional<QJsonValue> getAt(const QJsonValue& v, const std::vector<PathToken>& t, size_t i = 0)
{
    if (i == t.size()) return v;
    if (!t[i].key.isEmpty()) {
        if (!v.isObject() || !v.toObject().contains(t[i].key)) return std::nullopt;
        return getAt(v.toObject().value(t[i].key), t, i + 1);
    }
    if (!v.isArray() || t[i].index >= v.toArray().size()) return std::nullopt;
    return getAt(v.toArray().at(t[i].index), t, i + 1);
}

QJsonValue setAt(const QJsonValue& v, const std::vector<PathToken>& t, const QJsonValue& value, size_t i = 0)
{
    if (i == t.size()) return value;
    if (!t[i].key.isEmpty()) {
        QJsonObject o = v.toObject();
        o.insert(t[i].key, setAt(o.value(t[i].key), t, value, i + 1));
        return o;
    }
    QJsonArray a = v.toArray();
    a.replace(t[i].index, setAt(a.at(t[i].index), t, value, i + 1));
    return a;
}

// ---- the portable mapping from the engine's integers to the values ----

// Decimals of a rounding step (0.5 -> 1, 0.25 -> 2, 2 -> 0), at most 6; -1 if the step
// has more.
int decimalsOf(double step)
{
    for (int d = 0; d <= 6; ++d) {
        const double scaled = step * std::pow(10.0, d);
        if (std::abs(scaled - std::round(scaled)) <= 1e-9 * std::max(1.0, scaled)) return d;
    }
    return -1;
}

// lo + k step, rounded to `decimals`: an integer divided by a power of ten, which IEEE
// division rounds correctly, so the double is the nearest one to the decimal and JSON
// writes it as the short decimal ("0.3", never "0.30000000000000004").
double gridValue(double lo, std::uint64_t k, double step, int decimals)
{
    const double scale = std::pow(10.0, decimals);
    const double units = std::round(lo * scale) + static_cast<double>(k) * std::round(step * scale);
    return units / scale;
}

std::uint64_t gridCount(double lo, double hi, double step)
{
    return static_cast<std::uint64_t>(std::floor((hi - lo) / step + 1e-9));
}

QString fmt(const ExerciseSpec& spec, const QString& path, const QString& reason)
{
    return spec.file + ": " + path + ": " + reason;
}

QString errorIn(const QString& file, const QString& path, const QString& reason)
{
    return file + ": " + path + ": " + reason;
}

std::optional<QString> resolveLessonFolder(const QString& lesson, QString* error)
{
    const QFileInfo asPath(lesson);
    if (asPath.isDir()) return QDir::cleanPath(asPath.filePath());
    const QString dir = lessonsDirectory();
    const QFileInfo asId(QDir(dir).filePath(lesson));
    if (!lesson.isEmpty() && !lesson.contains('/') && asId.isDir()) return QDir::cleanPath(asId.filePath());
    QStringList known;
    for (const QString& id : QDir(dir).entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name)) {
        if (QFile::exists(QDir(dir).filePath(id + "/exercise.json"))) known << id;
    }
    *error = lesson + ": LESSON: no lesson folder of that name (lessons with exercises: " + known.join(", ") + ")";
    return std::nullopt;
}

} // namespace

std::uint64_t uniformIndex(std::mt19937_64& engine, std::uint64_t n)
{
    if (n == std::numeric_limits<std::uint64_t>::max()) return engine();
    const std::uint64_t range = n + 1;
    // 2^64 mod range: the first `threshold` raw values are rejected, so the rest are a
    // whole number of copies of [0, range) and x % range is exactly uniform.
    const std::uint64_t threshold = (0 - range) % range;
    for (;;) {
        const std::uint64_t x = engine();
        if (x >= threshold) return x % range;
    }
}

ExerciseLoadResult loadExercise(const QString& lesson)
{
    ExerciseLoadResult result;
    QString folderError;
    const std::optional<QString> folder = resolveLessonFolder(lesson, &folderError);
    if (!folder) {
        result.errors << folderError;
        return result;
    }
    ExerciseSpec spec;
    spec.file = QDir(*folder).filePath(QStringLiteral("exercise.json"));
    spec.lessonId = QFileInfo(*folder).fileName();
    QFile file(spec.file);
    if (!file.open(QIODevice::ReadOnly)) {
        result.errors << fmt(spec, "(file)", "cannot open: " + file.errorString() + " (this lesson has no exercise)");
        return result;
    }
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(file.readAll(), &parseError);
    if (parseError.error != QJsonParseError::NoError || !doc.isObject()) {
        result.errors << fmt(spec, "(file)",
                             parseError.error != QJsonParseError::NoError
                                 ? "not valid JSON: " + parseError.errorString() + " at offset " +
                                       QString::number(parseError.offset)
                                 : QStringLiteral("must be a JSON object"));
        return result;
    }
    const QJsonObject o = doc.object();
    QStringList& errors = result.errors;
    static const QStringList knownKeys{"scene",      "vary", "require",  "step", "quantities",
                                       "description", "task", "attempts", "keep"};
    for (const QString& key : o.keys()) {
        if (!knownKeys.contains(key)) errors << fmt(spec, key, "unknown key; known: " + knownKeys.join(", "));
    }

    // The base scene: "scene" (default scene.json), relative to the lesson folder.
    const QJsonValue sceneName = o.value("scene");
    if (!sceneName.isUndefined() && !sceneName.isString()) errors << fmt(spec, "scene", "must be a file name");
    spec.scenePath = QDir(*folder).filePath(sceneName.toString(QStringLiteral("scene.json")));
    QFile sceneFile(spec.scenePath);
    if (!sceneFile.open(QIODevice::ReadOnly)) {
        errors << fmt(spec, "scene", "cannot open " + spec.scenePath + ": " + sceneFile.errorString());
        return result;
    }
    const QByteArray sceneBytes = sceneFile.readAll();
    const SceneLoadResult base = parseScene(sceneBytes, spec.scenePath);
    if (!base.ok()) {
        errors << base.errors;
        return result;
    }
    spec.scene = QJsonDocument::fromJson(sceneBytes).object();

    // vary: [{ "path" | "paths", "range", "step", "nonzero" }]
    const QJsonValue varyValue = o.value("vary");
    if (!varyValue.isArray() || varyValue.toArray().isEmpty()) {
        errors << fmt(spec, "vary", "must be a non-empty list of { \"path\", \"range\", \"step\" }");
    }
    const QJsonArray varyList = varyValue.toArray();
    for (qsizetype i = 0; i < varyList.size(); ++i) {
        const QString at = QStringLiteral("vary[%1]").arg(i);
        if (!varyList[i].isObject()) {
            errors << fmt(spec, at, "must be an object { \"path\", \"range\", \"step\" }");
            continue;
        }
        const QJsonObject v = varyList[i].toObject();
        for (const QString& key : v.keys()) {
            if (!QStringList{"path", "paths", "range", "step", "nonzero"}.contains(key)) {
                errors << fmt(spec, at + "." + key, "unknown key; known: path, paths, range, step, nonzero");
            }
        }
        ExerciseVary rule;
        rule.jsonPath = at;
        if (v.contains("path") == v.contains("paths")) {
            errors << fmt(spec, at, "needs exactly one of \"path\" (a scene path) or \"paths\" (a list)");
            continue;
        }
        if (v.value("path").isString()) rule.paths << v.value("path").toString();
        for (const QJsonValue& p : v.value("paths").toArray()) rule.paths << p.toString();
        if (rule.paths.isEmpty()) {
            errors << fmt(spec, at + (v.contains("path") ? ".path" : ".paths"), "must name a scene path such as \"bodies[0].mass\"");
            continue;
        }
        // range: [lo, hi] or a list of [lo, hi], one per component
        const QJsonArray range = v.value("range").toArray();
        const bool isVector = !range.isEmpty() && range[0].isArray();
        rule.vector = isVector;
        auto readPair = [&](const QJsonValue& pv, const QString& where) {
            const QJsonArray p = pv.toArray();
            if (!pv.isArray() || p.size() != 2 || !p[0].isDouble() || !p[1].isDouble() || p[0].toDouble() > p[1].toDouble()) {
                errors << fmt(spec, where, "must be [lo, hi], two numbers with lo <= hi");
                return;
            }
            rule.lo.push_back(p[0].toDouble());
            rule.hi.push_back(p[1].toDouble());
        };
        if (!v.value("range").isArray() || range.isEmpty()) {
            errors << fmt(spec, at + ".range", "must be [lo, hi] or a list of [lo, hi], one per component");
            continue;
        }
        if (isVector) {
            for (qsizetype c = 0; c < range.size(); ++c) readPair(range[c], at + QStringLiteral(".range[%1]").arg(c));
        } else {
            readPair(range, at + ".range");
        }
        const QJsonValue stepValue = v.value("step");
        rule.step = stepValue.toDouble(-1.0);
        rule.decimals = decimalsOf(rule.step);
        if (!stepValue.isDouble() || !(rule.step > 0.0) || rule.decimals < 0) {
            errors << fmt(spec, at + ".step", "must be a number > 0 with at most 6 decimals, e.g. 0.5 or 0.01");
            continue;
        }
        for (size_t c = 0; c < rule.lo.size(); ++c) {
            if (gridCount(rule.lo[c], rule.hi[c], rule.step) > 1000000) {
                errors << fmt(spec, at + ".step", "too small for the range: more than a million values");
            }
        }
        if (v.contains("nonzero") && !v.value("nonzero").isBool()) errors << fmt(spec, at + ".nonzero", "must be true or false");
        rule.nonzero = v.value("nonzero").toBool(false);
        // Every path must exist in the scene with the range's shape.
        for (const QString& path : rule.paths) {
            const auto tokens = parsePath(path);
            const QString where = at + (v.contains("path") ? QStringLiteral(".path") : QStringLiteral(".paths"));
            if (!tokens) {
                errors << fmt(spec, where, "\"" + path + "\" is not a scene path such as \"bodies[0].mass\"");
                continue;
            }
            const std::optional<QJsonValue> current = getAt(spec.scene, *tokens);
            if (!current) {
                errors << fmt(spec, where, "\"" + path + "\" is not in " + QFileInfo(spec.scenePath).fileName());
            } else if (isVector && (!current->isArray() || current->toArray().size() != static_cast<qsizetype>(rule.lo.size()))) {
                errors << fmt(spec, where, "\"" + path + "\" is not an array of " + QString::number(rule.lo.size()) +
                                               " numbers, as the range has " + QString::number(rule.lo.size()) + " ranges");
            } else if (!isVector && !current->isDouble()) {
                errors << fmt(spec, where, "\"" + path + "\" is not a number; a vector needs a list of ranges");
            }
        }
        spec.vary.push_back(rule);
    }

    // require: [{ "contact": [a, b], "points": n }]
    const QJsonValue requireValue = o.value("require");
    if (!requireValue.isUndefined() && !requireValue.isArray()) errors << fmt(spec, "require", "must be a list");
    const QJsonArray requireList = requireValue.toArray();
    QStringList names;
    for (const QJsonValue& b : spec.scene.value("bodies").toArray()) names << b.toObject().value("name").toString();
    for (const QJsonValue& p : spec.scene.value("planes").toArray()) names << p.toObject().value("name").toString();
    for (qsizetype i = 0; i < requireList.size(); ++i) {
        const QString at = QStringLiteral("require[%1]").arg(i);
        const QJsonObject r = requireList[i].toObject();
        const QJsonArray pair = r.value("contact").toArray();
        if (pair.size() != 2 || !pair[0].isString() || !pair[1].isString()) {
            errors << fmt(spec, at + ".contact", "must be two names [\"A\", \"B\"] (bodies or planes)");
            continue;
        }
        ExerciseRequire req{at, pair[0].toString(), pair[1].toString(), -1};
        for (const QString& n : {req.a, req.b}) {
            if (!names.contains(n)) errors << fmt(spec, at + ".contact", "no body or plane \"" + n + "\" in the scene");
        }
        if (r.contains("points")) {
            if (!r.value("points").isDouble() || r.value("points").toInt(-1) < 1) {
                errors << fmt(spec, at + ".points", "must be a whole number >= 1");
            }
            req.points = r.value("points").toInt(-1);
        }
        for (const QString& key : r.keys()) {
            if (key != "contact" && key != "points") errors << fmt(spec, at + "." + key, "unknown key; known: contact, points");
        }
        spec.require.push_back(req);
    }

    // step: a whole number k, or "first-contact"
    const QJsonValue stepValue = o.value("step");
    if (stepValue.isString() && stepValue.toString() == "first-contact") {
        spec.answerAtFirstContact = true;
    } else if (stepValue.isUndefined()) {
        spec.answerStep = 0;
    } else if (stepValue.isDouble() && stepValue.toDouble() >= 0 && stepValue.toDouble() == std::floor(stepValue.toDouble())) {
        spec.answerStep = static_cast<long>(stepValue.toDouble());
    } else {
        errors << fmt(spec, "step", "must be a whole number >= 0 or \"first-contact\"");
    }
    // quantities: the trace ids of the answer table
    const QJsonArray quantities = o.value("quantities").toArray();
    if (quantities.isEmpty()) errors << fmt(spec, "quantities", "must be a non-empty list of trace ids (rbw quantities)");
    for (qsizetype i = 0; i < quantities.size(); ++i) {
        const QString id = quantities[i].toString();
        bool known = false;
        for (const QuantityInfo& q : quantityCatalogue()) known = known || (id == QLatin1String(q.id));
        if (!known) errors << fmt(spec, QStringLiteral("quantities[%1]").arg(i), "\"" + id + "\" is not a trace id (rbw quantities)");
        spec.quantities << id;
    }
    for (const char* key : {"description", "task", "keep"}) {
        if (o.contains(QLatin1String(key)) && !o.value(QLatin1String(key)).isString()) {
            errors << fmt(spec, QLatin1String(key), "must be a string");
        }
    }
    spec.task = o.value("task").toString();
    spec.description = o.value("description").toString();
    if (o.contains("attempts")) {
        const int n = o.value("attempts").toInt(-1);
        if (n < 1 || n > 1000) errors << fmt(spec, "attempts", "must be a whole number from 1 to 1000");
        spec.attempts = n;
    }
    if (errors.isEmpty()) result.spec = std::move(spec);
    return result;
}

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
            if (!rule.nonzero || !allZero) break;
        }
        QJsonValue value;
        if (rule.vector) {
            QJsonArray a;
            for (double x : values) a.append(x);
            value = a;
        } else {
            value = values[0];
        }
        for (const QString& path : rule.paths) scene = setAt(scene, *parsePath(path), value);
    }
    return scene.toObject();
}

// The scene as indented JSON like the lessons' own files: an array of numbers on one
// line, "name" and "description" first, the other keys in Qt's (sorted) order. Numbers
// are written as Qt writes them (the shortest text that reads back the same double).
void writeJson(const QJsonValue& v, int indent, QByteArray& out)
{
    const QByteArray pad(indent * 2, ' ');
    const QByteArray inner((indent + 1) * 2, ' ');
    auto scalar = [](const QJsonValue& x) {
        QByteArray text = QJsonDocument(QJsonArray{x}).toJson(QJsonDocument::Compact);
        return text.mid(1, text.size() - 2);   // strip "[" and "]"
    };
    if (v.isObject()) {
        const QJsonObject o = v.toObject();
        QStringList keys;
        for (const char* first : {"name", "description"}) {
            if (o.contains(QLatin1String(first))) keys << QLatin1String(first);
        }
        for (const QString& k : o.keys()) {
            if (!keys.contains(k)) keys << k;
        }
        out += "{\n";
        for (qsizetype i = 0; i < keys.size(); ++i) {
            out += inner + scalar(keys[i]) + ": ";
            writeJson(o.value(keys[i]), indent + 1, out);
            out += i + 1 < keys.size() ? ",\n" : "\n";
        }
        out += pad + "}";
    } else if (v.isArray()) {
        const QJsonArray a = v.toArray();
        bool flat = true;
        for (const QJsonValue& x : a) flat = flat && !x.isObject() && !x.isArray();
        if (flat) {
            out += "[";
            for (qsizetype i = 0; i < a.size(); ++i) out += (i > 0 ? ", " : "") + scalar(a[i]);
            out += "]";
            return;
        }
        out += "[\n";
        for (qsizetype i = 0; i < a.size(); ++i) {
            out += inner;
            writeJson(a[i], indent + 1, out);
            out += i + 1 < a.size() ? ",\n" : "\n";
        }
        out += pad + "]";
    } else {
        out += scalar(v);
    }
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
        const StepStatus status = world.step(&trace);
        if (!status.ok) return "the scene blows up in step " + QString::number(k) + ": " + QString::fromStdString(status.message);
        const bool answerHere = spec.answerAtFirstContact ? !trace.contacts.empty() : k == spec.answerStep;
        if (answerHere && !haveAnswer) {
            haveAnswer = true;
            g.answerStep = k;
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
        doc.insert("name", spec.scene.value("name").toString(spec.lessonId) + ", seed " + QString::number(seed));
        if (!spec.description.isEmpty()) doc.insert("description", spec.description);
        QByteArray bytes;
        writeJson(doc, 0, bytes);
        bytes += '\n';
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
        for (const TraceEntry& e : candidate.answerTrace.entries) {
            if (spec.quantities.contains(QLatin1String(e.info->id))) candidate.key.push_back(e);
        }
        return candidate;
    }
    g.errors << errorIn(spec.file, "vary",
                        "no scene out of " + QString::number(spec.attempts) + " sub-seeds of seed " + QString::number(seed) +
                            " kept the lesson's point; the last: " + lastReason);
    return g;
}

std::vector<Answer> exerciseAnswers(const GeneratedExercise& g)
{
    std::vector<Answer> answers;
    for (const TraceEntry& e : g.key) {
        Answer a;
        a.quantity = e.info->id;
        if (e.info->indexKind == IndexKind::Contact) {
            a.contact = e.index;
        } else {
            a.body = e.body;
            a.index = e.index;
        }
        std::visit(
            [&](const auto& v) {
                using T = std::decay_t<decltype(v)>;
                if constexpr (std::is_same_v<T, double>) {
                    a.value = {v};
                } else if constexpr (std::is_same_v<T, Vec3>) {
                    a.value = {v.x(), v.y(), v.z()};
                } else if constexpr (std::is_same_v<T, Quat>) {
                    a.value = {v.w(), v.x(), v.y(), v.z()};
                } else {
                    for (int r = 0; r < 3; ++r)
                        for (int c = 0; c < 3; ++c) a.value.push_back(v(r, c));
                }
            },
            e.value);
        answers.push_back(std::move(a));
    }
    return answers;
}

QByteArray exerciseAnswersJson(const GeneratedExercise& g)
{
    return answersToJson(exerciseAnswers(g), g.answerStep, *g.scene);
}

namespace {

QString cellText(const QJsonValue& v)
{
    if (v.isObject()) {
        QStringList parts;
        const QJsonObject o = v.toObject();
        for (auto it = o.begin(); it != o.end(); ++it) parts << it.key() + ": " + cellText(it.value());
        return parts.join("; ");
    }
    if (v.isArray()) {
        QStringList parts;
        for (const QJsonValue& x : v.toArray()) parts << cellText(x);
        return '[' + parts.join(", ") + ']';
    }
    if (v.isDouble()) return QString::number(v.toDouble(), 'g', 15);
    if (v.isBool()) return v.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    return v.toString();
}

QString tableOf(const QString& title, const QJsonArray& rows)
{
    if (rows.isEmpty()) return QString();
    QStringList columns;
    for (const QJsonValue& r : rows) {
        for (const QString& k : r.toObject().keys()) {
            if (!columns.contains(k)) columns << k;
        }
    }
    QString html = "<h3>" + title + "</h3>\n<table>\n<tr>";
    for (const QString& c : columns) html += "<th>" + c.toHtmlEscaped() + "</th>";
    html += "</tr>\n";
    for (const QJsonValue& r : rows) {
        html += "<tr>";
        for (const QString& c : columns) html += "<td>" + cellText(r.toObject().value(c)).toHtmlEscaped() + "</td>";
        html += "</tr>\n";
    }
    return html + "</table>\n";
}

} // namespace

QString exerciseWorksheetHtml(const ExerciseSpec& spec, const GeneratedExercise& g, bool withAnswers)
{
    const QJsonObject scene = QJsonDocument::fromJson(g.sceneJson).object();
    const QString title = scene.value("name").toString();
    QString html;
    html += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + title.toHtmlEscaped() +
            (withAnswers ? QStringLiteral(" (answer key)") : QString()) + "</title>\n";
    html += "<style>body{font-family:sans-serif;max-width:60em;margin:2em auto}table{border-collapse:collapse;margin:.5em 0}"
            "th,td{border:1px solid #888;padding:.3em .6em;text-align:left}td.answer{min-width:18em;height:1.6em}</style>\n"
            "</head>\n<body>\n";
    html += "<h1>" + title.toHtmlEscaped() + (withAnswers ? QStringLiteral(" &mdash; answer key") : QString()) + "</h1>\n";
    html += "<p>Lesson " + spec.lessonId.toHtmlEscaped() + ", seed " + QString::number(g.seed) +
            ". Regenerate with <code>rbw exercise " + spec.lessonId.toHtmlEscaped() + " --seed " + QString::number(g.seed) +
            "</code>.</p>\n";
    html += "<h2>Setup</h2>\n<table>\n";
    for (auto it = scene.begin(); it != scene.end(); ++it) {
        if (it.value().isArray() && !it.value().toArray().isEmpty() && it.value().toArray()[0].isObject()) continue;
        if (it.key() == "name" || it.key() == "description") continue;
        html += "<tr><th>" + it.key().toHtmlEscaped() + "</th><td>" + cellText(it.value()).toHtmlEscaped() + "</td></tr>\n";
    }
    html += "</table>\n";
    for (const QString& list : QStringList{"bodies", "forces", "probes", "planes", "pairs"}) {
        html += tableOf(list.left(1).toUpper() + list.mid(1), scene.value(list).toArray());
    }
    html += "<p>Lengths in m, masses in kg, forces in N, velocities in m/s and rad/s, times in s; "
            "a force acts from step from_step up to (not including) to_step.</p>\n";
    html += "<h2>Your task</h2>\n<p>";
    if (!spec.task.isEmpty()) html += spec.task.toHtmlEscaped() + ' ';
    html += "Compute the numbers of step k = " + QString::number(g.answerStep) + " (from t = " +
            QString::number(g.answerStep * g.scene->dt, 'g', 10) + " s to t = " +
            QString::number((g.answerStep + 1) * g.scene->dt, 'g', 10) + " s).</p>\n";
    html += "<table>\n<tr><th>quantity</th><th>id</th><th>body / contact</th><th>index</th><th>unit</th><th>your answer</th></tr>\n";
    for (const TraceEntry& e : g.key) {
        const bool contact = e.info->indexKind == IndexKind::Contact;
        const QString who = contact ? "contact " + QString::number(e.index)
                                    : (e.body >= 0 ? QString::fromStdString(g.scene->bodies[e.body].name) : QString());
        const QString index = (!contact && e.index >= 0) ? QString::number(e.index) : QString();
        html += "<tr><td>" + QString::fromUtf8(e.info->text).toHtmlEscaped() + "</td><td><code>" +
                QString::fromLatin1(e.info->id) + "</code></td><td>" + who.toHtmlEscaped() + "</td><td>" + index +
                "</td><td>" + QString::fromUtf8(e.info->unit).toHtmlEscaped() + "</td><td class=\"answer\">" +
                (withAnswers ? formatValue(e.value).toHtmlEscaped() : QString()) + "</td></tr>\n";
    }
    html += "</table>\n";
    if (withAnswers) {
        html += "<p>The workbook's numbers, from the physics' trace of step " + QString::number(g.answerStep) +
                ". Check your own with <code>rbw check</code> (docs/checker.md).</p>\n";
    }
    html += "</body>\n</html>\n";
    return html;
}

} // namespace rbw
