#include "tests/support/json_schema.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QLocale>
#include <QSet>

#include <cmath>

namespace rbw::test {
namespace {

const QSet<QString> kAnnotations{"$schema", "$id", "$comment", "title", "description", "default", "examples"};
const QSet<QString> kSchemaValued{"additionalProperties", "items", "not", "if", "then", "else"};
const QSet<QString> kListValued{"anyOf", "oneOf", "allOf"};
const QSet<QString> kOther{"type",      "enum",      "const",          "properties",       "required",
                           "minItems",  "maxItems",  "uniqueItems",    "minimum",          "maximum",
                           "minLength", "$ref",      "exclusiveMinimum", "exclusiveMaximum", "$defs"};
const QStringList kTypes{"null", "boolean", "object", "array", "number", "integer", "string"};

QString key(const QString& path, const QString& k) { return path.isEmpty() ? k : path + '.' + k; }

QString num(double x) { return QString::number(x, 'g', QLocale::FloatingPointShortest); }

QString shown(const QJsonValue& v)
{
    if (v.isString()) return '"' + v.toString() + '"';
    if (v.isDouble()) return num(v.toDouble());
    if (v.isBool()) return v.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    if (v.isNull()) return QStringLiteral("null");
    const QJsonDocument d = v.isArray() ? QJsonDocument(v.toArray()) : QJsonDocument(v.toObject());
    return QString::fromUtf8(d.toJson(QJsonDocument::Compact));
}

bool hasType(const QJsonValue& v, const QString& type)
{
    if (type == QLatin1String("null")) return v.isNull();
    if (type == QLatin1String("boolean")) return v.isBool();
    if (type == QLatin1String("object")) return v.isObject();
    if (type == QLatin1String("array")) return v.isArray();
    if (type == QLatin1String("string")) return v.isString();
    if (type == QLatin1String("number")) return v.isDouble();
    if (type == QLatin1String("integer")) {
        const double d = v.toDouble();
        return v.isDouble() && std::isfinite(d) && d == std::floor(d);
    }
    return false;
}

} // namespace

bool jsonEqual(const QJsonValue& a, const QJsonValue& b)
{
    if (a.type() != b.type()) return false;
    switch (a.type()) {
    case QJsonValue::Double: return a.toDouble() == b.toDouble();
    case QJsonValue::Array: {
        const QJsonArray x = a.toArray(), y = b.toArray();
        if (x.size() != y.size()) return false;
        for (qsizetype i = 0; i < x.size(); ++i) {
            if (!jsonEqual(x[i], y[i])) return false;
        }
        return true;
    }
    case QJsonValue::Object: {
        const QJsonObject x = a.toObject(), y = b.toObject();
        if (x.keys() != y.keys()) return false;
        for (auto it = x.begin(); it != x.end(); ++it) {
            if (!jsonEqual(it.value(), y.value(it.key()))) return false;
        }
        return true;
    }
    default: return a == b;
    }
}

JsonSchema::JsonSchema(QJsonObject root)
    : root_(std::move(root))
{
    check(root_, QStringLiteral("#"));
}

void JsonSchema::check(const QJsonValue& schema, const QString& where)
{
    if (schema.isBool()) return;
    if (!schema.isObject()) {
        problems_ << QStringLiteral("%1: a schema must be an object or a boolean").arg(where);
        return;
    }
    const QJsonObject o = schema.toObject();
    for (auto it = o.begin(); it != o.end(); ++it) {
        const QString k = it.key();
        const QString at = where + '/' + k;
        if (kAnnotations.contains(k)) continue;
        if (kSchemaValued.contains(k)) {
            check(it.value(), at);
        } else if (kListValued.contains(k)) {
            const QJsonArray list = it.value().toArray();
            if (!it.value().isArray() || list.isEmpty()) problems_ << at + QStringLiteral(": must be a non-empty list");
            for (qsizetype i = 0; i < list.size(); ++i) check(list[i], at + QStringLiteral("/%1").arg(i));
        } else if (k == QLatin1String("properties") || k == QLatin1String("$defs")) {
            const QJsonObject props = it.value().toObject();
            for (auto p = props.begin(); p != props.end(); ++p) check(p.value(), at + '/' + p.key());
        } else if (k == QLatin1String("$ref")) {
            if (resolve(it.value().toString()).isUndefined()) {
                problems_ << QStringLiteral("%1: \"%2\" does not resolve (only #/$defs/NAME is supported)")
                                 .arg(at, it.value().toString());
            }
        } else if (k == QLatin1String("type")) {
            const QJsonArray types = it.value().isArray() ? it.value().toArray() : QJsonArray{it.value()};
            for (const QJsonValue& t : types) {
                if (!kTypes.contains(t.toString())) problems_ << at + QStringLiteral(": unknown type ") + shown(t);
            }
        } else if (!kOther.contains(k)) {
            problems_ << QStringLiteral("%1: keyword outside the supported subset").arg(at);
        }
    }
}

QJsonValue JsonSchema::resolve(const QString& ref) const
{
    static const QString prefix = QStringLiteral("#/$defs/");
    if (!ref.startsWith(prefix)) return QJsonValue(QJsonValue::Undefined);
    const QJsonObject defs = root_.value(QStringLiteral("$defs")).toObject();
    const QString name = ref.mid(prefix.size());
    return defs.contains(name) ? defs.value(name) : QJsonValue(QJsonValue::Undefined);
}

QList<SchemaError> JsonSchema::validate(const QJsonValue& instance) const
{
    QList<SchemaError> errors;
    if (!problems_.isEmpty()) {
        for (const QString& p : problems_) errors << SchemaError{QString(), QStringLiteral("schema: ") + p};
        return errors;
    }
    validate(root_, instance, QString(), errors, 0);
    return errors;
}

void JsonSchema::validate(const QJsonValue& schema, const QJsonValue& v, const QString& path,
                          QList<SchemaError>& errors, int depth) const
{
    if (depth > 64) {
        errors << SchemaError{path, QStringLiteral("schema nests too deeply (a $ref cycle?)")};
        return;
    }
    if (schema.isBool()) {
        if (!schema.toBool()) errors << SchemaError{path, QStringLiteral("no value is allowed here")};
        return;
    }
    const QJsonObject s = schema.toObject();
    auto fail = [&](const QString& message) { errors << SchemaError{path, message}; };

    if (s.contains("$ref")) validate(resolve(s.value("$ref").toString()), v, path, errors, depth + 1);
    if (s.contains("type")) {
        const QJsonValue t = s.value("type");
        const QJsonArray types = t.isArray() ? t.toArray() : QJsonArray{t};
        bool any = false;
        QStringList names;
        for (const QJsonValue& x : types) {
            any = any || hasType(v, x.toString());
            names << x.toString();
        }
        if (!any) {
            fail(QStringLiteral("must be of type %1, got %2").arg(names.join(QStringLiteral(" or ")), shown(v)));
            return;   // the other keywords would only repeat it
        }
    }
    if (s.contains("const") && !jsonEqual(v, s.value("const"))) {
        fail(QStringLiteral("must be %1, got %2").arg(shown(s.value("const")), shown(v)));
    }
    if (s.contains("enum")) {
        bool found = false;
        for (const QJsonValue& e : s.value("enum").toArray()) found = found || jsonEqual(v, e);
        if (!found) fail(QStringLiteral("must be one of %1, got %2").arg(shown(s.value("enum")), shown(v)));
    }
    if (v.isDouble()) {
        const double x = v.toDouble();
        if (s.contains("minimum") && !(x >= s.value("minimum").toDouble())) {
            fail(QStringLiteral("must be >= %1, got %2").arg(num(s.value("minimum").toDouble()), num(x)));
        }
        if (s.contains("maximum") && !(x <= s.value("maximum").toDouble())) {
            fail(QStringLiteral("must be <= %1, got %2").arg(num(s.value("maximum").toDouble()), num(x)));
        }
        if (s.contains("exclusiveMinimum") && !(x > s.value("exclusiveMinimum").toDouble())) {
            fail(QStringLiteral("must be > %1, got %2").arg(num(s.value("exclusiveMinimum").toDouble()), num(x)));
        }
        if (s.contains("exclusiveMaximum") && !(x < s.value("exclusiveMaximum").toDouble())) {
            fail(QStringLiteral("must be < %1, got %2").arg(num(s.value("exclusiveMaximum").toDouble()), num(x)));
        }
    }
    if (v.isString() && s.contains("minLength")) {
        // JSON Schema counts code points, not UTF-16 units.
        const qsizetype length = v.toString().toUcs4().size();
        if (length < s.value("minLength").toInteger()) {
            fail(QStringLiteral("must have at least %1 characters").arg(s.value("minLength").toInteger()));
        }
    }
    if (v.isArray()) {
        const QJsonArray a = v.toArray();
        if (s.contains("minItems") && a.size() < s.value("minItems").toInteger()) {
            fail(QStringLiteral("must have at least %1 elements, got %2").arg(s.value("minItems").toInteger()).arg(a.size()));
        }
        if (s.contains("maxItems") && a.size() > s.value("maxItems").toInteger()) {
            fail(QStringLiteral("must have at most %1 elements, got %2").arg(s.value("maxItems").toInteger()).arg(a.size()));
        }
        if (s.value("uniqueItems").toBool()) {
            for (qsizetype i = 0; i < a.size(); ++i) {
                for (qsizetype j = 0; j < i; ++j) {
                    if (jsonEqual(a[i], a[j])) fail(QStringLiteral("elements %1 and %2 are equal").arg(j).arg(i));
                }
            }
        }
        if (s.contains("items")) {
            for (qsizetype i = 0; i < a.size(); ++i) {
                validate(s.value("items"), a[i], path + QStringLiteral("[%1]").arg(i), errors, depth + 1);
            }
        }
    }
    if (v.isObject()) {
        const QJsonObject o = v.toObject();
        const QJsonObject props = s.value("properties").toObject();
        for (const QJsonValue& r : s.value("required").toArray()) {
            if (!o.contains(r.toString())) {
                errors << SchemaError{key(path, r.toString()), QStringLiteral("required field is missing")};
            }
        }
        for (auto it = o.begin(); it != o.end(); ++it) {
            if (props.contains(it.key())) {
                validate(props.value(it.key()), it.value(), key(path, it.key()), errors, depth + 1);
            } else if (s.contains("additionalProperties")) {
                const QJsonValue extra = s.value("additionalProperties");
                if (extra.isBool() && !extra.toBool()) {
                    errors << SchemaError{key(path, it.key()), QStringLiteral("unknown key")};
                } else {
                    validate(extra, it.value(), key(path, it.key()), errors, depth + 1);
                }
            }
        }
    }
    auto passes = [&](const QJsonValue& sub) {
        QList<SchemaError> scratch;
        validate(sub, v, path, scratch, depth + 1);
        return scratch.isEmpty();
    };
    if (s.contains("allOf")) {
        for (const QJsonValue& sub : s.value("allOf").toArray()) validate(sub, v, path, errors, depth + 1);
    }
    if (s.contains("anyOf")) {
        bool any = false;
        for (const QJsonValue& sub : s.value("anyOf").toArray()) any = any || passes(sub);
        if (!any) fail(QStringLiteral("matches none of the %1 allowed forms (anyOf)").arg(s.value("anyOf").toArray().size()));
    }
    if (s.contains("oneOf")) {
        int matching = 0;
        for (const QJsonValue& sub : s.value("oneOf").toArray()) matching += passes(sub) ? 1 : 0;
        if (matching != 1) {
            fail(QStringLiteral("must match exactly one of the %1 allowed forms (oneOf), matches %2")
                     .arg(s.value("oneOf").toArray().size())
                     .arg(matching));
        }
    }
    if (s.contains("not") && passes(s.value("not"))) fail(QStringLiteral("matches a form that is not allowed (not)"));
    if (s.contains("if")) {
        const bool condition = passes(s.value("if"));
        if (condition && s.contains("then")) validate(s.value("then"), v, path, errors, depth + 1);
        if (!condition && s.contains("else")) validate(s.value("else"), v, path, errors, depth + 1);
    }
}

} // namespace rbw::test
