// The strict JSON scanner (internal to app/scene): one pass over a scene file's raw
// bytes for what QJsonDocument does not say.
#pragma once

#include <QByteArray>
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

// "line L, column C" (1-based, columns count bytes) of a byte offset in the text.
QString textPosition(const QByteArray& text, qsizetype offset);

} // namespace rbw::scenefile
