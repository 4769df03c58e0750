#include "app/scene/scene_loader.h"

#include "app/scene/scene_fields.h"
#include "app/scene/scene_mapping.h"
#include "app/scene/strict_json_scan.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>

#include <optional>
#include <vector>

namespace rbw {

using scenefile::FieldError;
using scenefile::RawFinding;
using scenefile::scanParsed;
using scenefile::textPosition;
using scenefile::toScene;

SceneLoadResult parseScene(const QByteArray& json, const QString& fileLabel)
{
    SceneLoadResult result;
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    // Duplicate keys in a file that parsed; the field of a NaN or 1e999 where
    // QJsonDocument stopped.
    if (const std::optional<RawFinding> f = scanParsed(json, parseError)) {
        result.errors << QStringLiteral("%1: %2: %3").arg(fileLabel, f->path, f->reason);
        return result;
    }
    if (parseError.error != QJsonParseError::NoError) {
        // QJsonParseError::offset points at (or just after) the offending token.
        result.errors << QStringLiteral("%1: malformed JSON at %2: %3")
                             .arg(fileLabel, textPosition(json, parseError.offset), parseError.errorString());
        return result;
    }
    if (!doc.isObject()) {
        result.errors << QStringLiteral("%1: the top level must be a JSON object").arg(fileLabel);
        return result;
    }
    try {
        // Structure first (stops at the first problem), then every rule of the physics
        // (all problems at once), the same validate() a scene built in code goes through.
        SceneDef scene = toScene(doc.object(), fileLabel);
        const std::vector<SceneIssue> issues = validate(scene);
        // Every problem, up to a screenful: 100 000 bad bodies need not print 100 000 lines.
        constexpr std::size_t kShown = 100;
        for (std::size_t i = 0; i < issues.size() && i < kShown; ++i) {
            result.errors << QStringLiteral("%1: %2: %3")
                                 .arg(fileLabel, QString::fromStdString(issues[i].path),
                                      QString::fromStdString(issues[i].reason));
        }
        if (issues.size() > kShown) {
            result.errors << QStringLiteral("%1: \u2026 and %2 more problems (the first %3 are listed)")
                                 .arg(fileLabel)
                                 .arg(issues.size() - kShown)
                                 .arg(kShown);
        }
        if (result.errors.isEmpty()) {
            result.scene = std::move(scene);
        }
    } catch (const FieldError& e) {
        result.errors << QStringLiteral("%1: %2: %3").arg(fileLabel, e.path, e.reason);
    }
    return result;
}

SceneLoadResult loadSceneFile(const QString& filePath)
{
    QFile file(filePath);
    if (!file.open(QIODevice::ReadOnly)) {
        SceneLoadResult result;
        result.errors << QStringLiteral("%1: cannot open: %2").arg(filePath, file.errorString());
        return result;
    }
    return parseScene(file.readAll(), filePath);
}

} // namespace rbw