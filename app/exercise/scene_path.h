// The small JSON-path language of exercise.json (docs/exercises.md): a scene path such
// as "bodies[0].mass", "forces[1].force" or "dt" names one value of a scene document.
// Keys are identifiers, each may be followed by array indices "[k]". Reading a path
// that is not in the document gives nothing; writing replaces the value in a copy.
#pragma once

#include <QJsonValue>
#include <QString>

#include <optional>
#include <vector>

namespace rbw {

struct ScenePathToken {
    QString key;        // an object key, or empty for an array index
    qint64 index = -1;  // an index too large for qint64 is qint64's largest: in no array
};

// The tokens of PATH, or nothing when it is not a scene path.
std::optional<std::vector<ScenePathToken>> parseScenePath(const QString& path);

// The value at the path, or nothing when the document has no such value.
std::optional<QJsonValue> sceneValueAt(const QJsonValue& document, const std::vector<ScenePathToken>& path);

// DOCUMENT with the value at the path replaced by VALUE (the path must exist).
QJsonValue withSceneValue(const QJsonValue& document, const std::vector<ScenePathToken>& path, const QJsonValue& value);

} // namespace rbw
