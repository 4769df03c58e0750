// rbw check through the real binary (issue 10): verdicts and mistakes of Table 2.1
// answers (hand numbers in tst_checker.cpp), exit 0 when every answer is correct, 1
// when one is not, 2 for bad answers files (the message names the file, the JSON path
// and the reason), and the CSV marking sheet with one row per file and answer.
#include "tests/test_support.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

namespace {

const QString kScene = QStringLiteral(RBW_SOURCE_DIR "/lessons/01-one-step/scene.json");
// Two bodies, "standard" with probe 0 and "template" with probe 1; 1000 steps.
const QString kConventions = QStringLiteral(RBW_SOURCE_DIR "/lessons/08-conventions/scene.json");

// All right to 4 significant figures.
const char* kRight = R"({ "step": 0, "answers": [
  { "quantity": "torque", "body": "box", "value": [-0.25, 0.25, -0.2] },
  { "quantity": "angular_momentum", "body": "box", "value": [-0.5, 0.5, -0.4] },
  { "quantity": "inverse_inertia_world", "body": "box", "value": [[4.8, 0, 0], [0, 9.836, 0], [0, 0, 4.412]] },
  { "quantity": "angular_velocity", "body": "box", "value": [-2.4, 4.918, -1.765] } ] })";

// x with the new v; omega with I0^-1 (the body frame).
// RFC 4180: fields split by commas, a quoted field may hold commas, line breaks and
// doubled quotes. The CSV's records, each its fields.
QList<QStringList> parseCsv(const QString& text)
{
    QList<QStringList> records;
    QStringList fields;
    QString field;
    bool quoted = false;
    for (qsizetype i = 0; i < text.size(); ++i) {
        const QChar c = text[i];
        if (quoted) {
            if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') field += '"', ++i;
            else if (c == '"') quoted = false;
            else field += c;
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            fields << field, field.clear();
        } else if (c == '\n') {
            fields << field, field.clear();
            records << fields, fields.clear();
        } else {
            field += c;
        }
    }
    if (!field.isEmpty() || !fields.isEmpty()) records << (fields << field);
    return records;
}

const char* kWrong = R"({ "step": 0, "answers": [
  { "quantity": "position", "body": "box", "value": [2, 2, 0] },
  { "quantity": "angular_velocity", "body": "box", "value": [-4.918, 2.4, -1.765] } ] })";

} // namespace

class TestCheckCli : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QVERIFY(dir_.isValid()); }

    void rightAnswersExitZero()
    {
        const rbw::test::RbwRun r = rbw::test::runRbw({"check", kScene, write("right.json", kRight), "--format", "json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonArray results = QJsonDocument::fromJson(r.out).object().value("results").toArray();
        QCOMPARE(results.size(), 4);
        for (const QJsonValue& v : results) {
            QCOMPARE(v.toObject().value("verdict").toString(), QStringLiteral("correct"));
            QVERIFY(v.toObject().value("mistakes").toArray().isEmpty());
        }
    }

    void wrongAnswersNameMistakes()
    {
        const rbw::test::RbwRun r = rbw::test::runRbw({"check", kScene, write("wrong.json", kWrong), "--format", "json"});
        QCOMPARE(r.exitCode, 1);
        const QJsonArray results = QJsonDocument::fromJson(r.out).object().value("results").toArray();
        QCOMPARE(results.size(), 2);
        const QJsonObject x = results[0].toObject();
        QCOMPARE(x.value("verdict").toString(), QStringLiteral("wrong"));
        QCOMPARE(x.value("expected").toArray(), (QJsonArray{0, 0, 0}));
        QCOMPARE(x.value("given").toArray(), (QJsonArray{2, 2, 0}));
        QVERIFY(x.value("mistakes").toArray().contains(QStringLiteral("velocity-before-position")));
        // omega alone: several mistakes give it (issue 21), so it is only possible.
        QVERIFY(results[1].toObject().value("possible_mistakes").toArray().contains(
            QJsonObject{{"id", "body-inverse-inertia"}, {"reason", "several mistakes give this number"}}));
    }

    // --step overrides the file's step. In step 1 of lesson 1 no force acts: L stays
    // (-0.5, 0.5, -0.4), but the box has turned, so omega is no longer step 0's.
    // Lesson 1 has "steps": 1, so step 1 is checked in a copy with "steps": 2.
    void stepOption()
    {
        const char* text = R"({ "step": 0, "answers": [
          { "quantity": "angular_momentum", "body": "box", "value": [-0.5, 0.5, -0.4] },
          { "quantity": "angular_velocity", "body": "box", "value": [-2.4, 4.918, -1.765] } ] })";
        const QString path = write("step.json", text);
        QCOMPARE(rbw::test::runRbw({"check", kScene, path}).exitCode, 0);
        const QString twoSteps = sceneWithSteps(2);
        const rbw::test::RbwRun r = rbw::test::runRbw({"check", twoSteps, path, "--step", "1", "--format", "json"});
        QCOMPARE(r.exitCode, 1);
        const QJsonObject doc = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(doc.value("step").toInt(), 1);
        QCOMPARE(doc.value("results").toArray()[0].toObject().value("verdict").toString(), QStringLiteral("correct"));
        QCOMPARE(doc.value("results").toArray()[1].toObject().value("verdict").toString(), QStringLiteral("wrong"));
    }

    void markingSheet()
    {
        const rbw::test::RbwRun r = rbw::test::runRbw(
            {"check", kScene, write("a.json", kRight), write("b.json", kWrong), "--format", "csv"});
        QCOMPARE(r.exitCode, 1);
        const QStringList lines = QString::fromUtf8(r.out).trimmed().split('\n');
        QCOMPARE(lines.size(), 1 + 4 + 2);   // header, 4 answers of a, 2 of b
        QVERIFY(lines[0].startsWith(QStringLiteral("file,step,quantity,body,contact,index,verdict")));
        QVERIFY(lines[1].contains(QStringLiteral("a.json")) && lines[1].contains(QStringLiteral(",correct,")));
        QVERIFY(lines[5].contains(QStringLiteral("b.json")) && lines[5].contains(QStringLiteral(",wrong,")) &&
                lines[5].contains(QStringLiteral("velocity-before-position")));
    }

    // CSV quotes any field with a comma, a quote or a line break (RFC 4180, issue 22):
    // a file name with a line break (and no comma or quote, which were quoted before)
    // is one quoted field, once per answer (4 of kRight). Control: a plain name is not
    // quoted.
    void csvQuotesLineBreaks()
    {
        const QString odd = write(QStringLiteral("odd\nline.json"), kRight);
        const rbw::test::RbwRun r = rbw::test::runRbw({"check", kScene, odd, "--format", "csv"});
        QCOMPARE(r.exitCode, 0);
        const QString quoted = QLatin1Char('"') + odd + QStringLiteral("\",0,");
        QCOMPARE(QString::fromUtf8(r.out).count(quoted), 4);
        const rbw::test::RbwRun plain = rbw::test::runRbw({"check", kScene, write("plain.json", kRight), "--format", "csv"});
        QCOMPARE(QString::fromUtf8(plain.out).count(dir_.filePath("plain.json") + QStringLiteral(",0,")), 4);
    }

    // A body's name with a line break, a comma or quotes is one quoted field (issue 22,
    // "CSV always quoted"): the marking sheet reads back (RFC 4180) as a header and one
    // record of 12 fields whose body is the name exactly. Control: a plain name is
    // written bare.
    void csvQuotesBodyNames_data()
    {
        QTest::addColumn<QString>("name");
        QTest::newRow("line break") << QStringLiteral("box\nsecond line");
        QTest::newRow("comma") << QStringLiteral("box, the first");
        QTest::newRow("quotes") << QStringLiteral("the \"box\"");
        QTest::newRow("all three") << QStringLiteral("a,\"b\"\r\nc");
        QTest::newRow("plain (control)") << QStringLiteral("box");
    }
    void csvQuotesBodyNames()
    {
        QFETCH(QString, name);
        QFile lesson(kScene);
        QVERIFY(lesson.open(QIODevice::ReadOnly));
        QJsonObject scene = QJsonDocument::fromJson(lesson.readAll()).object();
        const auto rename = [&](const char* key) {
            QJsonArray list = scene.value(key).toArray();
            for (qsizetype i = 0; i < list.size(); ++i) {
                QJsonObject o = list[i].toObject();
                o[key == QByteArray("bodies") ? "name" : "body"] = name;
                list[i] = o;
            }
            scene[key] = list;
        };
        rename("bodies");
        rename("forces");
        rename("probes");
        const QString scenePath = write(QStringLiteral("named.json"), QJsonDocument(scene).toJson());
        const QJsonObject answer{{"quantity", "torque"}, {"body", name}, {"value", QJsonArray{-0.25, 0.25, -0.2}}};
        const QString answers = write(QStringLiteral("named-answers.json"),
                                      QJsonDocument(QJsonObject{{"step", 0}, {"answers", QJsonArray{answer}}}).toJson());
        const rbw::test::RbwRun r = rbw::test::runRbw({"check", scenePath, answers, "--format", "csv"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QList<QStringList> records = parseCsv(QString::fromUtf8(r.out));
        QCOMPARE(records.size(), 2);
        QCOMPARE(records[0].size(), 12);
        QCOMPARE(records[0][3], QStringLiteral("body"));
        QCOMPARE(records[1].size(), 12);
        QCOMPARE(records[1][3], name);
        QCOMPARE(records[1][2], QStringLiteral("torque"));
        const bool needsQuotes = name.contains(',') || name.contains('"') || name.contains('\n') || name.contains('\r');
        QCOMPARE(QString::fromUtf8(r.out).contains(QStringLiteral(",torque,") + name + QStringLiteral(",")), !needsQuotes);
    }

    void badAnswers_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("words");
        QTest::newRow("malformed JSON") << QByteArray("{ \"answers\": [ ") << "malformed JSON";
        QTest::newRow("unknown quantity") << QByteArray(R"({"answers": [{"quantity": "omega", "body": "box", "value": 1}]})")
                                          << "answers[0].quantity: unknown quantity \"omega\"";
        QTest::newRow("unknown body") << QByteArray(R"({"answers": [{"quantity": "torque", "body": "ghost", "value": [1, 2, 3]}]})")
                                      << "answers[0].body: no body named \"ghost\"";
        QTest::newRow("wrong shape") << QByteArray(R"({"answers": [{"quantity": "torque", "body": "box", "value": 1}]})")
                                     << "answers[0]: \"torque\" is a vector of 3 numbers, got 1 numbers";
        QTest::newRow("matrix of 2 rows") << QByteArray(R"({"answers": [{"quantity": "rotation_matrix", "body": "box", "value": [[1, 0, 0], [0, 1, 0]]}]})")
                                          << "answers[0].value: a matrix must have 3 rows, got 2";
        QTest::newRow("unknown key") << QByteArray(R"({"answers": [{"quantity": "torque", "bdy": "box", "value": [1, 2, 3]}]})")
                                     << "answers[0].bdy: unknown key";
        QTest::newRow("no contact in step") << QByteArray(R"({"answers": [{"quantity": "impulse", "contact": 0, "value": 1}]})")
                                            << "answers[0]: no contact 0 in step 0";
        QTest::newRow("negative step") << QByteArray(R"({"step": -1, "answers": []})") << "step: must be a whole number";
    }

    void badAnswers()
    {
        QFETCH(QByteArray, text);
        QFETCH(QString, words);
        const QString path = write("bad.json", text);
        const rbw::test::RbwRun r = rbw::test::runRbw({"check", kScene, path});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(words), qPrintable(r.err));
        QVERIFY2(r.err.contains(path) || r.err.contains(QStringLiteral("bad.json")), qPrintable(r.err));
        // The marking sheet keeps the file: one row with its error (issue 21 item 7).
        QVERIFY2(r.out.startsWith("bad.json: NOT CHECKED: "), r.out.constData());
        QVERIFY2(QString::fromUtf8(r.out).contains(words), r.out.constData());
    }

    // Marking sheets never lose a student (issue 21 item 7): a broken file, an empty
    // file and three good ones give one row each (the good ones one per answer), the
    // sheet goes on past the bad ones, and the exit status is 2 at the end.
    //   a.json: kRight, 4 correct.
    //   b.json: kWrong, 2 wrong (x with the new v; omega with I0^-1).
    //   c.json: torque right, and I0 to 3 significant figures: M/12 diag(b²+c², a²+c², a²+b²)
    //           = diag(0.101667, 0.208333, 0.226667) written 0.102, 0.208, 0.227, off by
    //           0.15 % of the largest, more than the 0.1 % tolerance: 1 correct, 1 imprecise.
    void markingSheetKeepsEveryFile()
    {
        const char* third = R"({ "step": 0, "answers": [
          { "quantity": "torque", "body": "box", "value": [-0.25, 0.25, -0.2] },
          { "quantity": "inertia_body", "body": "box", "value": [[0.102, 0, 0], [0, 0.208, 0], [0, 0, 0.227]] } ] })";
        const QStringList files = {write("broken.json", "{ \"answers\": [ "), write("empty.json", ""),
                                   write("a.json", kRight), write("b.json", kWrong), write("c.json", third)};
        const rbw::test::RbwRun csv = rbw::test::runRbw(QStringList{"check", kScene} + files + QStringList{"--format", "csv"});
        QCOMPARE(csv.exitCode, 2);
        const QStringList lines = QString::fromUtf8(csv.out).trimmed().split('\n');
        QCOMPARE(lines.size(), 1 + 1 + 1 + 4 + 2 + 2);
        QCOMPARE(lines[0], QStringLiteral("file,step,quantity,body,contact,index,verdict,expected,given,mistakes,score,error"));
        QVERIFY2(lines[1].startsWith(files[0] + ",,,,,,error,") && lines[1].contains("malformed JSON"), qPrintable(lines[1]));
        QVERIFY2(lines[2].startsWith(files[1] + ",,,,,,error,") && lines[2].contains("the file is empty"), qPrintable(lines[2]));
        const QString scoreA = QStringLiteral(",\"4 correct, 0 imprecise, 0 follows, 0 wrong\",");
        const QString scoreB = QStringLiteral(",\"0 correct, 0 imprecise, 0 follows, 2 wrong\",");
        const QString scoreC = QStringLiteral(",\"1 correct, 1 imprecise, 0 follows, 0 wrong\",");
        for (int i = 3; i < 7; ++i) QVERIFY2(lines[i].startsWith(files[2]) && lines[i].endsWith(scoreA), qPrintable(lines[i]));
        for (int i = 7; i < 9; ++i) QVERIFY2(lines[i].startsWith(files[3]) && lines[i].endsWith(scoreB), qPrintable(lines[i]));
        for (int i = 9; i < 11; ++i) QVERIFY2(lines[i].startsWith(files[4]) && lines[i].endsWith(scoreC), qPrintable(lines[i]));
        QVERIFY(lines[10].contains(",imprecise,"));
        // Both errors on stderr too.
        QVERIFY(csv.err.contains("malformed JSON") && csv.err.contains("the file is empty"));

        // Text and JSON keep every file as well.
        const rbw::test::RbwRun text = rbw::test::runRbw(QStringList{"check", kScene} + files);
        QCOMPARE(text.exitCode, 2);
        const QString t = QString::fromUtf8(text.out);
        QVERIFY(t.contains("broken.json: NOT CHECKED: ") && t.contains("empty.json: NOT CHECKED: "));
        QCOMPARE(t.count("  score: "), 3);
        QVERIFY(t.contains("  score: 1 correct, 1 imprecise, 0 follows, 0 wrong\n"));
        const rbw::test::RbwRun json = rbw::test::runRbw(QStringList{"check", kScene} + files + QStringList{"--format", "json"});
        QCOMPARE(json.exitCode, 2);
        const QJsonArray all = QJsonDocument::fromJson(json.out).array();
        QCOMPARE(all.size(), 5);
        QVERIFY(all[1].toObject().value("error").toString().contains("the file is empty"));
        QCOMPARE(all[4].toObject().value("score").toObject(),
                 (QJsonObject{{"correct", 1}, {"imprecise", 1}, {"follows", 0}, {"wrong", 0}}));
        // Negative control: the three good files alone exit 1 (b is wrong), not 2.
        QCOMPARE(rbw::test::runRbw(QStringList{"check", kScene} + files.mid(2)).exitCode, 1);
    }

    // Input slips get a hint (issue 21 item 6); the exit status stays 2.
    void inputSlips_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("words");
        // Lesson 1 has one step, step 0: a student who counts from 1 writes step 1.
        QTest::newRow("step counted from 1") << kScene << QByteArray(R"({"step": 1, "answers": [{"quantity": "torque", "value": [-0.25, 0.25, -0.2]}]})")
                                             << "step: step 1 is beyond the scene's 1 steps (the last is step 0); steps count from 0: did you mean step 0?";
        // Refused at once, before any simulation (10^9 steps would take minutes).
        QTest::newRow("step far beyond") << kScene << QByteArray(R"({"step": 1000000000, "answers": [{"quantity": "torque", "value": [1, 2, 3]}]})")
                                         << "step 1000000000 is beyond the scene's 1 steps";
        QTest::newRow("decimal commas") << kScene << QByteArray(R"({"answers": [{"quantity": "torque", "value": [-0,25, 0,25, -0,2]}]})")
                                        << "got 6 (decimal commas? use a decimal point";
        QTest::newRow("decimal comma in a string") << kScene << QByteArray(R"({"answers": [{"quantity": "torque", "value": "-0,25"}]})")
                                                   << "use a decimal point";
        QTest::newRow("probe index missing") << kScene << QByteArray(R"({"answers": [{"quantity": "point_velocity", "value": [1, 2, 3]}]})")
                                             << "it needs \"index\": the probes of box are 0, 1";
        QTest::newRow("probe index per body") << kConventions << QByteArray(R"({"answers": [{"quantity": "point_velocity", "body": "template", "index": 0, "value": [1, 2, 3]}]})")
                                              << "not per body: the probes of template are 1";
        QTest::newRow("no answers") << kScene << QByteArray(R"({"answers": []})") << "answers: there are no answers";
        QTest::newRow("duplicate key") << kScene << QByteArray(R"({"answers": [{"quantity": "torque", "value": [1, 2, 3], "value": [-0.25, 0.25, -0.2]}]})")
                                       << "answers[0].value: duplicate key \"value\" (first at line 1";
        QTest::newRow("duplicate step") << kScene << QByteArray(R"({"step": 0, "step": 0, "answers": [{"quantity": "torque", "value": [1, 2, 3]}]})")
                                        << ": duplicate key \"step\"";
        QTest::newRow("control bytes escaped") << kScene << QByteArray("{\"answers\": [{\"quantity\": \"tor\\u0007que\\nx\", \"value\": 1}]}")
                                               << "unknown quantity \"tor\\x07que\\nx\"";
        QTest::newRow("long id cut") << kScene << (QByteArray(R"({"answers": [{"quantity": ")") + QByteArray(5000, 'q') + QByteArray(R"(", "value": 1}]})"))
                                     << QString(80, QLatin1Char('q')) + QChar(0x2026) + QLatin1Char('"');
    }

    void inputSlips()
    {
        QFETCH(QString, scene);
        QFETCH(QByteArray, text);
        QFETCH(QString, words);
        const rbw::test::RbwRun r = rbw::test::runRbw({"check", scene, write("slip.json", text)});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(words), qPrintable(r.err));
        QVERIFY2(r.err.size() < 2000, "a message stays short");
        QVERIFY2(!r.err.contains(QChar(7)), "no raw control byte");
    }

    // A slip the checker sees only in the numbers: the orientation of lesson 1 is 90°
    // about z, r = (cos 45°, 0, 0, sin 45°) = (0.7071068, 0, 0, 0.7071068), unchanged in
    // the step (explicit Euler turns with the old omega = 0). Written [x, y, z, w] =
    // [0, 0, 0.7071068, 0.7071068] it is wrong, with the hint; the right order gets none.
    void quaternionOrderHint()
    {
        const rbw::test::RbwRun r = rbw::test::runRbw({"check", kScene,
            write("xyzw.json", R"({"answers": [{"quantity": "orientation", "value": [0, 0, 0.7071068, 0.7071068]}]})"), "--format", "json"});
        QCOMPARE(r.exitCode, 1);
        const QJsonObject o = QJsonDocument::fromJson(r.out).object().value("results").toArray()[0].toObject();
        QCOMPARE(o.value("verdict").toString(), QStringLiteral("wrong"));
        QVERIFY2(o.value("hint").toString().contains("quaternions are [w, x, y, z]"), r.out.constData());
        const rbw::test::RbwRun right = rbw::test::runRbw({"check", kScene,
            write("wxyz.json", R"({"answers": [{"quantity": "orientation", "value": [0.7071068, 0, 0, 0.7071068]}]})"), "--format", "json"});
        QCOMPARE(right.exitCode, 0);
        QVERIFY(!QJsonDocument::fromJson(right.out).object().value("results").toArray()[0].toObject().contains("hint"));
    }

    // Steps counted from 1 in a scene that has the step: lesson 1's Table 2.1 answers
    // (step 0's) given as step 1 of a two-step copy are not all right there (no force
    // acts in step 1: L stays and is right, but the box has turned, so I^-1 and omega
    // are not step 0's), and every one is right in step 0:
    // the hint says so. Control: given as step 0, no hint.
    void stepCountedFromOneHint()
    {
        const QString twoSteps = sceneWithSteps(2);
        // kRight without the torque (the trace of step 1 has none: no force acts).
        const QByteArray text = R"({ "step": 1, "answers": [
          { "quantity": "angular_momentum", "body": "box", "value": [-0.5, 0.5, -0.4] },
          { "quantity": "inverse_inertia_world", "body": "box", "value": [[4.8, 0, 0], [0, 9.836, 0], [0, 0, 4.412]] },
          { "quantity": "angular_velocity", "body": "box", "value": [-2.4, 4.918, -1.765] } ] })";
        const rbw::test::RbwRun r = rbw::test::runRbw({"check", twoSteps, write("from1.json", text), "--format", "json"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(QJsonDocument::fromJson(r.out).object().value("hint").toString().contains(
                     "steps count from 0: did you mean step 0?"), r.out.constData());
        QByteArray step0 = text;
        step0.replace("\"step\": 1", "\"step\": 0");
        const rbw::test::RbwRun control = rbw::test::runRbw({"check", twoSteps, write("from0.json", step0), "--format", "json"});
        QCOMPARE(control.exitCode, 0);
        QVERIFY(!QJsonDocument::fromJson(control.out).object().contains("hint"));
    }

    // At most 1 MiB is read from any input file (docs/checker.md): /dev/zero ends.
    void inputSizeLimited()
    {
        const rbw::test::RbwRun zero = rbw::test::runRbw({"check", kScene, "/dev/zero"});
        QCOMPARE(zero.exitCode, 2);
        QVERIFY2(zero.err.contains("/dev/zero: larger than 1048576 bytes"), qPrintable(zero.err));
        const rbw::test::RbwRun scene = rbw::test::runRbw({"check", "/dev/zero", write("a.json", kRight)});
        QCOMPARE(scene.exitCode, 2);
        QVERIFY2(scene.err.contains("/dev/zero: larger than 1048576 bytes"), qPrintable(scene.err));
    }

private:
    // Lesson 1 with "steps": n.
    QString sceneWithSteps(int n)
    {
        QFile f(kScene);
        if (!f.open(QIODevice::ReadOnly)) qFatal("cannot read lesson 1");
        QByteArray text = f.readAll();
        if (!text.contains("\"steps\": 1,")) qFatal("lesson 1 changed");
        text.replace("\"steps\": 1,", "\"steps\": " + QByteArray::number(n) + ",");
        return write(QStringLiteral("steps%1.json").arg(n), text);
    }
    QString write(const QString& name, const QByteArray& text)
    {
        const QString path = dir_.filePath(name);
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly)) qFatal("cannot write");
        f.write(text);
        return path;
    }
    QTemporaryDir dir_;
};

QTEST_GUILESS_MAIN(TestCheckCli)
#include "tst_check_cli.moc"
