#include "app/scene/scene_fields.h"

#include "app/scene/did_you_mean.h"
#include "physics/engine/scene.h"

#include <QLocale>

#include <cmath>
#include <cstdlib>
#include <limits>

namespace rbw::scenefile {

QString join(const QString& path, const QString& key)
{
    return path.isEmpty() ? key : path + '.' + key;
}

// What a message echoes from the file (a key, a word): cut and escaped by physics'
// messageText(). It keeps 40 characters; 200 UTF-16 units hold at least 100, so a
// 50 MB key is never copied whole.
QString shown(const QString& text)
{
    return QString::fromStdString(messageText(text.left(200).toStdString()));
}

// The shortest text that reads back as the same double (2.0000001, not Qt's default 2).
QString numText(double x)
{
    return QString::number(x, 'g', QLocale::FloatingPointShortest);
}

QString typeName(const QJsonValue& v)
{
    switch (v.type()) {
    case QJsonValue::Null: return QStringLiteral("null");
    case QJsonValue::Bool: return QStringLiteral("a boolean");
    case QJsonValue::Double: return QStringLiteral("a number");
    case QJsonValue::String: return QStringLiteral("a string");
    case QJsonValue::Array: return QStringLiteral("an array");
    case QJsonValue::Object: return QStringLiteral("an object");
    case QJsonValue::Undefined: return QStringLiteral("nothing");
    }
    return QStringLiteral("?");
}

void checkKeys(const QJsonObject& o, const QString& path, const QStringList& allowed)
{
    for (auto it = o.begin(); it != o.end(); ++it) {
        if (allowed.contains(it.key())) {
            continue;
        }
        const QString best = nearestKey(it.key(), allowed);
        QString reason = QStringLiteral("unknown key");
        if (!best.isEmpty()) {
            reason += QStringLiteral(" (did you mean \"%1\"?)").arg(best);
        } else {
            reason += QStringLiteral(" (allowed: %1)").arg(allowed.join(QStringLiteral(", ")));
        }
        throw FieldError{join(path, shown(it.key())), reason};
    }
}

QJsonValue require(const QJsonObject& o, const QString& path, const QString& key)
{
    if (!o.contains(key)) {
        throw FieldError{join(path, key), QStringLiteral("required field is missing")};
    }
    return o.value(key);
}

// A number JSON cannot hold (NaN, Infinity, 1e999) is refused by QJsonDocument, and
// the raw scan in parseScene() names its field; the check below only guards that.
double toNumber(const QJsonValue& v, const QString& path)
{
    if (!v.isDouble()) {
        throw FieldError{path, QStringLiteral("must be a number, got %1").arg(typeName(v))};
    }
    const double x = v.toDouble();
    if (!std::isfinite(x)) {
        throw FieldError{path, QStringLiteral("must be a finite number, got %1").arg(numText(x))};
    }
    return x;
}

// Whole numbers are read into a long; beyond 9e15 a double no longer holds every
// whole number, so larger ones are refused here (steps has its own, lower limit).
long toInteger(const QJsonValue& v, const QString& path)
{
    const double x = toNumber(v, path);
    if (x != std::floor(x)) {
        throw FieldError{path, QStringLiteral("must be a whole number, got %1").arg(numText(x))};
    }
    if (std::abs(x) > 9.0e15) {
        throw FieldError{path, QStringLiteral("must be a whole number from -9e15 to 9e15, got %1").arg(numText(x))};
    }
    return static_cast<long>(x);
}

Vec3 toVec3(const QJsonValue& v, const QString& path)
{
    if (!v.isArray() || v.toArray().size() != 3) {
        throw FieldError{path, QStringLiteral("must be an array of 3 numbers, got %1")
                                   .arg(v.isArray() ? QStringLiteral("%1 elements").arg(v.toArray().size())
                                                    : typeName(v))};
    }
    const QJsonArray a = v.toArray();
    return Vec3(toNumber(a[0], path + "[0]"), toNumber(a[1], path + "[1]"),
                toNumber(a[2], path + "[2]"));
}

Vec3 vec3Or(const QJsonObject& o, const QString& path, const QString& key, const Vec3& fallback)
{
    return o.contains(key) ? toVec3(o.value(key), join(path, key)) : fallback;
}

QString toString(const QJsonValue& v, const QString& path)
{
    if (!v.isString()) {
        throw FieldError{path, QStringLiteral("must be a string, got %1").arg(typeName(v))};
    }
    return v.toString();
}

bool toBool(const QJsonValue& v, const QString& path)
{
    if (!v.isBool()) {
        throw FieldError{path, QStringLiteral("must be true or false, got %1").arg(typeName(v))};
    }
    return v.toBool();
}

QJsonObject toObject(const QJsonValue& v, const QString& path)
{
    if (!v.isObject()) {
        throw FieldError{path, QStringLiteral("must be an object, got %1").arg(typeName(v))};
    }
    return v.toObject();
}

QJsonArray toArray(const QJsonValue& v, const QString& path)
{
    if (!v.isArray()) {
        throw FieldError{path, QStringLiteral("must be an array, got %1").arg(typeName(v))};
    }
    return v.toArray();
}

// A vector or quaternion is normalised by dividing by its length, sqrt of the sum of
// the squares: that sum must neither overflow ([1e308, 1e308, 0]) nor round to 0
// ([1e-200, 0, 0]), or the direction is lost (it used to become the identity).
void requireNormalisable(double squaredNorm, const QString& path)
{
    if (!std::isfinite(squaredNorm)) {
        throw FieldError{path, QStringLiteral("its length overflows (the sum of the squares exceeds the largest "
                                              "double), so it cannot be normalised; only its direction counts, so "
                                              "divide it by a large number")};
    }
    if (squaredNorm == 0.0) {
        throw FieldError{path, QStringLiteral("its length underflows (the sum of the squares rounds to 0), so it "
                                              "cannot be normalised; only its direction counts, so multiply it by "
                                              "a large number")};
    }
}

// A length that is 1 to rounding (|x.x - 1| <= 16 eps): normalising it again would only
// move the last bits, so it is kept as written and a scene the app saved (scene_writer.h)
// reads back bit for bit.
bool isUnitToRounding(double squaredNorm)
{
    return std::abs(squaredNorm - 1.0) <= 16 * std::numeric_limits<double>::epsilon();
}

} // namespace rbw::scenefile
