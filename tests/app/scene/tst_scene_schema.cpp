// docs/scene.schema.json against the loader. The schema is what editors use to
// complete and check scene files; the loader is what the workbook runs. They must
// agree:
//   - every lesson scene (lessons/*/*.json except exercise.json) passes the schema,
//     and so does what the scene writer makes of it;
//   - on a corpus of good and bad files (tests/scene_schema/corpus.json) each verdict
//     is the stated one, and where both refuse a file they point at the same field;
//   - on the bad-input corpus of rbw (tests/bad_inputs/corpus.json) the schema never
//     refuses a file the loader accepts, and refuses every file the loader refuses
//     except for the classes listed below, whose rules relate values to each other
//     (or are not JSON at all) and so lie beyond a schema;
//   - the schema's list of integrators is the physics' registry, and its closed objects
//     hold exactly the keys the loader allows (the objects of the scene-format table,
//     app/scene/scene_format.h, whose lists the loader checks keys against).
// The validator (tests/support/json_schema.h) is checked first, keyword by keyword,
// on schemas whose verdicts follow from the JSON Schema specification.
#include "app/scene/scene_format.h"
#include "app/scene/scene_loader.h"
#include "app/scene/scene_writer.h"
#include "physics/engine/integrator_registry.h"
#include "tests/support/json_schema.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QSet>
#include <QtTest>

#include <functional>

using namespace rbw;
using rbw::test::JsonSchema;
using rbw::test::SchemaError;

namespace {

const QString kSource = QStringLiteral(RBW_SOURCE_DIR);

QByteArray readFile(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) qFatal("cannot read %s", qPrintable(path));
    return f.readAll();
}

QJsonObject readObject(const QString& path) { return QJsonDocument::fromJson(readFile(path)).object(); }

const JsonSchema& sceneSchema()
{
    static const JsonSchema schema(readObject(kSource + QStringLiteral("/docs/scene.schema.json")));
    return schema;
}

QString errorsText(const QList<SchemaError>& errors)
{
    QStringList lines;
    for (const SchemaError& e : errors) lines << e.text();
    return lines.join('\n');
}

// "bodies[0].orientation.axis" -> {"bodies", "[0]", "orientation", "axis"}
QStringList pathParts(const QString& path)
{
    QString spaced = path;
    spaced.replace('[', QStringLiteral(".["));
    QStringList parts = spaced.split('.', Qt::SkipEmptyParts);
    return parts;
}

// One field contains the other (or they are the same field).
bool related(const QString& a, const QString& b)
{
    const QStringList x = pathParts(a), y = pathParts(b);
    const qsizetype n = std::min(x.size(), y.size());
    return x.mid(0, n) == y.mid(0, n);
}

// The loader's JSON path of an error line "FILE: PATH: REASON" ("" when it has none).
QString loaderPath(const QString& line, const QString& file)
{
    const QString rest = line.mid(file.size() + 2);
    const qsizetype colon = rest.indexOf(QStringLiteral(": "));
    const QString candidate = colon < 0 ? QString() : rest.left(colon);
    return candidate.contains(' ') ? QString() : candidate;
}

// Sets (or with an undefined value removes) the value at "a/0/b" in a JSON value;
// an array index equal to its size appends.
QJsonValue edited(const QJsonValue& root, const QStringList& path, const QJsonValue& value)
{
    if (path.isEmpty()) return value;
    const QString head = path.first();
    if (root.isArray()) {
        QJsonArray a = root.toArray();
        const int i = head.toInt();
        if (i == a.size()) a.append(QJsonValue());
        if (path.size() == 1 && value.isUndefined()) {
            a.removeAt(i);
        } else {
            a[i] = edited(a.at(i), path.mid(1), value);
        }
        return a;
    }
    QJsonObject o = root.toObject();
    if (path.size() == 1 && value.isUndefined()) {
        o.remove(head);
    } else {
        o[head] = edited(o.value(head), path.mid(1), value);
    }
    return o;
}

} // namespace

class TestSceneSchema : public QObject {
    Q_OBJECT
private slots:
    void validatorKeywords_data();
    void validatorKeywords();
    void validatorRefusesOtherKeywords();
    void schemaIsWithinTheSubset();
    void integratorsAreTheRegistry();
    void keysAreTheLoaders();
    void everyLessonPasses_data();
    void everyLessonPasses();
    void corpusVerdicts_data();
    void corpusVerdicts();
    void agreesOnTheBadInputCorpus();
};

// Each row: a schema, an instance, and the verdict the JSON Schema specification gives.
void TestSceneSchema::validatorKeywords_data()
{
    QTest::addColumn<QByteArray>("schema");
    QTest::addColumn<QByteArray>("instance");
    QTest::addColumn<bool>("valid");
    auto row = [](const char* name, const char* schema, const char* instance, bool valid) {
        QTest::newRow(name) << QByteArray(schema) << QByteArray(instance) << valid;
    };
    row("type number", R"({"type":"number"})", "[1.5]", true);
    row("type number, string", R"({"type":"number"})", R"(["1"])", false);
    row("integer 2.0 is an integer", R"({"type":"integer"})", "[2.0]", true);
    row("integer 1.5 is not", R"({"type":"integer"})", "[1.5]", false);
    row("type list", R"({"type":["string","null"]})", "[null]", true);
    row("minimum inclusive", R"({"minimum":0})", "[0]", true);
    row("minimum below", R"({"minimum":0})", "[-1e-300]", false);
    row("exclusiveMinimum at the bound", R"({"exclusiveMinimum":0})", "[0]", false);
    row("exclusiveMinimum above", R"({"exclusiveMinimum":0})", "[5e-324]", true);
    row("maximum", R"({"maximum":1})", "[1.0000000000000002]", false);
    row("exclusiveMaximum", R"({"exclusiveMaximum":1})", "[1]", false);
    row("minimum ignores strings", R"({"minimum":0})", R"(["-5"])", true);
    row("enum", R"({"enum":["a","b"]})", R"(["b"])", true);
    row("enum miss", R"({"enum":["a","b"]})", R"(["c"])", false);
    row("const number 0 == 0.0", R"({"const":0})", "[0.0]", true);
    row("const array", R"({"const":[0,0,0]})", "[[0,0,1]]", false);
    row("const -0 == 0", R"({"const":[0,0,0]})", "[[0,-0.0,0]]", true);
    row("minLength", R"({"minLength":1})", R"([""])", false);
    row("minLength code points", R"({"minLength":2})", R"(["😀"])", false);
    row("items", R"({"items":{"type":"number"}})", R"([[1,"x"]])", false);
    row("minItems", R"({"minItems":3})", "[[1,2]]", false);
    row("maxItems", R"({"maxItems":3})", "[[1,2,3,4]]", false);
    row("uniqueItems", R"({"uniqueItems":true})", R"([["a","a"]])", false);
    row("uniqueItems distinct", R"({"uniqueItems":true})", R"([["a","b"]])", true);
    row("required", R"({"required":["a"]})", R"([{"b":1}])", false);
    row("additionalProperties false", R"({"properties":{"a":{}},"additionalProperties":false})", R"([{"a":1,"b":2}])", false);
    row("additionalProperties absent", R"({"properties":{"a":{}}})", R"([{"a":1,"b":2}])", true);
    row("properties apply", R"({"properties":{"a":{"type":"string"}}})", R"([{"a":1}])", false);
    row("anyOf one", R"({"anyOf":[{"const":0},{"minimum":1}]})", "[1.5]", true);
    row("anyOf none", R"({"anyOf":[{"const":0},{"minimum":1}]})", "[0.5]", false);
    row("oneOf two match", R"({"oneOf":[{"minimum":0},{"maximum":5}]})", "[3]", false);
    row("oneOf exactly one", R"({"oneOf":[{"minimum":0},{"maximum":-5}]})", "[3]", true);
    row("allOf", R"({"allOf":[{"minimum":0},{"maximum":5}]})", "[6]", false);
    row("not", R"({"not":{"const":1}})", "[1]", false);
    row("if-then", R"({"if":{"required":["f"]},"then":{"required":["g"]},"else":{"required":["h"]}})", R"([{"f":1}])", false);
    row("if-else", R"({"if":{"required":["f"]},"then":{"required":["g"]},"else":{"required":["h"]}})", R"([{"h":1}])", true);
    row("$ref", R"({"$defs":{"p":{"minimum":0}},"$ref":"#/$defs/p"})", "[-1]", false);
    row("$ref with a sibling", R"({"$defs":{"p":{"minimum":0}},"$ref":"#/$defs/p","maximum":2})", "[3]", false);
    row("false schema", R"({"properties":{"a":false}})", R"([{"a":1}])", false);
}

void TestSceneSchema::validatorKeywords()
{
    QFETCH(QByteArray, schema);
    QFETCH(QByteArray, instance);
    QFETCH(bool, valid);
    const JsonSchema s(QJsonDocument::fromJson(schema).object());
    QVERIFY2(s.problems().isEmpty(), qPrintable(s.problems().join('\n')));
    const QJsonValue v = QJsonDocument::fromJson(instance).array().at(0);   // wrapped: any JSON value
    const QList<SchemaError> errors = s.validate(v);
    QVERIFY2(errors.isEmpty() == valid, qPrintable(errorsText(errors)));
}

void TestSceneSchema::validatorRefusesOtherKeywords()
{
    // A keyword it does not implement would be silently ignored: refused instead.
    const JsonSchema s(QJsonDocument::fromJson(R"({"properties":{"a":{"pattern":"^x"}}})").object());
    QCOMPARE(s.problems().size(), 1);
    QVERIFY(s.problems().first().contains("pattern"));
    QVERIFY(!s.accepts(QJsonObject{{"a", "x"}}));
    const JsonSchema r(QJsonDocument::fromJson(R"({"$ref":"other.json#/x"})").object());
    QCOMPARE(r.problems().size(), 1);
}

void TestSceneSchema::schemaIsWithinTheSubset()
{
    QVERIFY2(sceneSchema().problems().isEmpty(), qPrintable(sceneSchema().problems().join('\n')));
    const QJsonObject root = readObject(kSource + QStringLiteral("/docs/scene.schema.json"));
    QCOMPARE(root.value("$schema").toString(), QString("https://json-schema.org/draft/2020-12/schema"));
    // Every top-level key the loader knows is described (a key missing here would be
    // refused by the schema: the corpus below would show it too).
    const QStringList keys = root.value("properties").toObject().keys();
    for (const char* k : {"name", "description", "dt", "steps", "integrator", "inertia_convention", "gravity", "bodies",
                          "forces", "torques", "push", "probes", "planes", "box_collisions", "restitution",
                          "restitution_threshold", "friction", "pairs", "position_correction", "plane_contacts",
                          "energy_jump", "contact_model", "solver_iterations", "sleep", "position_fix", "solver",
                          "substeps"}) {
        QVERIFY2(keys.contains(QLatin1String(k)), k);
    }
}

void TestSceneSchema::integratorsAreTheRegistry()
{
    const QJsonArray listed =
        readObject(kSource + QStringLiteral("/docs/scene.schema.json")).value("$defs").toObject().value("integrator").toObject().value("enum").toArray();
    QStringList schemaNames, registry;
    for (const QJsonValue& v : listed) schemaNames << v.toString();
    for (const IntegratorInfo& info : integratorCatalogue()) registry << QString::fromLatin1(info.name);
    QCOMPARE(schemaNames, registry);
}

// Every list of keys the loader allows (the scene-format table's objects, which the
// loader's checkKeys() calls use) is exactly the keys of one closed object of the schema
// (additionalProperties false; an orientation's forms together), and every closed object
// is one of the loader's: a key added to one and not the other fails here.
void TestSceneSchema::keysAreTheLoaders()
{
    using sceneformat::Section;
    QList<QSet<QString>> loader;
    for (Section s : {Section::Scene, Section::EnergyJump, Section::Body, Section::Orientation, Section::Force,
                      Section::Torque, Section::Push, Section::Probe, Section::Plane, Section::Pair}) {
        const QStringList keys = sceneformat::keysOf(s);
        loader << QSet<QString>(keys.begin(), keys.end());
    }
    QVERIFY2(loader.size() >= 10, qPrintable(QString::number(loader.size())));

    QList<QSet<QString>> schema;
    std::function<void(const QJsonValue&)> walk = [&](const QJsonValue& v) {
        if (v.isArray()) {
            for (const QJsonValue& e : v.toArray()) walk(e);
            return;
        }
        if (!v.isObject()) return;
        const QJsonObject o = v.toObject();
        if (o.contains("oneOf")) {
            QSet<QString> forms;
            for (const QJsonValue& b : o.value("oneOf").toArray()) {
                for (const QString& k : b.toObject().value("properties").toObject().keys()) forms.insert(k);
            }
            schema << forms;
        } else if (o.value("additionalProperties") == QJsonValue(false)) {
            const QStringList keys = o.value("properties").toObject().keys();
            schema << QSet<QString>(keys.begin(), keys.end());
        }
        for (auto it = o.begin(); it != o.end(); ++it) {
            if (it.key() != QLatin1String("oneOf")) walk(it.value());
        }
    };
    walk(readObject(kSource + QStringLiteral("/docs/scene.schema.json")));
    for (const QSet<QString>& keys : loader) {
        QStringList sorted(keys.begin(), keys.end());
        sorted.sort();
        QVERIFY2(schema.contains(keys), qPrintable(QStringLiteral("the loader allows {%1}; no schema object has exactly these keys")
                                                       .arg(sorted.join(", "))));
    }
    for (const QSet<QString>& keys : schema) {
        QStringList sorted(keys.begin(), keys.end());
        sorted.sort();
        QVERIFY2(loader.contains(keys), qPrintable(QStringLiteral("the schema allows {%1}; the loader has no such list")
                                                       .arg(sorted.join(", "))));
    }
}

void TestSceneSchema::everyLessonPasses_data()
{
    QTest::addColumn<QString>("file");
    const QDir root(kSource + QStringLiteral("/lessons"));
    int count = 0;
    for (const QString& folder : root.entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name)) {
        for (const QString& f : QDir(root.filePath(folder)).entryList({"*.json"}, QDir::Files, QDir::Name)) {
            if (f == QLatin1String("exercise.json")) continue;
            QTest::newRow(qPrintable(folder + '/' + f)) << root.filePath(folder + '/' + f);
            ++count;
        }
    }
    QVERIFY(count >= 14);
}

void TestSceneSchema::everyLessonPasses()
{
    QFETCH(QString, file);
    const QByteArray text = readFile(file);
    const QList<SchemaError> errors = sceneSchema().validate(QJsonDocument::fromJson(text).object());
    QVERIFY2(errors.isEmpty(), qPrintable(errorsText(errors)));
    const SceneLoadResult loaded = parseScene(text, file);
    QVERIFY2(loaded.ok(), qPrintable(loaded.errors.join('\n')));
    // What the editor saves for this lesson passes too.
    const QJsonDocument written = QJsonDocument::fromJson(writeScene(*loaded.scene));
    const QList<SchemaError> writtenErrors = sceneSchema().validate(written.object());
    QVERIFY2(writtenErrors.isEmpty(), qPrintable(errorsText(writtenErrors)));
}

void TestSceneSchema::corpusVerdicts_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<bool>("schemaAccepts");
    QTest::addColumn<bool>("loaderAccepts");
    QTest::addColumn<QString>("path");
    const QJsonObject corpus = readObject(kSource + QStringLiteral("/tests/scene_schema/corpus.json"));
    const QJsonArray cases = corpus.value("cases").toArray();
    QVERIFY(cases.size() >= 60);
    int good = 0, beyond = 0;
    QSet<QString> names;
    for (const QJsonValue& v : cases) {
        const QJsonObject c = v.toObject();
        const QString name = c.value("case").toString();
        QVERIFY2(!names.contains(name), qPrintable(name));
        names.insert(name);
        QByteArray text;
        if (c.contains("text")) {
            text = c.value("text").toString().toUtf8();
        } else {
            QJsonValue scene = readObject(kSource + '/' + c.value("base").toString(corpus.value("base").toString()));
            const QJsonObject set = c.value("set").toObject();
            for (auto it = set.begin(); it != set.end(); ++it) scene = edited(scene, it.key().split('/'), it.value());
            for (const QJsonValue& r : c.value("remove").toArray()) {
                scene = edited(scene, r.toString().split('/'), QJsonValue(QJsonValue::Undefined));
            }
            text = QJsonDocument(scene.toObject()).toJson();
        }
        const bool schemaAccepts = c.value("schema").toBool();
        const bool loaderAccepts = c.value("loader").toBool();
        good += schemaAccepts && loaderAccepts;
        // A file the schema accepts and the loader refuses needs its reason written down.
        if (schemaAccepts && !loaderAccepts) {
            ++beyond;
            QVERIFY2(!c.value("why").toString().isEmpty(), qPrintable(name));
        }
        QVERIFY2(!(loaderAccepts && !schemaAccepts), qPrintable(name + ": the schema may not be stricter than the loader"));
        QTest::newRow(qPrintable(name)) << text << schemaAccepts << loaderAccepts << c.value("path").toString();
    }
    QVERIFY(good >= 15);   // enough accepted files that a schema refusing too much is caught
    QVERIFY(beyond >= 5);
}

void TestSceneSchema::corpusVerdicts()
{
    QFETCH(QByteArray, text);
    QFETCH(bool, schemaAccepts);
    QFETCH(bool, loaderAccepts);
    QFETCH(QString, path);
    const QString file = QStringLiteral("case.json");
    const SceneLoadResult loaded = parseScene(text, file);
    QVERIFY2(loaded.ok() == loaderAccepts, qPrintable(loaded.ok() ? QStringLiteral("the loader accepts it")
                                                                   : loaded.errors.join('\n')));
    const QList<SchemaError> errors = sceneSchema().validate(QJsonDocument::fromJson(text).isObject()
                                                                 ? QJsonValue(QJsonDocument::fromJson(text).object())
                                                                 : QJsonValue(QJsonDocument::fromJson(text).array()));
    QVERIFY2(errors.isEmpty() == schemaAccepts,
             qPrintable(errors.isEmpty() ? QStringLiteral("the schema accepts it") : errorsText(errors)));
    if (loaderAccepts) return;
    // The loader's message names the stated field...
    const QString first = loaderPath(loaded.errors.first(), file);
    QVERIFY2(first == path, qPrintable(QStringLiteral("loader: %1").arg(loaded.errors.first())));
    // ...and where the schema refuses too, one of its errors is about that field (or
    // the object holding it: an orientation that matches none of its forms).
    if (!schemaAccepts && !path.isEmpty()) {
        bool same = false;
        for (const SchemaError& e : errors) same = same || related(e.path, path);
        QVERIFY2(same, qPrintable(QStringLiteral("loader: %1\nschema:\n%2").arg(loaded.errors.first(), errorsText(errors))));
    }
}

void TestSceneSchema::agreesOnTheBadInputCorpus()
{
    // Classes of tests/bad_inputs/corpus.json the schema cannot refuse, and why. Each
    // must really pass the schema (a stale entry fails below).
    const QHash<QString, QString> beyondSchema{
        {"duplicate key", "the JSON reader keeps the last of two equal keys; the schema sees a valid object"},
        {"control byte in a name", "a force names a body that does not exist: a relation between values"},
        {"mass so small that 1/M overflows", "a limit of the double range"},
        {"mass so large that I0 overflows", "a limit of the double range that depends on the size"},
        {"size whose square overflows", "a limit of the double range"},
        {"rotation axis whose length overflows", "a limit of the double range"},
        {"duplicate body name", "uniqueness across array elements"},
        {"force on an unknown body", "a name must name a body of the file"},
        {"probe on an unknown body", "a name must name a body of the file"},
    };
    const QJsonObject corpus = readObject(kSource + QStringLiteral("/tests/bad_inputs/corpus.json"));
    const QByteArray base = readFile(kSource + '/' + corpus.value("base").toString());
    int compared = 0, notJson = 0;
    QSet<QString> seenBeyond;
    for (const QJsonValue& v : corpus.value("cases").toArray()) {
        const QJsonObject c = v.toObject();
        const QString name = c.value("class").toString();
        // Only cases about the scene file itself: no file, or command-line options, are not.
        if (!c.value("scene").toBool(true) || c.contains("args")) continue;
        QByteArray text = c.contains("text") ? c.value("text").toString().toUtf8() : base;
        for (const QJsonValue& r : c.value("replace").toArray()) {
            text.replace(r.toArray().at(0).toString().toUtf8(), r.toArray().at(1).toString().toUtf8());
        }
        const SceneLoadResult loaded = parseScene(text, QStringLiteral("scene.json"));
        QJsonParseError error;
        const QJsonDocument doc = QJsonDocument::fromJson(text, &error);
        if (error.error != QJsonParseError::NoError) {
            // Not JSON: no schema applies, and the loader refuses it.
            QVERIFY2(!loaded.ok(), qPrintable(name));
            ++notJson;
            continue;
        }
        const QList<SchemaError> errors = sceneSchema().validate(doc.isObject() ? QJsonValue(doc.object())
                                                                                : QJsonValue(doc.array()));
        const bool schemaAccepts = errors.isEmpty();
        ++compared;
        if (loaded.ok()) {
            // Exit 3 cases: the file is fine, the run stops later.
            QVERIFY2(schemaAccepts, qPrintable(name + ":\n" + errorsText(errors)));
        } else if (beyondSchema.contains(name)) {
            QVERIFY2(schemaAccepts, qPrintable(name + ": listed as beyond the schema, but it refuses it:\n" +
                                               errorsText(errors)));
            seenBeyond.insert(name);
        } else {
            QVERIFY2(!schemaAccepts, qPrintable(name + ": the loader refuses it (" + loaded.errors.first() +
                                                "), the schema accepts it"));
        }
    }
    QCOMPARE(seenBeyond.size(), beyondSchema.size());
    QVERIFY(compared >= 30);
    QVERIFY(notJson >= 4);
}

QTEST_GUILESS_MAIN(TestSceneSchema)
#include "tst_scene_schema.moc"
