// The mapping from a scene file's JSON object to a physics SceneDef (internal to
// app/scene): each key read into its SceneDef field, the notations with no SceneDef
// counterpart resolved (orientation forms, enum strings, a fixed body's "mass" key,
// names into indices). Structure only: the value rules are validate()'s.
#pragma once

#include "physics/engine/scene.h"

#include <QJsonObject>
#include <QString>

namespace rbw::scenefile {

// The scene the object describes; throws FieldError (scene_fields.h) at the first
// field that is missing, unknown or of the wrong type. The file's name is the scene's
// name when the file gives none.
SceneDef toScene(const QJsonObject& o, const QString& fileLabel);

} // namespace rbw::scenefile
