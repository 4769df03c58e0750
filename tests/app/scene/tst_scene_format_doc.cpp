// docs/scene-format.md lists the scene-format table (app/scene/scene_format.cpp): each
// object of a scene file has its key table on the page (the first table with the columns
// "key | type | required / default | meaning" under the object's heading), and
//   - it lists exactly the table's keys of that object, each once;
//   - a key is "**required**" on the page exactly when the table requires it (a key
//     required only "unless" something is not required);
//   - a key with a default in the table says "default `X`" with the same JSON value
//     (1e-9 and 1e-09 are the same number);
//   - a key with a unit in the table names that unit in its row ("in m", "(m/s)").
// The page may say more (a default in words where no JSON value says it, "the
// scene's"), never something else. tamperedDocDiffers is the negative control: a
// page changed in one of these ways shows exactly that difference.
#include "app/scene/scene_format.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QMap>
#include <QRegularExpression>
#include <QSet>
#include <QtTest>

using namespace rbw;
using namespace rbw::sceneformat;

namespace {

const QString kSource = QStringLiteral(RBW_SOURCE_DIR);
const QString kHeader = QStringLiteral("| key | type | required / default | meaning |");

QString realDoc()
{
    QFile f(kSource + QStringLiteral("/docs/scene-format.md"));
    if (!f.open(QIODevice::ReadOnly)) qFatal("cannot read docs/scene-format.md");
    return QString::fromUtf8(f.readAll());
}

// The heading under which each object's key table stands.
const QList<QPair<QString, Section>> kHeadings{
    {"Top level", Section::Scene},   {"`energy_jump`", Section::EnergyJump}, {"Bodies", Section::Body},
    {"Orientation", Section::Orientation}, {"Forces", Section::Force},       {"Torques", Section::Torque},
    {"Push", Section::Push},         {"Probes", Section::Probe},             {"Planes", Section::Plane},
    {"Pairs", Section::Pair}};

QString sectionName(Section s)
{
    static const QStringList names{"top level", "energy_jump", "body", "orientation", "force",
                                   "torque", "push", "probe", "plane", "pair"};
    return names.value(static_cast<int>(s));
}

// One row of a key table: its cells, without the outer bars, trimmed.
QStringList cells(const QString& line)
{
    static const QRegularExpression bar(QStringLiteral(R"((?<!\\)\|)"));
    QStringList c = line.trimmed().split(bar);
    if (c.size() >= 2) c = c.mid(1, c.size() - 2);
    for (QString& x : c) x = x.trimmed();
    return c;
}

// Each object's key table: section -> its rows (cells), in the page's order.
QMap<Section, QList<QStringList>> keyTables(const QString& doc)
{
    QMap<Section, QList<QStringList>> tables;
    std::optional<Section> under;   // the object whose heading we are under, until its table
    bool inTable = false;
    for (const QString& line : doc.split('\n')) {
        if (line.startsWith('#')) {
            under.reset();
            inTable = false;
            const QString heading = line.section(' ', 1).trimmed();
            for (const auto& [text, section] : kHeadings) {
                if (heading == text && !tables.contains(section)) under = section;
            }
        } else if (under && line.trimmed() == kHeader) {
            inTable = true;
            tables[*under];
        } else if (inTable && line.startsWith('|')) {
            if (!line.startsWith(QLatin1String("| ---"))) tables[*under] << cells(line);
        } else if (inTable) {
            inTable = false;
            under.reset();   // only the first key table under the heading
        }
    }
    return tables;
}

QJsonValue jsonOf(const QString& text)
{
    return QJsonDocument::fromJson("[" + text.toUtf8() + "]").array().at(0);
}

// Every way the page and the table differ, one line each ("body.mass: ...").
QStringList differences(const QString& doc)
{
    const QMap<Section, QList<QStringList>> tables = keyTables(doc);
    static const QRegularExpression defaultText(QStringLiteral("default `([^`]*)`"));
    QStringList out;
    for (const auto& [heading, s] : kHeadings) {
        const QString where = sectionName(s);
        if (!tables.contains(s)) {
            out << QStringLiteral("%1: no key table under \"%2\"").arg(where, heading);
            continue;
        }
        QMap<QString, QStringList> rowOf;
        for (const QStringList& row : tables.value(s)) {
            const QString k = row.value(0).remove('`');
            if (rowOf.contains(k)) out << QStringLiteral("%1.%2: listed twice").arg(where, k);
            rowOf.insert(k, row);
            if (!find(s, k)) out << QStringLiteral("%1.%2: in the doc, not in the table").arg(where, k);
        }
        for (const QString& k : keysOf(s)) {
            const KeyRow& r = *find(s, k);
            if (!rowOf.contains(k)) {
                out << QStringLiteral("%1.%2: in the table, not in the doc").arg(where, k);
                continue;
            }
            const QStringList row = rowOf.value(k);
            const QString given = row.value(2);
            const bool required = given.startsWith(QLatin1String("**required**")) && !given.contains(QLatin1String("unless"));
            if (required != r.required) out << QStringLiteral("%1.%2: required in one, not in the other").arg(where, k);
            if (*r.fallback) {
                const QRegularExpressionMatch m = defaultText.match(given);
                if (!m.hasMatch()) {
                    out << QStringLiteral("%1.%2: no default in the doc, %3 in the table").arg(where, k, QString::fromUtf8(r.fallback));
                } else if (jsonOf(m.captured(1)) != jsonOf(QString::fromUtf8(r.fallback))) {
                    out << QStringLiteral("%1.%2: default %3 in the doc, %4 in the table")
                               .arg(where, k, m.captured(1), QString::fromUtf8(r.fallback));
                }
            }
            if (*r.unit) {
                const QString unit = QString::fromUtf8(r.unit);
                const QRegularExpression token(QStringLiteral(R"((?<![\w/])%1(?![\w/²]))").arg(QRegularExpression::escape(unit)),
                                               QRegularExpression::UseUnicodePropertiesOption);
                if (!row.mid(1).join(' ').contains(token)) out << QStringLiteral("%1.%2: no unit %3 in the doc").arg(where, k, unit);
            }
        }
    }
    return out;
}

} // namespace

class TestSceneFormatDoc : public QObject {
    Q_OBJECT
private slots:
    void docIsTheTable();
    void tamperedDocDiffers_data();
    void tamperedDocDiffers();
};

void TestSceneFormatDoc::docIsTheTable()
{
    const QString doc = realDoc();
    // Every object's table was found, with all of its rows.
    const QMap<Section, QList<QStringList>> tables = keyTables(doc);
    QCOMPARE(tables.size(), kHeadings.size());
    qsizetype rows = 0;
    for (const QList<QStringList>& t : tables) rows += t.size();
    QCOMPARE(rows, static_cast<qsizetype>(sceneformat::rows().size()));
    const QStringList diff = differences(doc);
    QVERIFY2(diff.isEmpty(), qPrintable(diff.join('\n')));
}

// Negative controls: each edit of the real page must show as exactly its difference.
void TestSceneFormatDoc::tamperedDocDiffers_data()
{
    QTest::addColumn<QString>("from");
    QTest::addColumn<QString>("to");
    QTest::addColumn<QStringList>("expected");
    QTest::newRow("key missing")
        << "| `angular_response` | true / false | default `true` |" << "| `angular_resp` | true / false | default `true` |"
        << QStringList{"body.angular_resp: in the doc, not in the table", "body.angular_response: in the table, not in the doc"};
    QTest::newRow("default changed") << "| `steps` | whole number | default `1` |" << "| `steps` | whole number | default `2` |"
                                     << QStringList{"top level.steps: default 2 in the doc, 1 in the table"};
    QTest::newRow("default dropped") << "| `floor` | number (J) | default `1e-9` |" << "| `floor` | number (J) | small |"
                                     << QStringList{"energy_jump.floor: no default in the doc, 1e-09 in the table"};
    QTest::newRow("unit dropped") << "force f in N, world frame" << "force f, world frame"
                                  << QStringList{"force.force: no unit N in the doc"};
    QTest::newRow("required changed") << "| `point` | [x, y, z] | **required** | the point's **world** position"
                                      << "| `point` | [x, y, z] | default `[0, 0, 0]` | the point's **world** position"
                                      << QStringList{"probe.point: required in one, not in the other"};
    QTest::newRow("table gone") << "\n## Push\n" << "\n## Pushing\n" << QStringList{"push: no key table under \"Push\""};
}

void TestSceneFormatDoc::tamperedDocDiffers()
{
    QFETCH(QString, from);
    QFETCH(QString, to);
    QFETCH(QStringList, expected);
    QString doc = realDoc();
    QCOMPARE(doc.count(from), qsizetype(1));   // the edit is where it is meant to be
    doc.replace(from, to);
    QCOMPARE(differences(doc), expected);
}

QTEST_GUILESS_MAIN(TestSceneFormatDoc)
#include "tst_scene_format_doc.moc"
