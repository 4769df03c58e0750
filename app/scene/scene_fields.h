// The loader's field readers (internal to app/scene): each reads one JSON value as the
// scene format's type, or throws a FieldError that names the field's JSON path and the
// reason ("bodies[0].mass: must be a number, got a string"). parseScene() turns the
// first FieldError into the file's error line.
#pragma once

#include "physics/engine/math_types.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <QStringList>

namespace rbw::scenefile {

// Thrown inside the loader only; parseScene() turns it into an error line.
struct FieldError {
    QString path;
    QString reason;
};

// "bodies[0]" + "mass" -> "bodies[0].mass"; "" + "dt" -> "dt".
QString join(const QString& path, const QString& key);

// What a message echoes from the file (a key, a word): cut and escaped by physics'
// messageText().
QString shown(const QString& text);

// The shortest text that reads back as the same double (2.0000001, not Qt's default 2).
QString numText(double x);

// "a number", "a string", ...: what a value is, for "must be X, got Y".
QString typeName(const QJsonValue& v);

// Unknown keys are refused (with "did you mean", did_you_mean.h), so a typo is caught
// instead of silently ignored.
void checkKeys(const QJsonObject& o, const QString& path, const QStringList& allowed);

QJsonValue require(const QJsonObject& o, const QString& path, const QString& key);
double toNumber(const QJsonValue& v, const QString& path);
long toInteger(const QJsonValue& v, const QString& path);
Vec3 toVec3(const QJsonValue& v, const QString& path);
Vec3 vec3Or(const QJsonObject& o, const QString& path, const QString& key, const Vec3& fallback);
QString toString(const QJsonValue& v, const QString& path);
bool toBool(const QJsonValue& v, const QString& path);
QJsonObject toObject(const QJsonValue& v, const QString& path);
QJsonArray toArray(const QJsonValue& v, const QString& path);

// A vector or quaternion to be normalised: its squared length must neither overflow
// nor round to 0.
void requireNormalisable(double squaredNorm, const QString& path);

// A length that is 1 to rounding (|x.x - 1| <= 16 eps): kept as written, not normalised
// again, so a scene the app saved reads back bit for bit.
bool isUnitToRounding(double squaredNorm);

} // namespace rbw::scenefile
