// The scene editor's fields as text (internal to app/gui/panels/editor): the unit and
// meaning shown beside each key, a value written as text ("1, 2, 3") and read back
// from what the student typed, in the loader's terms ("must be a finite number, got
// \"abc\"").
#pragma once

#include "app/scene/scene_format.h"
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

// One row of an element (or of the settings): a key of the scene-format table, and for
// a pair's two names which of them (0, 1; -1 for every other key).
struct Field {
    sceneformat::Key key;
    int index = -1;
};

// The rows of a group (SceneEditorModel::Group), in the table's order: the settings are
// the top-level keys with a single value (energy_jump's two keys inline), the other
// groups the keys of their element's object.
QList<Field> fieldsOf(int group);
// The row's key as the tree and the paths show it: "mass", "energy_jump.factor", "bodies[1]".
QString fieldName(const Field& f);
// The unit shown beside it ("" for none), and its meaning (the table's).
QString fieldUnit(const Field& f);
QString fieldMeaning(const Field& f);
// A true/false key with a default is a check box (sleep, which may be left out, is a choice).
bool isCheckBox(const Field& f);


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

} // namespace rbw::editorfields
