#include "app/exercise/scene_text.h"

#include "app/scene/scene_format.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QStringList>

namespace rbw {

namespace {

void writeJson(const QJsonValue& v, int indent, QByteArray& out)
{
    const QByteArray pad(indent * 2, ' ');
    const QByteArray inner((indent + 1) * 2, ' ');
    auto scalar = [](const QJsonValue& x) {
        QByteArray text = QJsonDocument(QJsonArray{x}).toJson(QJsonDocument::Compact);
        return text.mid(1, text.size() - 2);   // strip "[" and "]"
    };
    if (v.isObject()) {
        const QJsonObject o = v.toObject();
        QStringList keys;
        // The name first, then the description (of the scene; a body's or plane's name
        // is the same key), as the lessons' files have them.
        for (const QString& first : {sceneformat::key(sceneformat::Key::Name), sceneformat::key(sceneformat::Key::Description)}) {
            if (o.contains(first)) keys << first;
        }
        for (const QString& k : o.keys()) {
            if (!keys.contains(k)) keys << k;
        }
        out += "{\n";
        for (qsizetype i = 0; i < keys.size(); ++i) {
            out += inner + scalar(keys[i]) + ": ";
            writeJson(o.value(keys[i]), indent + 1, out);
            out += i + 1 < keys.size() ? ",\n" : "\n";
        }
        out += pad + "}";
    } else if (v.isArray()) {
        const QJsonArray a = v.toArray();
        bool flat = true;
        for (const QJsonValue& x : a) flat = flat && !x.isObject() && !x.isArray();
        if (flat) {
            out += "[";
            for (qsizetype i = 0; i < a.size(); ++i) out += (i > 0 ? ", " : "") + scalar(a[i]);
            out += "]";
            return;
        }
        out += "[\n";
        for (qsizetype i = 0; i < a.size(); ++i) {
            out += inner;
            writeJson(a[i], indent + 1, out);
            out += i + 1 < a.size() ? ",\n" : "\n";
        }
        out += pad + "]";
    } else {
        out += scalar(v);
    }
}

} // namespace

QByteArray indentedSceneJson(const QJsonObject& scene)
{
    QByteArray bytes;
    writeJson(scene, 0, bytes);
    bytes += '\n';
    return bytes;
}

} // namespace rbw
