// Reads a scene file (JSON, see docs/scene-format.md) into a physics SceneDef.
//
// Every bad input is refused before anything runs: the error names the file, the
// JSON path of the field (e.g. "bodies[0].mass") and the reason. Malformed JSON is
// reported with its line and column.
#pragma once

#include "physics/scene.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace rbw {

struct SceneLoadResult {
    std::optional<SceneDef> scene;
    QStringList errors;   // "file: path: reason", one per problem; empty on success

    bool ok() const { return scene.has_value(); }
};

SceneLoadResult loadSceneFile(const QString& filePath);
SceneLoadResult parseScene(const QByteArray& json, const QString& fileLabel);

} // namespace rbw
