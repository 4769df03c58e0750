#include "app/exercise/scene_path.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QRegularExpression>

#include <limits>

namespace rbw {

namespace {

std::optional<QJsonValue> getAt(const QJsonValue& v, const std::vector<ScenePathToken>& t, size_t i)
{
    if (i == t.size()) return v;
    if (!t[i].key.isEmpty()) {
        if (!v.isObject() || !v.toObject().contains(t[i].key)) return std::nullopt;
        return getAt(v.toObject().value(t[i].key), t, i + 1);
    }
    if (!v.isArray() || t[i].index >= v.toArray().size()) return std::nullopt;
    return getAt(v.toArray().at(t[i].index), t, i + 1);
}

QJsonValue setAt(const QJsonValue& v, const std::vector<ScenePathToken>& t, const QJsonValue& value, size_t i)
{
    if (i == t.size()) return value;
    if (!t[i].key.isEmpty()) {
        QJsonObject o = v.toObject();
        o.insert(t[i].key, setAt(o.value(t[i].key), t, value, i + 1));
        return o;
    }
    QJsonArray a = v.toArray();
    a.replace(t[i].index, setAt(a.at(t[i].index), t, value, i + 1));
    return a;
}

} // namespace

std::optional<std::vector<ScenePathToken>> parseScenePath(const QString& path)
{
    static const QRegularExpression token(QStringLiteral(R"(^([A-Za-z_][A-Za-z0-9_]*)((?:\[\d+\])*)$)"));
    static const QRegularExpression index(QStringLiteral(R"(\[(\d+)\])"));
    std::vector<ScenePathToken> tokens;
    if (path.isEmpty()) return std::nullopt;
    for (const QString& part : path.split('.')) {
        const QRegularExpressionMatch m = token.match(part);
        if (!m.hasMatch()) return std::nullopt;
        tokens.push_back(ScenePathToken{m.captured(1), -1});
        auto it = index.globalMatch(m.captured(2));
        while (it.hasNext()) {
            // "[4294967296]" must not wrap to 0 (toInt's answer on overflow): an index
            // that does not fit is beyond every array, so the path is not in the scene.
            bool fits = false;
            const qint64 k = it.next().captured(1).toLongLong(&fits);
            tokens.push_back(ScenePathToken{QString(), fits ? k : std::numeric_limits<qint64>::max()});
        }
    }
    return tokens;
}

std::optional<QJsonValue> sceneValueAt(const QJsonValue& document, const std::vector<ScenePathToken>& path)
{
    return getAt(document, path, 0);
}

QJsonValue withSceneValue(const QJsonValue& document, const std::vector<ScenePathToken>& path, const QJsonValue& value)
{
    return setAt(document, path, value, 0);
}

} // namespace rbw
