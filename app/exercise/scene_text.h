// A drawn scene as the text of a scene file, indented like the lessons' own files: an
// array of numbers on one line, "name" and "description" first, the other keys in Qt's
// (sorted) order. Numbers are written as Qt writes them (the shortest text that reads
// back the same double), so a seed gives the same bytes everywhere.
#pragma once

#include <QByteArray>
#include <QJsonObject>

namespace rbw {

// The document as indented JSON, ending with a newline.
QByteArray indentedSceneJson(const QJsonObject& scene);

} // namespace rbw
