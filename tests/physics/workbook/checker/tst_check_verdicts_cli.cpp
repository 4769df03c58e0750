// The verdicts of issue 21 through the real rbw binary: an answer right to 3 significant
// figures is "imprecise" and exits 0 (tst_checker's hand numbers), and a number several
// mistakes give lists them under "possible_mistakes" with their reasons (tst_diagnosis).
#include "tests/test_support.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

namespace {

const QString kScene = QStringLiteral(RBW_SOURCE_DIR "/lessons/01-one-step/scene.json");

// v_p = (3.111861, 1.070588, -2.675410) and I0 = diag(0.1016667, 0.2083333, 0.2266667)
// to 3 significant figures. (In the other order v_p would be computed from the 3-figure
// I0, whose rounding it inherits: correct up to the rounding of the earlier answers.)
const char* kThreeFigures = R"({ "step": 0, "answers": [
  { "quantity": "point_velocity", "body": "box", "index": 1, "value": [3.11, 1.07, -2.68] },
  { "quantity": "inertia_body", "body": "box", "value": [[0.102, 0, 0], [0, 0.208, 0], [0, 0, 0.227]] } ] })";

// The same v_p wrong in its third figure.
const char* kThirdFigureWrong = R"({ "step": 0, "answers": [
  { "quantity": "point_velocity", "body": "box", "index": 1, "value": [3.12, 1.07, -2.68] } ] })";

// omega' = I0^-1 L' alone: body-inverse-inertia, a quaternion without the half angle and
// swapped I0 axes all give it.
const char* kBodyFrameOmega = R"({ "step": 0, "answers": [
  { "quantity": "angular_velocity", "body": "box", "value": [-4.918, 2.4, -1.765] } ] })";

} // namespace

class TestCheckVerdictsCli : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QVERIFY(dir_.isValid()); }

    void threeFiguresAreImpreciseAndExitZero()
    {
        const QString path = write("three.json", kThreeFigures);
        const rbw::test::RbwRun r = rbw::test::runRbw({"check", kScene, path, "--format", "json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonArray results = QJsonDocument::fromJson(r.out).object().value("results").toArray();
        QCOMPARE(results.size(), 2);
        for (const QJsonValue& v : results) {
            QCOMPARE(v.toObject().value("verdict").toString(), QStringLiteral("imprecise"));
            QVERIFY(v.toObject().value("mistakes").toArray().isEmpty());
        }
        const rbw::test::RbwRun text = rbw::test::runRbw({"check", kScene, path});
        QCOMPARE(text.exitCode, 0);
        QVERIFY2(text.out.contains("right to 3 significant figures; write 4 for the check") ||
                     text.out.contains("Right to 3 significant figures; write 4 for the check"),
                 text.out.constData());
        // Negative control: wrong in the third figure is wrong, exit 1.
        const rbw::test::RbwRun wrong = rbw::test::runRbw({"check", kScene, write("w.json", kThirdFigureWrong), "--format", "json"});
        QCOMPARE(wrong.exitCode, 1);
        QCOMPARE(QJsonDocument::fromJson(wrong.out).object().value("results").toArray()[0].toObject().value("verdict").toString(),
                 QStringLiteral("wrong"));
    }

    // Lesson 6, step 33: contact 0 separates (v_rel.n > 0), so no impulse: J = 0 is right.
    void separatingContactJZero()
    {
        const QString scene = QStringLiteral(RBW_SOURCE_DIR "/lessons/06-box-on-plane/scene.json");
        const QString path = write("j0.json", R"({ "step": 33, "answers": [
          { "quantity": "impulse", "contact": 0, "value": 0 } ] })");
        const rbw::test::RbwRun r = rbw::test::runRbw({"check", scene, path, "--format", "json"});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(QJsonDocument::fromJson(r.out).object().value("results").toArray()[0].toObject().value("verdict").toString(),
                 QStringLiteral("correct"));
    }

    void possibleMistakesInJson()
    {
        const rbw::test::RbwRun r = rbw::test::runRbw({"check", kScene, write("omega.json", kBodyFrameOmega), "--format", "json"});
        QCOMPARE(r.exitCode, 1);
        const QJsonObject o = QJsonDocument::fromJson(r.out).object().value("results").toArray()[0].toObject();
        QCOMPARE(o.value("verdict").toString(), QStringLiteral("wrong"));
        QVERIFY(o.value("mistakes").toArray().isEmpty());
        QStringList ids;
        for (const QJsonValue& p : o.value("possible_mistakes").toArray()) {
            ids << p.toObject().value("id").toString();
            QVERIFY(!p.toObject().value("reason").toString().isEmpty());
        }
        for (const char* id : {"body-inverse-inertia", "quaternion-without-half-angle", "inertia-axes-swapped"}) {
            QVERIFY2(ids.contains(QString::fromLatin1(id)), qPrintable(ids.join(',')));
        }
        QVERIFY(o.value("explanation").toString().startsWith("Several mistakes give this number: "));
    }

private:
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

QTEST_GUILESS_MAIN(TestCheckVerdictsCli)
#include "tst_check_verdicts_cli.moc"
