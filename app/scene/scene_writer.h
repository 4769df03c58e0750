// Writes a SceneDef back as a scene file (docs/scene-format.md): the inverse of
// loadSceneFile(), so that the app's scene editor can save what the student edited.
//
// The text round-trips: parseScene(writeScene(s)) gives a scene equal to s, field by
// field and bit for bit (sceneDifferences() is empty), for every valid scene. To keep
// that exact:
//   - every number is written as the shortest text that reads back as the same double
//     (QJsonDocument's own number format);
//   - an orientation is written as its quaternion [w, x, y, z] (scalar first), and a
//     plane normal as the unit vector the scene holds; the loader keeps a vector that
//     is unit to rounding as it is written (it normalises only longer or shorter ones);
//   - every key is written, defaults too, except those that have no value to give
//     (a fixed body's mass, a torque that lasts for ever, a scene without a push).
// Keys come in the order of docs/scene-format.md, not alphabetically, so the file
// reads like a hand-written one.
#pragma once

#include "physics/engine/scene.h"

#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <QStringList>

namespace rbw {

// The scene as a JSON object (keys unordered, as QJsonObject holds them).
QJsonObject sceneToJson(const SceneDef& scene);

// The scene file's text: indented, one body (force, probe, ...) per line, keys in the
// documented order, UTF-8, ending with a newline.
QByteArray writeScene(const SceneDef& scene);

// Writes the scene to a file through QSaveFile: the old file stays whole until the
// new one is complete. False with the reason ("FILE: cannot write: ...") otherwise.
bool saveSceneFile(const SceneDef& scene, const QString& path, QString* error = nullptr);

// Every field in which two scenes differ, as "bodies[1].mass: 2 != 3" (paths in the
// scene file's terms); empty when they are equal. Doubles compare with ==, so
// "equal" is bit for bit (up to the sign of zero). A fixed body's mass is not
// compared: a fixed body has none (the file may not give it).
QStringList sceneDifferences(const SceneDef& a, const SceneDef& b);

} // namespace rbw
