// Every traced number names the physics statement that computed it (issue 9): for
// every scene file of every lesson, `rbw run --trace all --format json` gives each
// quantity (and each contact field) a "source" of the form "physics/<file>:<line>",
// relative to the repository root; the file exists, the line exists, and that line
// is the statement that captures the source location (a record() call, a
// trace->add(), or a std::source_location::current() beside the computed value).
#include "tests/test_support.h"

#include "physics/engine/quantity_catalogue.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QtTest>

#include <map>

namespace {

// Empty if `source` names an existing line of a physics file that records a value.
QString checkSource(const QString& source, std::map<QString, QStringList>& files)
{
    static const QRegularExpression form(QStringLiteral("^(physics/[A-Za-z0-9_/]+\\.(?:cpp|h)):(\\d+)$"));
    const QRegularExpressionMatch m = form.match(source);
    if (!m.hasMatch()) return QStringLiteral("not of the form physics/<file>:<line>: \"%1\"").arg(source);
    const QString path = m.captured(1);
    if (!files.count(path)) {
        QFile f(QStringLiteral(RBW_SOURCE_DIR "/") + path);
        if (!f.open(QIODevice::ReadOnly | QIODevice::Text)) return QStringLiteral("no such file: ") + path;
        files[path] = QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'));
    }
    const QStringList& lines = files[path];
    const int line = m.captured(2).toInt();
    if (line < 1 || line > lines.size()) return QStringLiteral("%1 has no line %2").arg(path).arg(line);
    const QString text = lines[line - 1];
    static const QRegularExpression records(QStringLiteral("record\\(|->add\\(|source_location::current\\(\\)"));
    if (!text.contains(records)) return QStringLiteral("%1 line %2 records nothing: %3").arg(path).arg(line).arg(text);
    return {};
}

} // namespace

class TestTraceSources : public QObject {
    Q_OBJECT
private slots:
    void everyEntryHasItsSource_data()
    {
        QTest::addColumn<QString>("scene");
        const QDir lessons(QStringLiteral(RBW_SOURCE_DIR "/lessons"));
        for (const QString& dir : lessons.entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name)) {
            for (const QString& f : QDir(lessons.filePath(dir)).entryList({QStringLiteral("*.json")}, QDir::Files)) {
                if (f == QLatin1String("exercise.json")) continue;   // not a scene (docs/exercises.md)
                QTest::newRow(qPrintable(dir + QLatin1Char('/') + f)) << lessons.filePath(dir + QLatin1Char('/') + f);
            }
        }
    }

    void everyEntryHasItsSource()
    {
        QFETCH(QString, scene);
        // 120 steps: long enough for the collision lessons' first contacts.
        const rbw::test::RbwRun run = rbw::test::runRbw(
            {QStringLiteral("run"), scene, QStringLiteral("--trace"), QStringLiteral("all"), QStringLiteral("--steps"),
             QStringLiteral("120"), QStringLiteral("--format"), QStringLiteral("json")});
        QCOMPARE(run.exitCode, 0);
        const QJsonObject doc = QJsonDocument::fromJson(run.out).object();
        std::map<QString, QStringList> files;
        int checked = 0;
        for (const QJsonValue& step : doc.value(QStringLiteral("trace")).toArray()) {
            for (const QJsonValue& q : step.toObject().value(QStringLiteral("quantities")).toArray()) {
                const QJsonObject o = q.toObject();
                const QString problem = checkSource(o.value(QStringLiteral("source")).toString(), files);
                QVERIFY2(problem.isEmpty(), qPrintable(o.value(QStringLiteral("id")).toString() + QStringLiteral(": ") + problem));
                // The id is one of the catalogue's.
                QVERIFY(rbw::isQuantityId(o.value(QStringLiteral("id")).toString().toStdString()));
                ++checked;
            }
            for (const QJsonValue& c : step.toObject().value(QStringLiteral("contacts")).toArray()) {
                const QJsonObject sources = c.toObject().value(QStringLiteral("sources")).toObject();
                QVERIFY(!sources.isEmpty());
                for (auto it = sources.begin(); it != sources.end(); ++it) {
                    const QString problem = checkSource(it.value().toString(), files);
                    QVERIFY2(problem.isEmpty(), qPrintable(it.key() + QStringLiteral(": ") + problem));
                }
            }
        }
        QVERIFY(checked > 0);
    }

    // The collision numbers point into the impulse, the narrow phase and the stages, not
    // at one place that copies them: lesson 3's J comes from course/impulse.cpp and its
    // contact point from the SAT.
    void contactNumbersPointWhereComputed()
    {
        const rbw::test::RbwRun run = rbw::test::runRbw(
            {QStringLiteral("run"), QStringLiteral(RBW_SOURCE_DIR "/lessons/03-two-box-collision/scene.json"),
             QStringLiteral("--trace"), QStringLiteral("all"), QStringLiteral("--format"), QStringLiteral("json")});
        QCOMPARE(run.exitCode, 0);
        QString impulse, point;
        for (const QJsonValue& step : QJsonDocument::fromJson(run.out).object().value(QStringLiteral("trace")).toArray()) {
            for (const QJsonValue& c : step.toObject().value(QStringLiteral("contacts")).toArray()) {
                const QJsonObject s = c.toObject().value(QStringLiteral("sources")).toObject();
                impulse = s.value(QStringLiteral("impulse")).toString();
                point = s.value(QStringLiteral("point")).toString();
            }
        }
        QVERIFY2(impulse.startsWith(QStringLiteral("physics/engine/course/impulse.cpp:")), qPrintable(impulse));
        QVERIFY2(point.startsWith(QStringLiteral("physics/engine/course/box_box_sat.cpp:")), qPrintable(point));
    }

    // `rbw quantities --format json` lists the catalogue the trace points into, row by row.
    void quantitiesCommandListsTheCatalogue()
    {
        const rbw::test::RbwRun run =
            rbw::test::runRbw({QStringLiteral("quantities"), QStringLiteral("--format"), QStringLiteral("json")});
        QCOMPARE(run.exitCode, 0);
        const QJsonArray rows = QJsonDocument::fromJson(run.out).array();
        QCOMPARE(rows.size(), static_cast<qsizetype>(rbw::quantityCatalogue().size()));
        for (int i = 0; i < rows.size(); ++i) {
            const QJsonObject o = rows[i].toObject();
            QCOMPARE(o.value(QStringLiteral("key")).toString(), QString::fromLatin1(rbw::quantityCatalogue()[i].key));
            QCOMPARE(o.value(QStringLiteral("id")).toString(), QString::fromLatin1(rbw::quantityCatalogue()[i].id));
        }
    }

    // Negative controls: the check rejects what it must.
    void checkRejectsBadSources_data()
    {
        QTest::addColumn<QString>("source");
        QTest::newRow("absolute path") << QStringLiteral("/work/physics/engine/body.cpp:16");
        QTest::newRow("no such file") << QStringLiteral("physics/nope.cpp:1");
        QTest::newRow("past the end") << QStringLiteral("physics/engine/body.cpp:100000");
        QTest::newRow("blank or comment line") << QStringLiteral("physics/engine/body.cpp:1");
        QTest::newRow("not physics") << QStringLiteral("app/cli/main.cpp:10");
    }

    void checkRejectsBadSources()
    {
        QFETCH(QString, source);
        std::map<QString, QStringList> files;
        QVERIFY(!checkSource(source, files).isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestTraceSources)
#include "tst_trace_sources.moc"
