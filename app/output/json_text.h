// The one JSON text writer: every JSON document the workbook writes as text is laid out
// here from QJsonValue - the scene files (app/scene/scene_writer.h), the drawn exercises
// (app/exercise/exercise_draw.h) and the streamed document of `rbw run`
// (json_output.h's JsonRunWriter). A scalar's text is QJsonDocument's own (its escaping,
// its shortest round-trip numbers, "null" for a non-finite number, which callers never
// hand over); nothing edits a finished document's text.
#pragma once

#include <QByteArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QStringList>

namespace rbw::jsontext {

// One string, number, bool or null as JSON text: `"box"`, `0.1`, `true`.
QByteArray scalar(const QJsonValue& v);

// Any value on one line, a space after each comma and inside an object's braces:
// `[1, 2, 3]`, `{ "mass": 2, "name": "box" }` (an object's keys in QJsonObject's order).
QByteArray oneLine(const QJsonValue& v);

// Appends v laid out as QJsonDocument::Indented lays it out (four spaces a level), as
// if it stood `depth` levels in: the first line is not indented (it follows what is
// already there), the rest are, and there is no final newline. At depth 0 this is
// QJsonDocument(v).toJson(QJsonDocument::Indented) without its last newline.
void appendIndented(QByteArray& out, const QJsonValue& v, int depth);

// The members of o as an indented document at `depth` lays them out, without braces
// and without a final newline: `    "dt": 0.01,\n    "file": "a.json"` at depth 1.
// Empty for an empty object.
QByteArray indentedMembers(const QJsonObject& o, int depth);

// The layout of the lessons' scene files: two spaces a level, an array of scalars on
// one line, the keys in `firstKeys` first (those o has, in that order, at every level),
// then the others in QJsonObject's (sorted) order; ends with a newline.
QByteArray sceneFileText(const QJsonObject& o, const QStringList& firstKeys);

} // namespace rbw::jsontext
