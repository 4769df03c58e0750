// The bad-input corpus (issue 13): every class of malformed or extreme input in
// tests/bad_inputs/corpus.json runs through the real rbw binary. Each class states the
// exit status (2 bad input, 3 a run that had to stop) and words its message must
// contain (the field's JSON path and the reason); no output of any run may contain a
// non-finite number (nan, inf, or a JSON null where a number belongs).
//
// docs/reliability.md carries the table of classes with the message each one prints,
// between the markers <!-- bad-input-table:begin --> and <!-- bad-input-table:end -->;
// this test builds that table from the real runs and requires the document to hold
// exactly it. To write it anew after a deliberate change of messages:
//   RBW_WRITE_RELIABILITY_TABLE=1 build/tests/tst_bad_inputs
#include "tests/support/pile_scene.h"
#include "tests/test_support.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QSaveFile>
#include <QTemporaryDir>
#include <QtTest>

namespace {

const QString kCorpus = QStringLiteral(RBW_SOURCE_DIR "/tests/bad_inputs/corpus.json");
const QString kDoc = QStringLiteral(RBW_SOURCE_DIR "/docs/reliability.md");
const QString kBegin = QStringLiteral("<!-- bad-input-table:begin -->");
const QString kEnd = QStringLiteral("<!-- bad-input-table:end -->");

QJsonObject corpus()
{
    QFile f(kCorpus);
    if (!f.open(QIODevice::ReadOnly)) qFatal("cannot read %s", qPrintable(kCorpus));
    return QJsonDocument::fromJson(f.readAll()).object();
}

QByteArray baseText()
{
    QFile f(QStringLiteral(RBW_SOURCE_DIR "/") + corpus().value(QStringLiteral("base")).toString());
    if (!f.open(QIODevice::ReadOnly)) qFatal("cannot read the corpus base scene");
    return f.readAll();
}

// Empty when no non-finite number is in the text: no nan/inf word, and in JSON no null
// except as the value of "body" (a world-level quantity has no body).
QString nonFinite(const QByteArray& out)
{
    static const QRegularExpression word(QStringLiteral("(?<![A-Za-z_])(-?nan|-?inf|-?infinity)(?![A-Za-z_])"),
                                         QRegularExpression::CaseInsensitiveOption);
    const QString text = QString::fromUtf8(out);
    const QRegularExpressionMatch m = word.match(text);
    if (m.hasMatch()) return QStringLiteral("\"%1\" in the output").arg(m.captured(1));
    QJsonParseError err;
    const QJsonDocument doc = QJsonDocument::fromJson(out, &err);
    if (err.error != QJsonParseError::NoError) return {};   // not JSON (CSV, text): the word check above
    QString problem;
    std::function<void(const QJsonValue&, const QString&)> walk = [&](const QJsonValue& v, const QString& key) {
        if (!problem.isEmpty()) return;
        if (v.isNull() && key != QLatin1String("body")) problem = QStringLiteral("null at \"%1\"").arg(key);
        if (v.isArray()) {
            for (const QJsonValue& e : v.toArray()) walk(e, key);
        }
        if (v.isObject()) {
            const QJsonObject o = v.toObject();
            for (auto it = o.begin(); it != o.end(); ++it) walk(it.value(), it.key());
        }
    };
    walk(doc.isArray() ? QJsonValue(doc.array()) : QJsonValue(doc.object()), QString());
    return problem;
}

struct Outcome {
    int exit = -1;
    QString message;   // stderr, temp paths replaced by "scene.json"
    QString problem;   // why the case itself is broken or its output not clean
};

// A manifold-model scene of n unit boxes, all at (0, 0.5, 0) on the ground.
QByteArray coincidentBoxes(int n)
{
    return QJsonDocument(rbw::test::pileScene({.boxes = n})).toJson();
}

Outcome runCase(const QJsonObject& c, const QByteArray& base, QTemporaryDir& dir, int n)
{
    Outcome o;
    const QString scene = dir.filePath(QStringLiteral("case-%1/scene.json").arg(n));
    QDir().mkpath(QFileInfo(scene).path());
    if (c.value(QStringLiteral("scene")).toBool(true)) {
        QByteArray text = c.contains(QStringLiteral("text")) ? c.value(QStringLiteral("text")).toString().toUtf8() : base;
        // "coincident_boxes": N unit boxes at one point, manifold model (issue 22: a pile
        // beyond the work limits, physics/engine/manifold/work_limits.h).
        if (c.contains(QStringLiteral("coincident_boxes"))) text = coincidentBoxes(c.value(QStringLiteral("coincident_boxes")).toInt());
        for (const QJsonValue& r : c.value(QStringLiteral("replace")).toArray()) {
            const QByteArray from = r.toArray().at(0).toString().toUtf8();
            if (!text.contains(from)) {
                o.problem = QStringLiteral("the base scene has no \"%1\"").arg(QString::fromUtf8(from));
                return o;
            }
            text.replace(from, r.toArray().at(1).toString().toUtf8());
        }
        QFile f(scene);
        if (!f.open(QIODevice::WriteOnly)) qFatal("cannot write %s", qPrintable(scene));
        f.write(text);
    }
    // "exercise": edits of lesson 1's exercise.json, written to {dir}/exercise.json
    // beside the scene, so {dir} is a lesson for rbw exercise (issue 22's holes).
    if (c.contains(QStringLiteral("exercise"))) {
        QFile in(QStringLiteral(RBW_SOURCE_DIR "/lessons/01-one-step/exercise.json"));
        if (!in.open(QIODevice::ReadOnly)) qFatal("cannot read lesson 1's exercise.json");
        QByteArray text = in.readAll();
        for (const QJsonValue& r : c.value(QStringLiteral("exercise")).toArray()) {
            const QByteArray from = r.toArray().at(0).toString().toUtf8();
            if (!text.contains(from)) {
                o.problem = QStringLiteral("lesson 1's exercise.json has no \"%1\"").arg(QString::fromUtf8(from));
                return o;
            }
            text.replace(from, r.toArray().at(1).toString().toUtf8());
        }
        QFile f(QFileInfo(scene).path() + QStringLiteral("/exercise.json"));
        if (!f.open(QIODevice::WriteOnly)) qFatal("cannot write exercise.json");
        f.write(text);
    }
    // "answers": the text of {dir}/answers.json, an answers file for rbw check.
    if (c.contains(QStringLiteral("answers"))) {
        QFile f(QFileInfo(scene).path() + QStringLiteral("/answers.json"));
        if (!f.open(QIODevice::WriteOnly)) qFatal("cannot write answers.json");
        f.write(c.value(QStringLiteral("answers")).toString().toUtf8());
    }
    QStringList args;
    for (const QJsonValue& a : c.value(QStringLiteral("args")).toArray()) args << a.toString();
    if (args.isEmpty()) args = {QStringLiteral("run"), QStringLiteral("{scene}")};
    for (QString& a : args) {
        a.replace(QStringLiteral("{scene}"), scene);
        a.replace(QStringLiteral("{dir}"), QFileInfo(scene).path());
    }
    // "stdout": a file standard output is redirected into (e.g. /dev/full, issue 22).
    const QString stdoutFile = c.value(QStringLiteral("stdout")).toString();
    rbw::test::RbwRun run;
    if (stdoutFile.isEmpty()) {
        run = rbw::test::runRbw(args);
    } else {
        QProcess p;
        p.setStandardOutputFile(stdoutFile);
        p.start(QStringLiteral(RBW_CLI_PATH), args);
        p.waitForFinished(120000);
        run = rbw::test::RbwRun{p.exitCode(), {}, QString::fromUtf8(p.readAllStandardError())};
    }
    o.exit = run.exitCode;
    o.message = run.err.trimmed();
    o.message.replace(scene, QStringLiteral("scene.json"));
    o.message.replace(QFileInfo(scene).path(), QStringLiteral("DIR"));
    const QString dirty = nonFinite(run.out);
    // A message may quote the input literal it rejects ("got NaN", "got -Infinity").
    QString err = run.err;
    err.remove(QRegularExpression(QStringLiteral("got -?(NaN|Infinity)")));
    const QString dirtyErr = nonFinite(err.toUtf8());
    if (!dirty.isEmpty()) o.problem = QStringLiteral("stdout: ") + dirty;
    if (!dirtyErr.isEmpty()) o.problem = QStringLiteral("stderr: ") + dirtyErr;
    return o;
}

QString tableRow(const QJsonObject& c, const Outcome& o)
{
    QString message = o.message.split(QLatin1Char('\n')).first();
    if (message.size() > 160) message = message.left(157) + QStringLiteral("…");
    message.replace(QLatin1Char('|'), QStringLiteral("\\|"));
    return QStringLiteral("| %1 | %2 | `%3` |").arg(c.value(QStringLiteral("class")).toString()).arg(o.exit).arg(message);
}

} // namespace

class TestBadInputs : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        base_ = baseText();
        cases_ = corpus().value(QStringLiteral("cases")).toArray();
        // At least 40 classes (issue 13), each with a distinct name.
        QVERIFY2(cases_.size() >= 40, qPrintable(QString::number(cases_.size())));
        QSet<QString> names;
        for (const QJsonValue& c : cases_) names.insert(c.toObject().value(QStringLiteral("class")).toString());
        QCOMPARE(names.size(), static_cast<qsizetype>(cases_.size()));
        // Negative control: the base scene itself runs cleanly, so each case fails for its edit.
        QJsonObject clean{{QStringLiteral("class"), QStringLiteral("base")}};
        const Outcome o = runCase(clean, base_, dir_, 0);
        QCOMPARE(o.exit, 0);
        QVERIFY2(o.problem.isEmpty(), qPrintable(o.problem));
    }

    void badInput_data()
    {
        QTest::addColumn<int>("i");
        for (int i = 0; i < cases_.size(); ++i) {
            QTest::newRow(qPrintable(cases_[i].toObject().value(QStringLiteral("class")).toString())) << i;
        }
    }

    void badInput()
    {
        QFETCH(int, i);
        const QJsonObject c = cases_[i].toObject();
        const Outcome o = runCase(c, base_, dir_, i + 1);
        rows_[i] = tableRow(c, o);
        QVERIFY2(o.problem.isEmpty(), qPrintable(o.problem + QStringLiteral("\n  message: ") + o.message));
        QVERIFY2(o.exit == c.value(QStringLiteral("exit")).toInt(),
                 qPrintable(QStringLiteral("exit %1, expected %2; message: %3")
                                .arg(o.exit)
                                .arg(c.value(QStringLiteral("exit")).toInt())
                                .arg(o.message)));
        for (const QJsonValue& w : c.value(QStringLiteral("words")).toArray()) {
            QVERIFY2(o.message.contains(w.toString()),
                     qPrintable(QStringLiteral("message lacks \"%1\": %2").arg(w.toString(), o.message)));
        }
    }

    // The document's table is the one these runs print.
    void reliabilityTableIsCurrent()
    {
        QStringList table{QStringLiteral("| class | exit | message (first line) |"),
                          QStringLiteral("| --- | ---: | --- |")};
        for (int i = 0; i < cases_.size(); ++i) {
            QVERIFY2(rows_.contains(i), "run the badInput rows first (the whole test)");
            table << rows_[i];
        }
        const QString expected = table.join(QLatin1Char('\n'));
        QFile f(kDoc);
        QVERIFY(f.open(QIODevice::ReadOnly | QIODevice::Text));
        QString doc = QString::fromUtf8(f.readAll());
        f.close();
        const int b = doc.indexOf(kBegin);
        const int e = doc.indexOf(kEnd);
        QVERIFY2(b >= 0 && e > b, "docs/reliability.md lacks the bad-input-table markers");
        const QString current = doc.mid(b + kBegin.size(), e - b - kBegin.size()).trimmed();
        if (qEnvironmentVariableIsSet("RBW_WRITE_RELIABILITY_TABLE") && current != expected) {
            doc.replace(b + kBegin.size(), e - b - kBegin.size(), QLatin1Char('\n') + expected + QLatin1Char('\n'));
            QSaveFile out(kDoc);
            QVERIFY(out.open(QIODevice::WriteOnly | QIODevice::Text));
            out.write(doc.toUtf8());
            QVERIFY(out.commit());
            return;
        }
        QVERIFY2(current == expected, qPrintable(QStringLiteral("docs/reliability.md's table is out of date; "
                                                                "expected:\n") + expected));
    }

    // Negative control for the scanner: it does see a non-finite number.
    void scannerSeesNonFinite_data()
    {
        QTest::addColumn<QByteArray>("out");
        QTest::newRow("csv nan") << QByteArray("step,x\n0,nan\n");
        QTest::newRow("csv inf") << QByteArray("step,x\n0,-inf\n");
        QTest::newRow("json null number") << QByteArray(R"({"total_energy": null})");
        QTest::newRow("json null in a vector") << QByteArray(R"({"value": [1, null, 2]})");
    }

    void scannerSeesNonFinite()
    {
        QFETCH(QByteArray, out);
        QVERIFY(!nonFinite(out).isEmpty());
        QVERIFY(nonFinite(R"({"body": null, "value": [1, 2, 3], "name": "infinite loop"})").isEmpty());
    }

private:
    QTemporaryDir dir_;
    QByteArray base_;
    QJsonArray cases_;
    QMap<int, QString> rows_;
};

QTEST_GUILESS_MAIN(TestBadInputs)
#include "tst_bad_inputs.moc"
