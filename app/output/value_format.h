// Text forms of trace values, for tables, clipboard copies and LaTeX. Formatting
// only: the numbers come from the trace.
#pragma once

#include "physics/engine/trace.h"

#include <QJsonValue>
#include <QString>

namespace rbw {

// Display forms chop round-off: an entry below 1e-12 of the value's largest entry is
// shown as 0 (R of a 90 degree turn has cos 90 deg = 6e-17). JSON keeps every bit.

// Plain text with `digits` significant digits: "-2.4", "(1, 1, 0)",
// "[w x y z] = [1, 0, 0, 0]", "[[a, b, c], [d, e, f], [g, h, i]]".
QString formatValue(const TraceValue& value, int digits = 7);

// The same for a table cell, as the derivation writes values: a vector as a column,
// one component per line; a quaternion on four lines, "w ...", "x ...", "y ...", "z ...";
// a matrix one row per line ("[a, b, c]\n[d, e, f]\n[g, h, i]"); a number as formatValue.
QString formatValueLines(const TraceValue& value, int digits = 7);

// LaTeX: a number, a column vector as pmatrix, a quaternion as (w, x, y, z), a 3x3 pmatrix.
QString latexValue(const TraceValue& value, int digits = 7);

// JSON: a number, [x, y, z], [w, x, y, z], or [[row0], [row1], [row2]] (row-major).
// Doubles are written by QJsonDocument with the shortest form that round-trips.
QJsonValue jsonValue(const TraceValue& value);
QJsonValue jsonVec3(const Vec3& v);
QJsonValue jsonQuat(const Quat& q);   // [w, x, y, z]
QJsonValue jsonMat3(const Mat3& m);   // row-major

// "scalar", "vector", "quaternion" or "matrix".
QString valueKind(const TraceValue& value);

QString formatNumber(double x, int digits = 7);

} // namespace rbw
