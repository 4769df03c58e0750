// The scene-format table (app/scene/scene_format.h) is the one statement of the scene
// format:
//   - docs/scene.schema.json declares exactly the table's keys in each object, with the
//     same JSON types, required keys, allowed words and defaults (schemaIsTheTable); a
//     schema changed in one place (a key, a word, a type, a required key, a default)
//     is caught (tamperedSchemaDiffers, the negative controls);
//   - a key the table gives a default means that default to the loader: a scene with
//     the key left out and one with the default written load the same, field by field
//     (leftOutIsTheDefault, with other values as its negative controls);
//   - the table itself is consistent: keys unique within an object, words unique,
//     each word read back as its enumeration value.
// That no other file spells a key is tst_scene_keys'; that docs/scene-format.md lists
// the table's keys, tst_scene_format_doc's.
#include "app/scene/scene_format.h"
#include "app/scene/scene_loader.h"
#include "app/scene/scene_writer.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>
#include <QtTest>

#include <functional>

using namespace rbw;
using namespace rbw::sceneformat;

namespace {

const QString kSource = QStringLiteral(RBW_SOURCE_DIR);

QByteArray readFile(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) qFatal("cannot read %s", qPrintable(path));
    return f.readAll();
}

QJsonObject realSchema()
{
    return QJsonDocument::fromJson(readFile(kSource + QStringLiteral("/docs/scene.schema.json"))).object();
}

// A definition's body with its "$ref" chain merged in (the referring object's own
// keywords win): {"$ref": "#/$defs/step", "minimum": 1} -> {"type": "integer", ...}.
QJsonObject resolved(const QJsonObject& schema, QJsonObject o)
{
    for (int depth = 0; o.contains("$ref") && depth < 10; ++depth) {
        const QString ref = o.take("$ref").toString();
        const QJsonObject target = schema.value("$defs").toObject().value(ref.section('/', -1)).toObject();
        for (auto it = target.begin(); it != target.end(); ++it) {
            if (!o.contains(it.key())) o.insert(it.key(), it.value());
        }
    }
    return o;
}

// The schema object that holds a section's keys; for an orientation, its forms merged.
QJsonObject sectionObject(const QJsonObject& schema, Section s)
{
    const QJsonObject defs = schema.value("$defs").toObject();
    switch (s) {
    case Section::Scene: return schema;
    case Section::EnergyJump: return schema.value("properties").toObject().value(key(Key::EnergyJump)).toObject();
    case Section::Body: return defs.value("body").toObject();
    case Section::Force: return defs.value("force").toObject();
    case Section::Torque: return defs.value("torque").toObject();
    case Section::Push: return defs.value("push").toObject();
    case Section::Probe: return defs.value("probe").toObject();
    case Section::Plane: return defs.value("plane").toObject();
    case Section::Pair: return defs.value("pair").toObject();
    case Section::Orientation: {
        QJsonObject properties;
        for (const QJsonValue& form : defs.value("orientation").toObject().value("oneOf").toArray()) {
            const QJsonObject p = form.toObject().value("properties").toObject();
            for (auto it = p.begin(); it != p.end(); ++it) properties.insert(it.key(), it.value());
        }
        return QJsonObject{{"properties", properties}};
    }
    }
    return {};
}

const QList<Section> kSections{Section::Scene, Section::EnergyJump, Section::Body, Section::Orientation,
                               Section::Force, Section::Torque, Section::Push, Section::Probe,
                               Section::Plane, Section::Pair};

QString sectionName(Section s)
{
    static const QStringList names{"top level", "energy_jump", "body", "orientation", "force",
                                   "torque", "push", "probe", "plane", "pair"};
    return names.value(static_cast<int>(s));
}

// Whether a (resolved) schema property has the table's type.
bool typeMatches(const QJsonObject& schema, const QJsonObject& p, const KeyRow& r)
{
    const QString type = p.value("type").toString();
    const QJsonObject items = resolved(schema, p.value("items").toObject());
    auto arrayOf = [&](const QString& itemType, int n) {
        return type == "array" && items.value("type").toString() == itemType && p.value("minItems").toInt() == n &&
               p.value("maxItems").toInt() == n;
    };
    switch (r.type) {
    case Type::Number: return type == "number";
    case Type::Integer: return type == "integer";
    case Type::String:
    case Type::BodyRef: return type == "string";
    case Type::Boolean: return type == "boolean";
    case Type::Vector: return arrayOf("number", 3);
    case Type::Quaternion: return arrayOf("number", 4);
    case Type::Word: return p.contains("enum") && (type.isEmpty() || type == "string");
    case Type::NamePair: return arrayOf("string", 2);
    case Type::Object: return type == "object";
    case Type::List: return type == "array" && items.value("type").toString() == "object";
    }
    return false;
}

// Every way the schema and the table differ, one line each ("body.mass: ...").
QStringList differences(const QJsonObject& schema)
{
    QStringList out;
    for (Section s : kSections) {
        const QJsonObject object = resolved(schema, sectionObject(schema, s));
        const QJsonObject properties = object.value("properties").toObject();
        const QStringList tableKeys = keysOf(s);
        const QString where = sectionName(s);
        for (const QString& k : properties.keys()) {
            if (!tableKeys.contains(k)) out << QStringLiteral("%1.%2: in the schema, not in the table").arg(where, k);
        }
        QSet<QString> required;
        for (const QJsonValue& v : object.value("required").toArray()) required.insert(v.toString());
        for (const QString& k : tableKeys) {
            const KeyRow& r = *find(s, k);
            if (!properties.contains(k)) {
                out << QStringLiteral("%1.%2: in the table, not in the schema").arg(where, k);
                continue;
            }
            const QJsonObject p = resolved(schema, properties.value(k).toObject());
            if (!typeMatches(schema, p, r)) out << QStringLiteral("%1.%2: the types differ").arg(where, k);
            if (s != Section::Orientation && required.contains(k) != r.required) {
                out << QStringLiteral("%1.%2: required in one, not in the other").arg(where, k);
            }
            if (r.type == Type::Word) {
                QStringList schemaWords;
                for (const QJsonValue& v : p.value("enum").toArray()) schemaWords << v.toString();
                if (schemaWords != words(r.choices)) {
                    out << QStringLiteral("%1.%2: words {%3} in the schema, {%4} in the table")
                               .arg(where, k, schemaWords.join(", "), words(r.choices).join(", "));
                }
            }
            if (p.contains("default")) {
                const QJsonValue tableDefault =
                    QJsonDocument::fromJson(QByteArray("[") + r.fallback + "]").array().at(0);
                if (tableDefault != p.value("default")) {
                    out << QStringLiteral("%1.%2: default %3 in the schema, \"%4\" in the table")
                               .arg(where, k, QString::fromUtf8(QJsonDocument(QJsonArray{p.value("default")}).toJson(QJsonDocument::Compact)),
                                    QString::fromLatin1(r.fallback));
                }
            }
        }
    }
    return out;
}

// The smallest valid scene with one object of each kind, each with only its required
// keys (a pair needs one coefficient): the base each default is tried against.
QJsonObject minimalScene()
{
    return QJsonDocument::fromJson(R"({
        "dt": 0.01,
        "bodies": [ { "name": "a", "size": [1, 1, 1], "mass": 1 },
                    { "name": "b", "size": [1, 1, 1], "mass": 1, "position": [5, 0, 0] } ],
        "forces": [ { "body": "a", "point": [0, 0, 0], "force": [1, 0, 0] } ],
        "torques": [ { "body": "a", "torque": [0, 0, 1] } ],
        "push": { "body": "a" },
        "probes": [ { "body": "a", "point": [0, 0, 0] } ],
        "planes": [ { "name": "ground", "point": [0, -2, 0], "normal": [0, 1, 0] } ],
        "pairs": [ { "bodies": ["a", "b"], "friction": 0.5 } ],
        "energy_jump": {}
    })").object();
}

// The scene with key k of section s (in the first object of its kind) set to v, or
// left out when v is undefined.
QJsonObject withKey(QJsonObject scene, Section s, const QString& k, const QJsonValue& v)
{
    auto set = [&](QJsonObject o) {
        if (v.isUndefined()) o.remove(k);
        else o.insert(k, v);
        return o;
    };
    auto inObject = [&](Key holder) { scene.insert(key(holder), set(scene.value(key(holder)).toObject())); };
    auto inFirst = [&](Key list) {
        QJsonArray a = scene.value(key(list)).toArray();
        a[0] = set(a[0].toObject());
        scene.insert(key(list), a);
    };
    switch (s) {
    case Section::Scene: return set(scene);
    case Section::EnergyJump: inObject(Key::EnergyJump); break;
    case Section::Push: inObject(Key::Push); break;
    case Section::Body: inFirst(Key::Bodies); break;
    case Section::Force: inFirst(Key::Forces); break;
    case Section::Torque: inFirst(Key::Torques); break;
    case Section::Probe: inFirst(Key::Probes); break;
    case Section::Plane: inFirst(Key::Planes); break;
    case Section::Pair: inFirst(Key::Pairs); break;
    case Section::Orientation: break;   // no key of an orientation has a default
    }
    return scene;
}

} // namespace

class TestSceneFormat : public QObject {
    Q_OBJECT
private slots:
    void tableIsConsistent();
    void schemaIsTheTable();
    void tamperedSchemaDiffers_data();
    void tamperedSchemaDiffers();
    void leftOutIsTheDefault_data();
    void leftOutIsTheDefault();
};

void TestSceneFormat::tableIsConsistent()
{
    for (Section s : kSections) {
        const QStringList keys = keysOf(s);
        QVERIFY2(!keys.isEmpty(), qPrintable(sectionName(s)));
        QCOMPARE(QSet<QString>(keys.begin(), keys.end()).size(), keys.size());
    }
    for (const KeyRow& r : rows()) {
        QVERIFY2(*r.meaning, r.name);
        QCOMPARE(find(r.section, QString::fromLatin1(r.name)), &r);
        QCOMPARE(words(r.choices).isEmpty(), r.choices == Choices::None);
        // An object or a list names the object its keys (its elements' keys) belong to.
        const bool nested = r.type == Type::Object || r.type == Type::List;
        QVERIFY2(nested == (r.object != Section::Scene), r.name);
        // A default is JSON the key's type can hold (or none).
        if (*r.fallback) {
            QJsonParseError error;
            QJsonDocument::fromJson(QByteArray("[") + r.fallback + "]", &error);
            QVERIFY2(error.error == QJsonParseError::NoError, r.name);
        }
    }
    // Each word reads back as the value it was written from (the enumerations' order).
    QCOMPARE(fromWord<InertiaConvention>(word(InertiaConvention::CourseTemplate)), InertiaConvention::CourseTemplate);
    QCOMPARE(fromWord<PlaneContactMode>(word(PlaneContactMode::Average)), PlaneContactMode::Average);
    QCOMPARE(fromWord<ContactModel>(word(ContactModel::Manifold)), ContactModel::Manifold);
    QCOMPARE(fromWord<PositionFix>(word(PositionFix::None)), PositionFix::None);
    QCOMPARE(fromWord<PositionFix>(word(PositionFix::Ngs)), PositionFix::Ngs);
    QCOMPARE(fromWord<ManifoldSolver>(word(ManifoldSolver::SoftStep)), ManifoldSolver::SoftStep);
    QCOMPARE(fromWord<ManifoldSolver>(word(ManifoldSolver::SequentialImpulses)), ManifoldSolver::SequentialImpulses);
    QVERIFY(!fromWord<ContactModel>(QStringLiteral("Course")).has_value());
    QCOMPARE(choiceText({"a", "b"}), QStringLiteral("\"a\" or \"b\""));
    QCOMPARE(choiceText({"a", "b", "c"}, "(default)"), QStringLiteral("\"a\", \"b\", \"c\" or (default)"));
}

void TestSceneFormat::schemaIsTheTable()
{
    const QStringList diff = differences(realSchema());
    QVERIFY2(diff.isEmpty(), qPrintable(diff.join('\n')));
}

// Negative controls: each edit of the real schema must show as a difference naming its key.
void TestSceneFormat::tamperedSchemaDiffers_data()
{
    using Edit = std::function<void(QJsonObject&)>;
    QTest::addColumn<Edit>("edit");
    QTest::addColumn<QString>("expected");
    auto def = [](QJsonObject& schema, const QString& name, const std::function<void(QJsonObject&)>& f) {
        QJsonObject defs = schema.value("$defs").toObject();
        QJsonObject d = defs.value(name).toObject();
        f(d);
        defs.insert(name, d);
        schema.insert("$defs", defs);
    };
    auto prop = [](QJsonObject& o, const QString& k, const std::function<void(QJsonObject&)>& f) {
        QJsonObject props = o.value("properties").toObject();
        QJsonObject p = props.value(k).toObject();
        f(p);
        props.insert(k, p);
        o.insert("properties", props);
    };
    QTest::newRow("body key missing") << Edit([=](QJsonObject& s) {
        def(s, "body", [](QJsonObject& d) {
            QJsonObject p = d.value("properties").toObject();
            p.remove("angular_response");
            d.insert("properties", p);
        });
    }) << "body.angular_response: in the table, not in the schema";
    QTest::newRow("extra top-level key") << Edit([=](QJsonObject& s) {
        prop(s, "relax_passes", [](QJsonObject& p) { p.insert("type", "integer"); });
    }) << "top level.relax_passes: in the schema, not in the table";
    QTest::newRow("extra word") << Edit([=](QJsonObject& s) {
        prop(s, "contact_model", [](QJsonObject& p) { p.insert("enum", QJsonArray{"course", "manifold", "soft"}); });
    }) << "top level.contact_model: words {course, manifold, soft} in the schema, {course, manifold} in the table";
    QTest::newRow("type changed") << Edit([=](QJsonObject& s) {
        def(s, "torque", [=](QJsonObject& d) { prop(d, "switchable", [](QJsonObject& p) { p.insert("type", "number"); }); });
    }) << "torque.switchable: the types differ";
    QTest::newRow("required dropped") << Edit([=](QJsonObject& s) {
        def(s, "probe", [](QJsonObject& d) { d.insert("required", QJsonArray{"body"}); });
    }) << "probe.point: required in one, not in the other";
    QTest::newRow("default changed") << Edit([=](QJsonObject& s) {
        prop(s, "steps", [](QJsonObject& p) { p.insert("default", 2); });
    }) << "top level.steps: default [2] in the schema, \"1\" in the table";
}

void TestSceneFormat::tamperedSchemaDiffers()
{
    using Edit = std::function<void(QJsonObject&)>;
    QFETCH(Edit, edit);
    QFETCH(QString, expected);
    QJsonObject schema = realSchema();
    edit(schema);
    QCOMPARE(differences(schema), QStringList{expected});
}

// Each default of the table is the loader's: leaving the key out and writing the
// table's default load the same scene. Negative controls: other values differ, in the
// key's own field (so sceneDifferences sees the fields the defaults are about).
void TestSceneFormat::leftOutIsTheDefault_data()
{
    QTest::addColumn<Section>("section");
    QTest::addColumn<QString>("name");
    QTest::addColumn<QJsonValue>("value");
    QTest::addColumn<bool>("same");
    int defaults = 0;
    for (const KeyRow& r : rows()) {
        if (!*r.fallback) continue;
        QVERIFY2(r.section != Section::Orientation, r.name);
        const QJsonValue fallback = QJsonDocument::fromJson(QByteArray("[") + r.fallback + "]").array().at(0);
        QTest::addRow("%s.%s", qPrintable(sectionName(r.section)), r.name) << r.section << key(r.id) << fallback << true;
        ++defaults;
    }
    QVERIFY(defaults >= 25);   // the table was read
    QTest::newRow("control: steps 2") << Section::Scene << key(Key::Steps) << QJsonValue(2) << false;
    QTest::newRow("control: another integrator") << Section::Scene << key(Key::Integrator)
                                                 << QJsonValue(words(Choices::Integrator).last()) << false;
    QTest::newRow("control: manifold") << Section::Scene << key(Key::ContactModel)
                                       << QJsonValue(word(ContactModel::Manifold)) << false;
    QTest::newRow("control: gravity") << Section::Scene << key(Key::Gravity) << QJsonValue(QJsonArray{0, -9.81, 0}) << false;
    QTest::newRow("control: energy_jump.factor 20") << Section::EnergyJump << key(Key::EnergyJumpFactor) << QJsonValue(20) << false;
    QTest::newRow("control: a particle") << Section::Body << key(Key::BodyAngularResponse) << QJsonValue(false) << false;
    QTest::newRow("control: torque off") << Section::Torque << key(Key::TorqueEnabled) << QJsonValue(false) << false;
    QTest::newRow("control: push force 2") << Section::Push << key(Key::PushForce) << QJsonValue(2) << false;
}

void TestSceneFormat::leftOutIsTheDefault()
{
    QFETCH(Section, section);
    QFETCH(QString, name);
    QFETCH(QJsonValue, value);
    QFETCH(bool, same);
    auto load = [](const QJsonObject& o) { return parseScene(QJsonDocument(o).toJson(), QStringLiteral("defaults.json")); };
    const SceneLoadResult leftOut = load(withKey(minimalScene(), section, name, QJsonValue::Undefined));
    const SceneLoadResult given = load(withKey(minimalScene(), section, name, value));
    QVERIFY2(leftOut.ok(), qPrintable(leftOut.errors.join('\n')));
    QVERIFY2(given.ok(), qPrintable(given.errors.join('\n')));
    const QStringList diff = sceneDifferences(*leftOut.scene, *given.scene);
    if (same) {
        QVERIFY2(diff.isEmpty(), qPrintable(diff.join('\n')));
    } else {
        QVERIFY2(!diff.isEmpty() && diff.join('\n').contains(name), qPrintable(diff.join('\n')));
    }
}

QTEST_GUILESS_MAIN(TestSceneFormat)
#include "tst_scene_format.moc"
