// A small JSON Schema validator for the subset of draft 2020-12 that
// docs/scene.schema.json uses. There is no JSON Schema package on the build machines,
// so the tests bring their own; it refuses a schema that uses any other keyword, so
// the schema cannot drift out of what is checked here.
//
// Keywords: type (a name or a list; "integer" is a number without a fraction, as
// 2.0), enum, const, properties, required, additionalProperties (true, false or a
// schema), items (one schema for every element), minItems, maxItems, uniqueItems,
// minimum, maximum, exclusiveMinimum, exclusiveMaximum (numbers), minLength, anyOf,
// oneOf, allOf, not, if / then / else, and $ref to "#/$defs/NAME". Annotations
// ($schema, $id, $comment, title, description, default, examples) are ignored.
// Equality (const, enum, uniqueItems) is JSON's: numbers by value, so 0 == 0.0.
//
// Paths are written as the scene loader writes them: "bodies[0].mass"; a missing
// required key and an unknown key are reported at the key's own path.
#pragma once

#include <QJsonObject>
#include <QJsonValue>
#include <QList>
#include <QString>
#include <QStringList>

namespace rbw::test {

struct SchemaError {
    QString path;
    QString message;
    QString text() const { return path.isEmpty() ? message : path + QStringLiteral(": ") + message; }
};

class JsonSchema {
public:
    // The schema document's root object. problems() lists every keyword outside the
    // subset and every $ref that does not resolve; a schema with problems validates
    // nothing (every instance fails with them).
    explicit JsonSchema(QJsonObject root);

    const QStringList& problems() const { return problems_; }
    QList<SchemaError> validate(const QJsonValue& instance) const;
    bool accepts(const QJsonValue& instance) const { return validate(instance).isEmpty(); }

private:
    void check(const QJsonValue& schema, const QString& where);
    void validate(const QJsonValue& schema, const QJsonValue& instance, const QString& path,
                  QList<SchemaError>& errors, int depth) const;
    QJsonValue resolve(const QString& ref) const;

    QJsonObject root_;
    QStringList problems_;
};

// JSON equality: numbers by value, arrays element by element, objects key by key.
bool jsonEqual(const QJsonValue& a, const QJsonValue& b);

} // namespace rbw::test
