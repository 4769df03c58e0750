// A scene key, or a word of a scene enumeration, is spelled in one app file: the
// scene-format table (app/scene/scene_format.cpp); the words themselves live beside
// their enumerations in physics/engine/scene_words.h. Every other file of app/ that
// reads or writes a scene takes them from there (issue 18).
//
// How the scan tells a scene key from another format's key of the same spelling (the
// run output's "bodies", an answers file's "body", exercise.json's "description"):
//   - every .cpp and .h of app/ but the table is scanned for the table's keys and the
//     enumerations' words (integrators' names too) as a string literal ("mass") or as
//     a quoted word inside one (\"mass\"), outside // comments;
//   - a literal is allowed only where kOtherFormats declares it: a file (or folder)
//     that reads or writes ANOTHER format, the format, and exactly the literals of that
//     format spelled like a scene key. A declaration no literal uses any more fails
//     (stale), so the list stays as small as the truth;
//   - even there, a literal handed to a scene object (`scene.value("name")`,
//     `spec.scene.insert("bodies", ...)`, `sceneJson["dt"]`) is a scene key and fails.
// So a scene key typed where a scene is read or written fails the test unless the
// file declares it as the key of another format, in a list a reviewer reads here.
// scannerIsHonest is the negative control: the scan finds a key typed in a text, on a
// scene object inside a declared file, and a stale declaration.
#include "app/scene/scene_format.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QRegularExpression>
#include <QSet>
#include <QtTest>

using namespace rbw;
using namespace rbw::sceneformat;

namespace {

const QString kSource = QStringLiteral(RBW_SOURCE_DIR);
const QString kTable = QStringLiteral("app/scene/scene_format.cpp");

// Another format whose keys or words are spelled like a scene's.
struct OtherFormat {
    QString where;          // a file, or a folder ending in '/'
    QString format;         // which format, and where it is documented
    QStringList literals;   // exactly the literals of that format spelled like a scene key
};

const QList<OtherFormat> kOtherFormats{
    {"app/output/json_output.cpp", "the run output of `rbw run --format json` (docs/cli.md)",
     {"bodies", "body", "dt", "fixed", "inertia_convention", "integrator", "name", "point", "probes", "steps"}},
    {"app/output/study_csv.cpp", "the columns of the study CSVs (docs/accuracy-lab.md)", {"dt", "integrator", "steps"}},
    {"app/output/value_format.cpp", "a trace value's kind in the run output (docs/cli.md)", {"quaternion"}},
    {"app/cli/",
     "rbw's options (--dt, --steps, --integrator, --trace none, --probes), the results of `rbw check` (docs/cli.md, "
     "docs/simulator-protocol.md)",
     {"body", "dt", "integrator", "none", "probes", "steps"}},
    {"app/simulator/diagnose_report.cpp",
     "`rbw diagnose`'s JSON: a probe's name, the probes, the body of a divergence, the restitution fitted to a "
     "simulator's answers (docs/simulator-protocol.md)",
     {"body", "name", "probes", "restitution"}},
    {"app/exercise/answers_file.cpp", "answers files (docs/checker.md)", {"body"}},
    {"app/exercise/exercise_spec.cpp", "exercise.json's own keys (docs/exercises.md)", {"description"}},
    {"app/derivation/", "the derivation templates' placeholders, {{mass}}, {{body}} (docs/derivation-templates.md)",
     {"body", "integrator", "mass", "size"}},
    {"app/gui/panels/derivation/derivation_view.cpp", "the rendered page's fields, read back from its JavaScript",
     {"body"}},
    {"app/gui/panels/accuracy/", "the accuracy study's settings and columns", {"dt", "integrator"}},
    {"app/gui/shell/performance_probe.cpp", "the performance report (docs/performance.md)", {"bodies"}},
};

QByteArray readFile(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) qFatal("cannot read %s", qPrintable(path));
    return f.readAll();
}

// The code of a C++ text without its // comments (a comment may name a key; a "//"
// inside a string literal is kept, after an even number of quotes on its line).
QString withoutComments(const QString& text)
{
    QStringList lines = text.split('\n');
    for (QString& line : lines) {
        for (qsizetype at = line.indexOf(QStringLiteral("//")); at >= 0; at = line.indexOf(QStringLiteral("//"), at + 2)) {
            if (line.left(at).count('"') % 2 == 0) {
                line.truncate(at);
                break;
            }
        }
    }
    return lines.join('\n');
}

// The table's keys and every enumeration's words: what no other file may spell.
QSet<QString> sceneLiterals()
{
    QSet<QString> literals;
    for (const KeyRow& r : rows()) literals.insert(QString::fromLatin1(r.name));
    for (Choices c : {Choices::Integrator, Choices::InertiaConvention, Choices::PlaneContacts, Choices::ContactModel,
                      Choices::PositionFix, Choices::ManifoldSolver}) {
        for (const QString& w : words(c)) literals.insert(w);
    }
    return literals;
}

// The scene literals a C++ text spells as a string literal ("mass") or as a quoted
// word inside one (\"mass\"), outside comments.
QStringList spelledKeys(const QString& text)
{
    const QString code = withoutComments(text);
    QStringList found;
    for (const QString& l : sceneLiterals()) {
        if (code.contains('"' + l + '"') || code.contains(QStringLiteral("\\\"%1\\\"").arg(l))) found << l;
    }
    found.sort();
    return found;
}

// The scene literals a text hands to a scene object: an expression whose last name
// contains "scene" (scene, spec.scene, m_scene, sceneJson, lessonScene), then
// .value( .insert( .contains( .remove( .take( or [, then the literal (bare, or in
// QStringLiteral / QLatin1String / u"").
QStringList keysOnASceneObject(const QString& text)
{
    static const QRegularExpression access(
        QStringLiteral(R"re([A-Za-z_]*[Ss]cene[A-Za-z_0-9]*\s*(?:(?:\.|->)\s*(?:value|insert|contains|remove|take)\s*\(|\[)\s*)re"
                       R"re((?:QStringLiteral\s*\(\s*|QLatin1String\s*\(\s*|u)?"([^"\\]*)")re"));
    const QSet<QString> literals = sceneLiterals();
    QStringList found;
    QRegularExpressionMatchIterator it = access.globalMatch(withoutComments(text));
    while (it.hasNext()) {
        const QString literal = it.next().captured(1);
        if (literals.contains(literal) && !found.contains(literal)) found << literal;
    }
    found.sort();
    return found;
}

bool covers(const OtherFormat& f, const QString& relative)
{
    return f.where.endsWith('/') ? relative.startsWith(f.where) : relative == f.where;
}

// Every offence of the files {relative path: text} against the declarations, one line
// each: a scene literal a file may not spell, one on a scene object, a stale declaration.
QStringList offences(const QMap<QString, QString>& files, const QList<OtherFormat>& declared)
{
    QStringList out;
    QMap<int, QSet<QString>> used;   // declaration -> the literals files it covers spell
    for (auto file = files.begin(); file != files.end(); ++file) {
        const QString& relative = file.key();
        if (relative == kTable) continue;
        QStringList undeclared;
        for (const QString& l : spelledKeys(file.value())) {
            bool allowed = false;
            for (int i = 0; i < declared.size(); ++i) {
                if (covers(declared[i], relative) && declared[i].literals.contains(l)) {
                    allowed = true;
                    used[i].insert(l);
                }
            }
            if (!allowed) undeclared << l;
        }
        if (!undeclared.isEmpty()) out << QStringLiteral("%1: spells %2").arg(relative, undeclared.join(", "));
        const QStringList onScene = keysOnASceneObject(file.value());
        if (!onScene.isEmpty()) {
            out << QStringLiteral("%1: spells %2 on a scene object").arg(relative, onScene.join(", "));
        }
    }
    for (int i = 0; i < declared.size(); ++i) {
        for (const QString& l : declared[i].literals) {
            if (!used[i].contains(l)) out << QStringLiteral("%1: declares \"%2\", which it no longer spells").arg(declared[i].where, l);
        }
    }
    return out;
}

} // namespace

class TestSceneKeys : public QObject {
    Q_OBJECT
private slots:
    void scannerIsHonest_data();
    void scannerIsHonest();
    void keysSpelledOnce();
};

void TestSceneKeys::scannerIsHonest_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QStringList>("expected");
    const QString file = QStringLiteral("app/output/json_output.cpp");   // a declared file
    QTest::newRow("key typed") << QStringLiteral("b.mass = toNumber(o.value(\"mass\"), path);")
                               << QStringList{"app/x.cpp: spells mass"};
    QTest::newRow("word typed") << QStringLiteral("if (w == \"course-template\") {}")
                                << QStringList{"app/x.cpp: spells course-template"};
    QTest::newRow("integrator typed") << QStringLiteral("s.integrator = \"explicit-euler\";")
                                      << QStringList{"app/x.cpp: spells explicit-euler"};
    QTest::newRow("key in a message") << QStringLiteral("throw E{QStringLiteral(\"leave \\\"mass\\\" out\")};")
                                      << QStringList{"app/x.cpp: spells mass"};
    QTest::newRow("scene read") << QStringLiteral("names << spec.scene.value(QStringLiteral(\"planes\"));")
                                << QStringList{"app/x.cpp: spells planes", "app/x.cpp: spells planes on a scene object"};
    // Negative controls: a key's name in a comment, in a longer literal, unquoted, or
    // through the table: nothing.
    QTest::newRow("not a key")
        << QStringLiteral("x = o.value(key(Key::BodyMass)); // \"mass\"\ny = \"masses\"; z = mass; w = \"from_step up\";")
        << QStringList{};
}

void TestSceneKeys::scannerIsHonest()
{
    QFETCH(QString, text);
    QFETCH(QStringList, expected);
    QCOMPARE(offences({{QStringLiteral("app/x.cpp"), text}}, {}), expected);
}

// No file of app/ but the table spells a scene key or word, except the keys of other
// formats its declaration lists; none on a scene object.
void TestSceneKeys::keysSpelledOnce()
{
    QMap<QString, QString> files;
    QDirIterator it(kSource + QStringLiteral("/app"), {"*.cpp", "*.h"}, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString path = it.next();
        files.insert(QDir(kSource).relativeFilePath(path), QString::fromUtf8(readFile(path)));
    }
    // The scan saw the app: the table, the loader, the exercise and the editor.
    for (const char* f : {"app/scene/scene_format.cpp", "app/scene/scene_mapping.cpp", "app/exercise/exercise_draw.cpp",
                          "app/gui/panels/editor/scene_editor_values.cpp"}) {
        QVERIFY2(files.contains(QString::fromLatin1(f)), f);
    }
    QVERIFY2(files.size() > 100, qPrintable(QString::number(files.size())));
    const QStringList found = offences(files, kOtherFormats);
    QVERIFY2(found.isEmpty(), qPrintable(found.join('\n')));

    // Negative controls on the real tree: a scene read typed into a declared file, and
    // the same file with a declared literal taken away, are each found.
    QMap<QString, QString> tampered = files;
    const QString output = QStringLiteral("app/output/json_output.cpp");
    tampered[output] += QStringLiteral("\nQString f(const QJsonObject& scene) { return scene.value(\"name\").toString(); }\n");
    QCOMPARE(offences(tampered, kOtherFormats), QStringList{output + ": spells name on a scene object"});
    QList<OtherFormat> narrower = kOtherFormats;
    narrower[0].literals.removeAll(QStringLiteral("dt"));
    QCOMPARE(offences(files, narrower), QStringList{output + ": spells dt"});
}

QTEST_GUILESS_MAIN(TestSceneKeys)
#include "tst_scene_keys.moc"
