// The strict JSON scanner: one pass over a JSON file's raw bytes for what
// QJsonDocument does not say. The scene loader uses it, and every other reader of a
// JSON file a person writes (exercise.json, app/exercise/exercise_spec.cpp), so that a
// key given twice is refused everywhere with the same message: there is one scanner.
#pragma once

#include <QByteArray>
#include <QJsonParseError>
#include <QString>

#include <optional>

namespace rbw::scenefile {

// A problem the raw scan finds: its JSON path and the reason.
struct RawFinding {
    QString path;
    QString reason;
};

// of two equal keys in an object silently, and reports NaN, Infinity or 1e999 only as
// "illegal number" at an offset. The scan follows the nesting of objects and arrays,
// so it names the JSON path of
//   - a key given twice in one object (compared after unescaping, as QJsonDocument
//     compares them), and
//   - with checkNumbers, a bare word that stands for a number a double cannot hold.
// It stops at the first finding, and looks only at tokens that start before `end`:
// the text QJsonDocument read without error, which is therefore JSON. Each open
// object keeps a hash set of its keys, so the scan is linear in the text.
std::optional<RawFinding> scanJson(const QByteArray& json, qsizetype end, bool checkNumbers);

// The scan after QJsonDocument::fromJson(json, &error): over the whole text when it
// parsed (a duplicate key), or up to where it stopped at a bare word NaN, Infinity or
// 1e999 (that word's path and reason, or a duplicate key before it). nullopt when the
// scan finds nothing, or the text failed for another reason (QJsonDocument's error
// then says where).
std::optional<RawFinding> scanParsed(const QByteArray& json, const QJsonParseError& error);

// "line L, column C" (1-based, columns count bytes) of a byte offset in the text.
QString textPosition(const QByteArray& text, qsizetype offset);

} // namespace rbw::scenefile
