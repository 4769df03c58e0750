#include "app/output/json_text.h"

#include <QJsonArray>
#include <QJsonDocument>

namespace rbw::jsontext {

namespace {

QByteArray key(const QString& k) { return scalar(QJsonValue(k)); }

// The lessons' layout of one value at `indent` levels of two spaces.
void appendSceneStyle(QByteArray& out, const QJsonValue& v, int indent, const QStringList& firstKeys)
{
    const QByteArray pad(indent * 2, ' ');
    const QByteArray inner((indent + 1) * 2, ' ');
    if (v.isObject()) {
        const QJsonObject o = v.toObject();
        QStringList keys;
        for (const QString& first : firstKeys) {
            if (o.contains(first)) keys << first;
        }
        for (const QString& k : o.keys()) {
            if (!keys.contains(k)) keys << k;
        }
        out += "{\n";
        for (qsizetype i = 0; i < keys.size(); ++i) {
            out += inner + key(keys[i]) + ": ";
            appendSceneStyle(out, o.value(keys[i]), indent + 1, firstKeys);
            out += i + 1 < keys.size() ? ",\n" : "\n";
        }
        out += pad + "}";
    } else if (v.isArray()) {
        const QJsonArray a = v.toArray();
        bool flat = true;
        for (const QJsonValue& x : a) flat = flat && !x.isObject() && !x.isArray();
        if (flat) {
            out += oneLine(a);
            return;
        }
        out += "[\n";
        for (qsizetype i = 0; i < a.size(); ++i) {
            out += inner;
            appendSceneStyle(out, a[i], indent + 1, firstKeys);
            out += i + 1 < a.size() ? ",\n" : "\n";
        }
        out += pad + "]";
    } else {
        out += scalar(v);
    }
}

} // namespace

QByteArray scalar(const QJsonValue& v)
{
    // QJsonDocument holds only an array or an object: the value inside a one-element
    // array, "[" and "]" left out.
    const QByteArray wrapped = QJsonDocument(QJsonArray{v}).toJson(QJsonDocument::Compact);
    return wrapped.mid(1, wrapped.size() - 2);
}

QByteArray oneLine(const QJsonValue& v)
{
    if (v.isArray()) {
        QByteArrayList parts;
        for (const QJsonValue& e : v.toArray()) parts << oneLine(e);
        return '[' + parts.join(", ") + ']';
    }
    if (v.isObject()) {
        const QJsonObject o = v.toObject();
        QByteArrayList parts;
        for (auto it = o.begin(); it != o.end(); ++it) parts << key(it.key()) + ": " + oneLine(it.value());
        return "{ " + parts.join(", ") + " }";
    }
    return scalar(v);
}

// QJsonDocument::Indented (Qt's qjsonwriter.cpp): "[" or "{" and a newline, each
// element on its own line one level in, ",\n" between them, a newline after the last,
// the closing bracket at the value's own level; an empty one is "[\n" + its indentation + "]".
void appendIndented(QByteArray& out, const QJsonValue& v, int depth)
{
    const QByteArray inner(4 * (depth + 1), ' ');
    if (v.isArray()) {
        const QJsonArray a = v.toArray();
        out += "[\n";
        for (qsizetype i = 0; i < a.size(); ++i) {
            out += inner;
            appendIndented(out, a[i], depth + 1);
            out += i + 1 < a.size() ? ",\n" : "\n";
        }
        out += QByteArray(4 * depth, ' ') + ']';
    } else if (v.isObject()) {
        out += "{\n";
        const QByteArray members = indentedMembers(v.toObject(), depth + 1);
        if (!members.isEmpty()) out += members + '\n';
        out += QByteArray(4 * depth, ' ') + '}';
    } else {
        out += scalar(v);
    }
}

QByteArray indentedMembers(const QJsonObject& o, int depth)
{
    const QByteArray pad(4 * depth, ' ');
    QByteArray out;
    for (auto it = o.begin(); it != o.end(); ++it) {
        if (it != o.begin()) out += ",\n";
        out += pad + key(it.key()) + ": ";
        appendIndented(out, it.value(), depth);
    }
    return out;
}

QByteArray sceneFileText(const QJsonObject& o, const QStringList& firstKeys)
{
    QByteArray bytes;
    appendSceneStyle(bytes, o, 0, firstKeys);
    bytes += '\n';
    return bytes;
}

} // namespace rbw::jsontext
