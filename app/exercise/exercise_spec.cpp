#include "app/exercise/exercise_spec.h"

#include "app/exercise/scene_path.h"
#include "app/exercise/value_grid.h"
#include "app/core/lesson_catalogue.h"
#include "app/scene/scene_loader.h"
#include "app/scene/strict_json_scan.h"
#include "app/scene/scene_format.h"
#include "physics/engine/quantity_catalogue.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>

#include <cmath>

namespace rbw {

namespace {

QString fmt(const ExerciseSpec& spec, const QString& path, const QString& reason)
{
    return spec.file + ": " + path + ": " + reason;
}

std::optional<QString> resolveLessonFolder(const QString& lesson, QString* error)
{
    const QFileInfo asPath(lesson);
    if (asPath.isDir()) return QDir::cleanPath(asPath.filePath());
    const QString dir = lessonsDirectory();
    const QFileInfo asId(QDir(dir).filePath(lesson));
    // "06-box-on-plane" or a lesson's further exercise in a folder of its own,
    // "06-box-on-plane/separating" (never "..": an id stays inside the lessons)
    const QStringList parts = lesson.split('/');
    const bool idForm = !lesson.isEmpty() && parts.size() <= 2 && !parts.contains(QString()) &&
                        !parts.contains(QStringLiteral(".")) && !parts.contains(QStringLiteral(".."));
    if (idForm && asId.isDir()) return QDir::cleanPath(asId.filePath());
    QStringList known;
    for (const QString& id : QDir(dir).entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name)) {
        if (QFile::exists(QDir(dir).filePath(id + "/exercise.json"))) known << id;
        const QDir lessonDir(QDir(dir).filePath(id));
        for (const QString& sub : lessonDir.entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name)) {
            if (QFile::exists(lessonDir.filePath(sub + "/exercise.json"))) known << id + '/' + sub;
        }
    }
    *error = lesson + ": LESSON: no lesson folder of that name (lessons with exercises: " + known.join(", ") + ")";
    return std::nullopt;
}

} // namespace

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
    // A lesson's further exercise (a folder inside the lesson's): "06-box-on-plane/separating"
    if (const QDir parent = QFileInfo(*folder).dir(); QFile::exists(parent.filePath(QStringLiteral("lesson.md")))) {
        spec.lessonId = parent.dirName() + '/' + spec.lessonId;
    }
    QFile file(spec.file);
    if (!file.open(QIODevice::ReadOnly)) {
        result.errors << fmt(spec, "(file)", "cannot open: " + file.errorString() + " (this lesson has no exercise)");
        return result;
    }
    QJsonParseError parseError;
    const QByteArray bytes = file.readAll();
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &parseError);
    // A key given twice (QJsonDocument keeps the last silently), NaN or 1e999: the
    // scene loader's strict scan, with the JSON path.
    if (const std::optional<scenefile::RawFinding> f = scenefile::scanParsed(bytes, parseError)) {
        result.errors << fmt(spec, f->path, f->reason);
        return result;
    }
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
            if (!QStringList{"path", "paths", "range", "step", "nonzero", "avoid"}.contains(key)) {
                errors << fmt(spec, at + "." + key, "unknown key; known: path, paths, range, step, nonzero, avoid");
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
        if (rule.nonzero) {
            // Some component must have a value other than 0 on its grid, else every
            // draw is all zero and "nonzero" would be broken silently.
            bool onlyZero = true;
            for (size_t c = 0; c < rule.lo.size(); ++c) {
                onlyZero = onlyZero && gridCount(rule.lo[c], rule.hi[c], rule.step) == 0 &&
                           gridValue(rule.lo[c], 0, rule.step, rule.decimals) == 0.0;
            }
            if (onlyZero) errors << fmt(spec, at + ".nonzero", "is true, but the range holds only 0");
        }
        // avoid: values of a number's grid that are redrawn (h = 1 hides missing-time-step).
        if (v.contains("avoid")) {
            const QJsonArray avoid = v.value("avoid").toArray();
            if (!v.value("avoid").isArray() || avoid.isEmpty()) {
                errors << fmt(spec, at + ".avoid", "must be a list of numbers of the range, e.g. [1]");
            } else if (isVector) {
                errors << fmt(spec, at + ".avoid", "is for a number; a vector's range avoids nothing");
            } else if (!rule.lo.empty()) {
                const std::uint64_t n = gridCount(rule.lo[0], rule.hi[0], rule.step);
                for (qsizetype a = 0; a < avoid.size(); ++a) {
                    const QString where = at + QStringLiteral(".avoid[%1]").arg(a);
                    const double x = avoid[a].toDouble();
                    bool onGrid = false;
                    for (std::uint64_t k = 0; avoid[a].isDouble() && k <= n && !onGrid; ++k) {
                        onGrid = gridValue(rule.lo[0], k, rule.step, rule.decimals) == x;
                    }
                    if (!onGrid) {
                        errors << fmt(spec, where, "must be one of the range's values (lo + k step)");
                    } else {
                        rule.avoid.push_back(x);
                    }
                }
                if (static_cast<std::uint64_t>(rule.avoid.size()) > n) {
                    errors << fmt(spec, at + ".avoid", "avoids every value of the range");
                }
            }
        }
        // Every path must exist in the scene with the range's shape.
        for (const QString& path : rule.paths) {
            const auto tokens = parseScenePath(path);
            const QString where = at + (v.contains("path") ? QStringLiteral(".path") : QStringLiteral(".paths"));
            if (!tokens) {
                errors << fmt(spec, where, "\"" + path + "\" is not a scene path such as \"bodies[0].mass\"");
                continue;
            }
            const std::optional<QJsonValue> current = sceneValueAt(spec.scene, *tokens);
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
    using sceneformat::Key;
    using sceneformat::key;
    for (const QJsonValue& b : spec.scene.value(key(Key::Bodies)).toArray()) {
        names << b.toObject().value(key(Key::BodyName)).toString();
    }
    for (const QJsonValue& p : spec.scene.value(key(Key::Planes)).toArray()) {
        names << p.toObject().value(key(Key::PlaneName)).toString();
    }
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

    // step: a whole number k, "first-contact" or "first-separating"
    const QJsonValue stepValue = o.value("step");
    if (stepValue.isString() && stepValue.toString() == "first-contact") {
        spec.answerAtFirstContact = true;
    } else if (stepValue.isString() && stepValue.toString() == "first-separating") {
        spec.answerAtFirstSeparating = true;
    } else if (stepValue.isUndefined()) {
        spec.answerStep = 0;
    } else if (stepValue.isDouble() && stepValue.toDouble() >= 0 && stepValue.toDouble() == std::floor(stepValue.toDouble())) {
        spec.answerStep = static_cast<long>(stepValue.toDouble());
    } else {
        errors << fmt(spec, "step", "must be a whole number >= 0, \"first-contact\" or \"first-separating\"");
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

} // namespace rbw
