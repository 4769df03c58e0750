#include "app/exercise/answers_file.h"

#include "app/exercise/answers_input.h"
#include "physics/engine/quantity_catalogue.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>

#include <cmath>

namespace rbw {

namespace {

const QString kDecimalPoint = QStringLiteral(" (decimal commas? use a decimal point: 3.11, not 3,11)");

// [3,11, 1,07, -2,68]: twice 1, 3 or 4 numbers, every second one a whole number >= 0
// (the digits after a decimal comma).
bool looksLikeDecimalCommas(const QJsonArray& a)
{
    if (a.size() != 2 && a.size() != 6 && a.size() != 8) return false;
    for (int i = 1; i < a.size(); i += 2) {
        const double d = a[i].toDouble(-1.0);
        if (!a[i].isDouble() || d < 0 || d != std::floor(d)) return false;
    }
    return true;
}

// Numbers of a value: 1, 3, 4 or 9 (three rows of three); empty with a reason otherwise.
std::vector<double> valueOf(const QJsonValue& v, QString& reason)
{
    std::vector<double> out;
    auto number = [&](const QJsonValue& x) {
        if (!x.isDouble() || !std::isfinite(x.toDouble())) {
            reason = QStringLiteral("every component must be a finite number");
            return false;
        }
        out.push_back(x.toDouble());
        return true;
    };
    if (v.isDouble()) {
        if (!number(v)) return {};
        return out;
    }
    if (!v.isArray()) {
        reason = QStringLiteral("must be a number, a vector, a quaternion [w, x, y, z] or three rows of a matrix");
        static const QRegularExpression decimalComma(QStringLiteral("\\d,\\d"));
        if (v.isString() && v.toString().contains(decimalComma)) reason += kDecimalPoint;
        return {};
    }
    const QJsonArray a = v.toArray();
    if (!a.isEmpty() && a.first().isArray()) {
        if (a.size() != 3) {
            reason = QStringLiteral("a matrix must have 3 rows, got %1").arg(a.size());
            return {};
        }
        for (const QJsonValue& row : a) {
            if (!row.isArray() || row.toArray().size() != 3) {
                reason = QStringLiteral("every row of a matrix must have 3 numbers");
                if (row.isArray() && looksLikeDecimalCommas(row.toArray())) reason += kDecimalPoint;
                return {};
            }
            for (const QJsonValue& x : row.toArray()) {
                if (!number(x)) return {};
            }
        }
        return out;
    }
    if (a.size() != 3 && a.size() != 4) {
        reason = QStringLiteral("a vector has 3 numbers and a quaternion 4, got %1").arg(a.size());
        if (looksLikeDecimalCommas(a)) reason += kDecimalPoint;
        return {};
    }
    for (const QJsonValue& x : a) {
        if (!number(x)) return {};
    }
    return out;
}

} // namespace

AnswersFile parseAnswers(const QByteArray& json, const QString& fileLabel, const SceneDef& scene)
{
    AnswersFile f;
    auto error = [&](const QString& path, const QString& reason) {
        f.errors << (path.isEmpty() ? QStringLiteral("%1: %2").arg(fileLabel, reason)
                                    : QStringLiteral("%1: %2: %3").arg(fileLabel, path, reason));
    };
    QJsonParseError pe;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &pe);
    if (pe.error != QJsonParseError::NoError) {
        error(QString(), QStringLiteral("malformed JSON at offset %1: %2").arg(pe.offset).arg(pe.errorString()));
        return f;
    }
    if (!doc.isObject()) {
        error(QString(), QStringLiteral("the top level must be a JSON object with \"answers\""));
        return f;
    }
    const QJsonObject top = doc.object();
    for (auto it = top.begin(); it != top.end(); ++it) {
        if (it.key() != QLatin1String("step") && it.key() != QLatin1String("answers")) {
            error(shownText(it.key()), QStringLiteral("unknown key (the keys are \"step\" and \"answers\")"));
        }
    }
    if (top.contains(QStringLiteral("step"))) {
        const QJsonValue s = top.value(QStringLiteral("step"));
        const double d = s.toDouble(-1.0);
        if (!s.isDouble() || d < 0 || d != std::floor(d) || d > 1e9) {
            error(QStringLiteral("step"), QStringLiteral("must be a whole number from 0 to 10^9"));
        } else {
            f.step = static_cast<long>(d);
        }
    }
    if (!top.value(QStringLiteral("answers")).isArray()) {
        error(QStringLiteral("answers"), QStringLiteral("required: a list of answers"));
        return f;
    }
    const QJsonArray answers = top.value(QStringLiteral("answers")).toArray();
    for (int i = 0; i < answers.size(); ++i) {
        const QString at = QStringLiteral("answers[%1]").arg(i);
        if (!answers[i].isObject()) {
            error(at, QStringLiteral("must be an object with \"quantity\" and \"value\""));
            continue;
        }
        const QJsonObject o = answers[i].toObject();
        for (auto it = o.begin(); it != o.end(); ++it) {
            static const QStringList keys = {QStringLiteral("quantity"), QStringLiteral("body"),
                                             QStringLiteral("contact"), QStringLiteral("index"), QStringLiteral("value")};
            if (!keys.contains(it.key())) {
                error(at + QLatin1Char('.') + shownText(it.key()), QStringLiteral("unknown key (known: %1)").arg(keys.join(", ")));
            }
        }
        Answer a;
        if (!o.value(QStringLiteral("quantity")).isString()) {
            error(at + QStringLiteral(".quantity"), QStringLiteral("required: a quantity id (rbw quantities lists them)"));
            continue;
        }
        a.quantity = o.value(QStringLiteral("quantity")).toString().toStdString();
        if (!isQuantityId(a.quantity)) {
            error(at + QStringLiteral(".quantity"),
                  QStringLiteral("unknown quantity \"%1\" (rbw quantities lists them)")
                      .arg(shownText(o.value(QStringLiteral("quantity")).toString())));
            continue;
        }
        if (o.contains(QStringLiteral("body"))) {
            const QString name = o.value(QStringLiteral("body")).toString();
            a.body = scene.bodyIndex(name.toStdString());
            if (a.body < 0) {
                QStringList names;
                for (const BodyDef& b : scene.bodies) names << QString::fromStdString(b.name);
                error(at + QStringLiteral(".body"),
                      QStringLiteral("no body named \"%1\" (bodies: %2)").arg(shownText(name), shownText(names.join(", "), 400)));
                continue;
            }
        }
        auto wholeNumber = [&](const char* key, int& into) {
            if (!o.contains(QLatin1String(key))) return true;
            const QJsonValue v = o.value(QLatin1String(key));
            const double d = v.toDouble(-1.0);
            if (!v.isDouble() || d < 0 || d != std::floor(d) || d > 1e9) {
                error(at + QLatin1Char('.') + QLatin1String(key), QStringLiteral("must be a whole number >= 0"));
                return false;
            }
            into = static_cast<int>(d);
            return true;
        };
        if (!wholeNumber("contact", a.contact) || !wholeNumber("index", a.index)) continue;
        if (a.body < 0 && a.contact < 0) {
            if (scene.bodies.size() == 1) {
                a.body = 0;   // one body: it needs no name
            } else {
                error(at, QStringLiteral("needs \"body\" (a body's name) or \"contact\" (a contact's number)"));
                continue;
            }
        }
        if (!o.contains(QStringLiteral("value"))) {
            error(at + QStringLiteral(".value"), QStringLiteral("required field is missing"));
            continue;
        }
        QString reason;
        a.value = valueOf(o.value(QStringLiteral("value")), reason);
        if (a.value.empty()) {
            error(at + QStringLiteral(".value"), reason);
            continue;
        }
        f.answers.push_back(a);
        f.paths.push_back(at);
    }
    return f;
}

AnswersFile loadAnswersFile(const QString& filePath, const SceneDef& scene)
{
    QByteArray bytes;
    QString error;
    if (!readInputFile(filePath, &bytes, &error)) {
        AnswersFile f;
        f.errors << error;
        return f;
    }
    return parseAnswers(bytes, filePath, scene);
}

QByteArray answersToJson(const std::vector<Answer>& answers, long step, const SceneDef& scene)
{
    QJsonArray list;
    for (const Answer& a : answers) {
        QJsonObject o{{"quantity", QString::fromStdString(a.quantity)}};
        if (a.contact >= 0) o.insert("contact", a.contact);
        else if (a.body >= 0) o.insert("body", QString::fromStdString(scene.bodies[a.body].name));
        if (a.index >= 0) o.insert("index", a.index);
        if (a.value.size() == 1) {
            o.insert("value", a.value[0]);
        } else if (a.value.size() == 9) {
            QJsonArray rows;
            for (int i = 0; i < 3; ++i) rows.append(QJsonArray{a.value[3 * i], a.value[3 * i + 1], a.value[3 * i + 2]});
            o.insert("value", rows);
        } else {
            QJsonArray v;
            for (double x : a.value) v.append(x);
            o.insert("value", v);
        }
        list.append(o);
    }
    return QJsonDocument(QJsonObject{{"step", static_cast<qint64>(step)}, {"answers", list}}).toJson();
}

} // namespace rbw
