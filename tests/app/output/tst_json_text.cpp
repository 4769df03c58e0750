// The one JSON text writer (app/output/json_text.h) against Qt's own: appendIndented()
// at depth 0 is QJsonDocument::toJson(Indented) without its last newline, byte for byte,
// for nested, empty and escaped values; deeper, it is that text with every line after
// the first indented four spaces a level (what JsonRunWriter used to do by editing the
// text); oneLine() and sceneFileText() keep their layouts.
#include "app/output/json_text.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QtTest>

using namespace rbw;

class TestJsonText : public QObject {
    Q_OBJECT
private slots:
    void indentedIsQtsLayout_data();
    void indentedIsQtsLayout();
    void oneLineAndSceneLayout();
};

void TestJsonText::indentedIsQtsLayout_data()
{
    QTest::addColumn<QJsonObject>("object");
    QTest::newRow("empty") << QJsonObject{};
    QTest::newRow("scalars") << QJsonObject{{"dt", 0.01}, {"n", qint64(3)}, {"ok", true}, {"none", QJsonValue()}};
    QTest::newRow("escaped") << QJsonObject{{"a \"b\"\n", QStringLiteral("ω \\ \t")}};
    QTest::newRow("empty lists") << QJsonObject{{"contacts", QJsonArray{}}, {"start", QJsonObject{}}};
    QTest::newRow("nested") << QJsonObject{
        {"trace", QJsonArray{QJsonObject{{"x", QJsonArray{1.5, -0.25, 1e-300}}, {"m", QJsonArray{QJsonArray{1, 0}, QJsonArray{}}}},
                             QJsonObject{}}},
        {"step", 7}};
}

void TestJsonText::indentedIsQtsLayout()
{
    QFETCH(QJsonObject, object);
    QByteArray qt = QJsonDocument(object).toJson(QJsonDocument::Indented);
    qt.chop(1);   // its last newline
    QByteArray ours;
    jsontext::appendIndented(ours, object, 0);
    QCOMPARE(ours, qt);
    // Two levels in: Qt's text with each later line 8 spaces further in.
    QByteArray deeper;
    jsontext::appendIndented(deeper, object, 2);
    QCOMPARE(deeper, QByteArray(qt).replace("\n", "\n        "));
    // The members alone: the text between "{\n" and "\n}" (nothing when empty).
    const QByteArray members = jsontext::indentedMembers(object, 1);
    QCOMPARE(members, object.isEmpty() ? QByteArray() : qt.mid(2, qt.size() - 4));
}

void TestJsonText::oneLineAndSceneLayout()
{
    const QJsonObject body{{"name", "box"}, {"position", QJsonArray{0, 1.5, -2}}, {"mass", 2}};
    QCOMPARE(jsontext::oneLine(body), QByteArray("{ \"mass\": 2, \"name\": \"box\", \"position\": [0, 1.5, -2] }"));
    QCOMPARE(jsontext::scalar(QStringLiteral("a\"b")), QByteArray("\"a\\\"b\""));
    const QJsonObject scene{{"dt", 0.1}, {"bodies", QJsonArray{body}}, {"name", "S"}, {"description", "d"}};
    // name and description first (at every level: the body's name too), number arrays on one line.
    QCOMPARE(jsontext::sceneFileText(scene, {"name", "description"}),
             QByteArray("{\n"
                        "  \"name\": \"S\",\n"
                        "  \"description\": \"d\",\n"
                        "  \"bodies\": [\n"
                        "    {\n"
                        "      \"name\": \"box\",\n"
                        "      \"mass\": 2,\n"
                        "      \"position\": [0, 1.5, -2]\n"
                        "    }\n"
                        "  ],\n"
                        "  \"dt\": 0.1\n"
                        "}\n"));
    // Negative control: without first keys the order is Qt's (sorted), so the text differs.
    QVERIFY(jsontext::sceneFileText(scene, {}) != jsontext::sceneFileText(scene, {"name", "description"}));
}


QTEST_GUILESS_MAIN(TestJsonText)
#include "tst_json_text.moc"
