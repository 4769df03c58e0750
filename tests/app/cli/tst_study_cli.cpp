// `rbw study` end to end through the real binary: the CSV parses and has one row per
// integrator x dt with the runner's numbers, --output writes the same text to a file,
// a blown-up run prints a status and empty fields (never NaN), and bad input exits 2
// with "rbw: FILE: field: reason".
#include "tests/test_support.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using rbw::test::runRbw;

namespace {

const QString kLab = QStringLiteral(RBW_SOURCE_DIR "/lessons/10-accuracy-lab/");
const QString kHeader = QStringLiteral(
    "integrator,dt,steps,t_end,position_error,orientation_error,omega_error,energy_drift,momentum_drift,"
    "ns_per_step,status");

QList<QStringList> parseCsv(const QByteArray& text)
{
    QList<QStringList> rows;
    for (const QString& line : QString::fromUtf8(text).split('\n', Qt::SkipEmptyParts)) rows << line.split(',');
    return rows;
}

} // namespace

class TestStudyCli : public QObject {
    Q_OBJECT
private slots:
    void csvRows();
    void outputFile();
    void blownUpRowHasNoNumbers();
    void badInput_data();
    void badInput();
    void contactStudyCsv();
};

// Constant spin, T = 1, h = 0.1 and 0.05: 2 integrators x 2 dts = 4 rows in that order.
// Explicit Euler's orientation error is |N 2 atan(h|omega|/2) - |omega| T| (tst_study):
// h = 0.1: |10 * 2 atan(0.15) - 3| = 0.0222010478...
void TestStudyCli::csvRows()
{
    const auto r = runRbw({"study", kLab + "constant-spin.json", "--integrators", "explicit-euler,rk4",
                           "--dt", "0.1,0.05", "--t-end", "1"});
    QCOMPARE(r.exitCode, 0);
    const QList<QStringList> rows = parseCsv(r.out);
    QCOMPARE(rows.size(), 5);
    QCOMPARE(rows[0].join(','), kHeader);
    const QStringList names{"explicit-euler", "explicit-euler", "rk4", "rk4"};
    const QStringList dts{"0.1", "0.05", "0.1", "0.05"};
    const QStringList steps{"10", "20", "10", "20"};
    for (int i = 1; i <= 4; ++i) {
        QCOMPARE(rows[i].size(), 11);
        QCOMPARE(rows[i][0], names[i - 1]);
        QCOMPARE(rows[i][1], dts[i - 1]);
        QCOMPARE(rows[i][2], steps[i - 1]);
        QCOMPARE(rows[i][3], QString("1"));
        for (int col = 4; col <= 9; ++col) {
            bool ok = false;
            const double x = rows[i][col].toDouble(&ok);
            QVERIFY2(ok && std::isfinite(x) && x >= 0.0, qPrintable(rows[i].join(',')));
        }
        QCOMPARE(rows[i][10], QString("ok"));
    }
    const double expected = std::abs(10.0 * 2.0 * std::atan(0.15) - 3.0);
    RBW_COMPARE_NEAR(rows[1][5].toDouble(), expected, 1e-13);
    // progress and the reference go to stderr, not into the CSV
    QVERIFY(r.err.contains("4/4 runs"));
    QVERIFY(r.err.contains("constant spin"));
}

void TestStudyCli::outputFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("study.csv");
    const auto r = runRbw({"study", kLab + "symmetric-top.json", "--integrators", "midpoint", "--dt", "0.1",
                           "--t-end", "1", "--output", path});
    QCOMPARE(r.exitCode, 0);
    QVERIFY(r.out.isEmpty());
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QList<QStringList> rows = parseCsv(f.readAll());
    QCOMPARE(rows.size(), 2);
    QCOMPARE(rows[0].join(','), kHeader);
    QCOMPARE(rows[1][0], QString("midpoint"));
}

void TestStudyCli::blownUpRowHasNoNumbers()
{
    const auto r = runRbw({"study", kLab + "scene.json", "--integrators", "rotation-matrix", "--dt", "0.1"});
    QCOMPARE(r.exitCode, 0);
    QVERIFY(!r.out.toLower().contains("nan"));
    QVERIFY(!r.out.toLower().contains("inf"));
    const QList<QStringList> rows = parseCsv(r.out);
    QCOMPARE(rows.size(), 2);
    QCOMPARE(rows[1].size(), 11);
    QVERIFY2(rows[1][10].startsWith("blown up at step "), qPrintable(rows[1][10]));
    for (int col = 4; col <= 9; ++col) QVERIFY(rows[1][col].isEmpty());
}

void TestStudyCli::badInput_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message");
    const QString spin = kLab + "constant-spin.json";
    const QString two = QStringLiteral(RBW_SOURCE_DIR "/lessons/03-two-box-collision/scene.json");
    const QString plane = QStringLiteral(RBW_SOURCE_DIR "/lessons/06-box-on-plane/scene.json");
    const QString one = QStringLiteral(RBW_SOURCE_DIR "/lessons/01-one-step/scene.json");
    QTest::newRow("unknown integrator") << QStringList{"study", spin, "--integrators", "rk4,rk5"}
                                        << "rbw: " + spin + ": integrators: unknown integrator \"rk5\"";
    QTest::newRow("negative dt") << QStringList{"study", spin, "--dt", "0.1,-0.05"}
                                 << "rbw: " + spin + ": dt: must be a finite number > 0, got -0.05";
    QTest::newRow("dt not a number") << QStringList{"study", spin, "--dt", "0.1,abc"}
                                     << "rbw: " + spin + ": dt: must be a finite number > 0, got \"abc\"";
    QTest::newRow("dt not dividing T") << QStringList{"study", spin, "--dt", "0.03", "--t-end", "1"}
                                       << "rbw: " + spin + ": dt: 0.03 does not divide t_end = 1";
    QTest::newRow("t-end zero") << QStringList{"study", spin, "--t-end", "0"}
                                << "rbw: " + spin + ": t_end: must be a finite number > 0";
    QTest::newRow("two bodies") << QStringList{"study", two}
                                << "rbw: " + two + ": bodies: an exact reference needs exactly one body";
    QTest::newRow("bodies and a plane") << QStringList{"study", plane} << "rbw: " + plane + ": bodies:";
    QTest::newRow("a force") << QStringList{"study", one} << "rbw: " + one + ": forces:";
    QTest::newRow("missing file") << QStringList{"study", kLab + "nope.json"} << "rbw: " + kLab + "nope.json";
    QTest::newRow("no scene") << QStringList{"study"} << "rbw: study takes exactly one scene file";
    // rbw contact-study PROBLEM
    QTest::newRow("contact: unknown problem") << QStringList{"contact-study", "pile"}
                                              << "rbw: contact-study: PROBLEM: unknown problem \"pile\" (resting-box, tower, rain)";
    QTest::newRow("contact: iterations 0") << QStringList{"contact-study", "tower", "--iterations", "4,0"}
                                           << "rbw: contact-study: --iterations: must be whole numbers from 1 to 1000, got 0";
    QTest::newRow("contact: iterations text") << QStringList{"contact-study", "tower", "--iterations", "4,many"}
                                              << "rbw: contact-study: --iterations: must be whole numbers, got \"many\"";
    QTest::newRow("contact: dt negative") << QStringList{"contact-study", "tower", "--dt", "-0.01"}
                                          << "rbw: contact-study: --dt: must be finite numbers > 0";
    QTest::newRow("contact: no boxes") << QStringList{"contact-study", "rain", "--boxes", "0"}
                                       << "rbw: contact-study: --boxes: must be a whole number from 1 to 10000, got 0";
    QTest::newRow("contact: no problem") << QStringList{"contact-study"} << "rbw: contact-study takes exactly one problem";
}

void TestStudyCli::badInput()
{
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    const auto r = runRbw(args);
    QCOMPARE(r.exitCode, 2);
    QVERIFY(r.out.isEmpty());
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
}

// rbw contact-study: one row per model x iterations x dt, course first; the numbers are
// the runner's (tst_contact_study checks them), here only their shape: T = 1 s at
// h = 1/60 is 60 steps, the resting box has a drift, and a blown-up row never shows NaN.
void TestStudyCli::contactStudyCsv()
{
    const auto r = runRbw({"contact-study", "resting-box", "--iterations", "1,4", "--dt", "0.0166666666666666667",
                           "--t-end", "1"});
    QCOMPARE(r.exitCode, 0);
    const QList<QStringList> rows = parseCsv(r.out);
    QCOMPARE(rows.size(), 5);
    QCOMPARE(rows[0].join(','), QStringLiteral("problem,model,iterations,dt,steps,t_end,deepest_overlap,deepest_below,"
                                               "drift,energy_gained,kinetic_energy_end,moving_end,ns_per_step,status"));
    QCOMPARE(rows[1].mid(0, 6), (QStringList{"resting-box", "course", "", "0.016666666666666666", "60", "1"}));
    // the soft step at its default 5 substeps, then the sequential impulses by iterations
    QCOMPARE(rows[2].mid(0, 3), (QStringList{"resting-box", "soft-step", "5"}));
    QCOMPARE(rows[3].mid(0, 3), (QStringList{"resting-box", "manifold", "1"}));
    QCOMPARE(rows[4].mid(0, 3), (QStringList{"resting-box", "manifold", "4"}));
    for (int i = 1; i < 5; ++i) {
        QCOMPARE(rows[i].size(), 14);
        QCOMPARE(rows[i].last(), QStringLiteral("ok"));
        QVERIFY(!rows[i][8].isEmpty());   // a resting box has a drift
        QVERIFY(!r.out.contains("nan") && !r.out.contains("inf"));
    }
    QVERIFY(r.err.contains("rbw: contact-study: 4/4 runs"));
}

QTEST_MAIN(TestStudyCli)
#include "tst_study_cli.moc"
