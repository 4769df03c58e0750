// Reads a scene file (JSON, see docs/scene-format.md) into a physics SceneDef.
//
// Every bad input is refused before anything runs: the error names the file, the
// JSON path of the field (e.g. "bodies[0].mass") and the reason. Malformed JSON is
// reported with its line and column.
//
// The loader checks only the file's structure: JSON syntax, unknown keys (with "did
// you mean"), required keys, types, numbers JSON cannot hold, and the notations that
// have no SceneDef counterpart (orientation forms, enum strings, a fixed body's
// "mass" key, a pair's two names). Every rule about the values themselves (ranges,
// names that exist and are unique, fixed bodies at rest, pairs listed once, ...)
// is physics' validate(), which parseScene() runs on the SceneDef it built, so a
// scene built in code obeys the same rules with the same messages.
#pragma once

#include "physics/engine/scene.h"

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
