// The scene editor's fields as text (internal to app/gui/panels/editor): the unit and
// meaning shown beside each key, a value written as text ("1, 2, 3") and read back
// from what the student typed, in the loader's terms ("must be a finite number, got
// \"abc\"").
#pragma once

#include "physics/engine/scene.h"

#include <QHash>
#include <QList>
#include <QString>

#include <cmath>
#include <limits>

namespace rbw::editorfields {

// Left out, a torque lasts for ever (the loader's default).
inline constexpr long kForever = std::numeric_limits<long>::max();
// The words a value cell shows for "not given": the scene's value, a torque that never
// ends, the contact model's default.
inline const QString kScenes = QStringLiteral("(scene's)");
inline const QString kNever = QStringLiteral("never");
inline const QString kDefault = QStringLiteral("(default)");

// The unit shown beside a key, and a one-line meaning (docs/scene-format.md).
struct KeyInfo {
    const char* unit;
    const char* meaning;
};
const QHash<QString, KeyInfo>& keyInfo();

QString positionFixText(PositionFix f);
QString convention(InertiaConvention c);

// The shortest text that reads back as the same double.
QString num(double x);
// "x, y, z".
QString vecText(const Vec3& v);
// What the student typed, in quotes, cut at 40 characters.
QString quoted(const QString& text);

// Numbers from "1, 2, 3", "[1 2 3]" or "1;2;3" (C locale: a point is the decimal sign).
bool parseNumbers(const QString& text, int count, QList<double>* out, QString* error);
bool parseNumber(const QString& text, double* x, QString* error);
// As the loader reads a whole number: no fraction, at most 9e15 in size.
bool parseWhole(const QString& text, long* n, QString* error);
bool parseVec(const QString& text, Vec3* v, QString* error);

// As the loader: a direction is normalised unless it is unit to rounding already.
template <typename V>
V normalisedAsLoaded(const V& v)
{
    return std::abs(v.squaredNorm() - 1.0) <= 16 * std::numeric_limits<double>::epsilon() ? v : v.normalized();
}

// Whether the key of a group (SceneEditorModel::Group) is a check box.
bool isBool(int group, const QString& key);

} // namespace rbw::editorfields
