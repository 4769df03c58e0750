// What a student types into "Check my numbers" (app/exercise/answer_parser.h): every form
// the parser accepts, with the numbers it must give (written out by hand below), and
// every form it refuses, with its message.
#include "app/exercise/answer_parser.h"

#include <QtTest>

#include <vector>

using namespace rbw;

Q_DECLARE_METATYPE(std::vector<double>)

class TestAnswerParser : public QObject {
    Q_OBJECT
private slots:
    void accepted_data();
    void accepted();
    void rejected_data();
    void rejected();
    void roundTrip_data();
    void roundTrip();
};

void TestAnswerParser::accepted_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("count");
    QTest::addColumn<std::vector<double>>("expected");
    // Table 2.1's omega' = (-2.4, 4.918, -1.765) written the usual ways.
    const std::vector<double> omega{-2.4, 4.918, -1.765};
    QTest::newRow("parentheses") << "(-2.4, 4.918, -1.765)" << 3 << omega;
    QTest::newRow("blanks") << "-2.4 4.918 -1.765" << 3 << omega;
    QTest::newRow("commas") << "-2.4, 4.918, -1.765" << 3 << omega;
    QTest::newRow("square brackets, tabs") << "[-2.4\t4.918\t-1.765]" << 3 << omega;
    QTest::newRow("unicode minus") << QString::fromUtf8("(\u22122.4, 4.918, \u22121.765)") << 3 << omega;
    QTest::newRow("exponent") << "1e-3, -2.5E2, +.5" << 3 << std::vector<double>{0.001, -250.0, 0.5};
    // Lesson 3's J = 64/27, and fractions in any component: -5/27, 1/2 = 0.5, 3/4 = 0.75.
    QTest::newRow("fraction") << "64/27" << 1 << std::vector<double>{64.0 / 27.0};
    QTest::newRow("negative fraction") << "-5/27" << 1 << std::vector<double>{-5.0 / 27.0};
    QTest::newRow("spaced fraction") << "64 / 27" << 1 << std::vector<double>{64.0 / 27.0};
    QTest::newRow("fractions in a vector") << "(1/2, -5/27, 3/4)" << 3 << std::vector<double>{0.5, -5.0 / 27.0, 0.75};
    QTest::newRow("scalar") << "2.37" << 1 << std::vector<double>{2.37};
    // A matrix, row by row: rows separated by semicolons, line breaks or brackets.
    const std::vector<double> m{4.8, 0, 0, 0, 9.836, 0, 0, 0, 4.412};
    QTest::newRow("matrix, semicolons") << "4.8 0 0; 0 9.836 0; 0 0 4.412" << 9 << m;
    QTest::newRow("matrix, three lines") << "4.8 0 0\n0 9.836 0\n0 0 4.412" << 9 << m;
    QTest::newRow("matrix, bracketed rows") << "[[4.8, 0, 0], [0, 9.836, 0], [0, 0, 4.412]]" << 9 << m;
    // A quaternion [w x y z]: the identity, and 90 degrees about z = [cos 45, 0, 0, sin 45].
    QTest::newRow("quaternion") << "[1 0 0 0]" << 4 << std::vector<double>{1, 0, 0, 0};
    QTest::newRow("quaternion, commas") << "[0.7071, 0, 0, 0.7071]" << 4 << std::vector<double>{0.7071, 0, 0, 0.7071};
}

void TestAnswerParser::accepted()
{
    QFETCH(QString, text);
    QFETCH(int, count);
    QFETCH(std::vector<double>, expected);
    const ParsedAnswer r = parseAnswerText(text, count);
    QVERIFY2(r.ok(), qPrintable(r.error));
    QCOMPARE(r.values.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) QCOMPARE(r.values[i], expected[i]);
}

void TestAnswerParser::rejected_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("count");
    QTest::addColumn<QString>("message");
    QTest::newRow("too few") << "(-2.4, 4.918)" << 3 << "3 numbers expected, got 2";
    QTest::newRow("too many") << "1 2 3 4" << 3 << "3 numbers expected, got 4";
    QTest::newRow("vector for a number") << "1 2 3" << 1 << "1 number expected, got 3";
    QTest::newRow("matrix short a row") << "4.8 0 0; 0 9.836 0" << 9 << "9 numbers expected, got 6";
    QTest::newRow("two points") << "(-2.4, 4.9.1, 0)" << 3 << "cannot read '4.9.1'";
    // Decimal commas (issue 21 item 6): read as separators, so twice the numbers, with a hint
    // ("too few" above, "1.5, 2" style with a blank after the comma, gets none).
    QTest::newRow("decimal commas") << "(-2,4, 4,918, -1,765)" << 3 << "3 numbers expected, got 6 (decimal commas? use a decimal point: 3.11, not 3,11)";
    QTest::newRow("decimal comma, a number") << "2,37" << 1 << "1 number expected, got 2 (decimal commas? use a decimal point: 3.11, not 3,11)";
    QTest::newRow("a word") << "omega" << 1 << "cannot read 'omega'";
    QTest::newRow("half a fraction") << "64/" << 1 << "cannot read '64/'";
    QTest::newRow("two slashes") << "1/2/3" << 1 << "cannot read '1/2/3'";
    QTest::newRow("division by zero") << "1/0" << 1 << "division by zero in '1/0'";
    QTest::newRow("blank") << "  ( ) " << 3 << "nothing written";
    QTest::newRow("infinity") << "inf 0 0" << 3 << "cannot read 'inf'";
}

void TestAnswerParser::rejected()
{
    QFETCH(QString, text);
    QFETCH(int, count);
    QFETCH(QString, message);
    const ParsedAnswer r = parseAnswerText(text, count);
    QVERIFY(!r.ok());
    QCOMPARE(r.error, message);
    QVERIFY(r.values.empty());
}

void TestAnswerParser::roundTrip_data()
{
    QTest::addColumn<std::vector<double>>("values");
    QTest::addColumn<QString>("text");
    QTest::newRow("number") << std::vector<double>{2.37} << "2.37";
    QTest::newRow("vector") << std::vector<double>{-2.4, 4.918, -1.765} << "(-2.4, 4.918, -1.765)";
    QTest::newRow("quaternion") << std::vector<double>{1, 0, 0, 0} << "[1 0 0 0]";
    QTest::newRow("matrix") << std::vector<double>{4.8, 0, 0, 0, 9.836, 0, 0, 0, 4.412} << "4.8 0 0; 0 9.836 0; 0 0 4.412";
}

// A loaded answers file is shown as text and read back to the same numbers.
void TestAnswerParser::roundTrip()
{
    QFETCH(std::vector<double>, values);
    QFETCH(QString, text);
    QCOMPARE(answerText(values), text);
    const ParsedAnswer r = parseAnswerText(text, static_cast<int>(values.size()));
    QVERIFY(r.ok());
    QCOMPARE(r.values, values);
}

QTEST_APPLESS_MAIN(TestAnswerParser)
#include "tst_answer_parser.moc"
