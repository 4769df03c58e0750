// The Contacts tab of the Accuracy dock under Xvfb: a small contact study runs off the
// GUI thread to completion, the table holds the runner's numbers (those of
// runContactStudy for the same configuration, without the timing), the chart draws one
// line per model and iteration count, bad input is refused with the reason, and the
// CSV export is the CLI's.
#include "app/output/study_csv.h"
#include "app/gui/panels/accuracy/contact_study_panel.h"

#include <QAbstractItemModelTester>
#include <QChart>
#include <QLegend>
#include <QLegendMarker>
#include <QSet>
#include <QFile>
#include <QSignalSpy>
#include <QStandardItemModel>
#include <QTemporaryDir>
#include <QtTest>

#include <set>
#include <string>
#include <utility>

using namespace rbw;

class TestContactStudyPanel : public QObject {
    Q_OBJECT
private slots:
    void smallStudy();
    void badInputRefused();
};

void TestContactStudyPanel::smallStudy()
{
    ContactStudyPanel panel;
    QAbstractItemModelTester tester(panel.tableModel(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    panel.resize(900, 800);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.setProblem(lab::ContactProblem::RestingBox);
    panel.setIterationsText(QStringLiteral("1, 4"));
    panel.setDtText(QStringLiteral("1/60, 0.0333333333333333333"));   // a fraction reads as one
    panel.setEndTime(1.0);
    panel.setMetric(ContactMetric::Drift);
    QSignalSpy finished(&panel, &ContactStudyPanel::studyFinished);
    QVERIFY(panel.startStudy());
    QVERIFY(finished.wait(60000));
    // course x 2 h, the soft step x 2 h, then manifold 1 and 4 x 2 h
    QCOMPARE(panel.result().rows.size(), size_t(8));
    QCOMPARE(panel.tableModel()->rowCount(), 8);
    QCOMPARE(panel.tableModel()->columnCount(), contactStudyCsvHeader().size());

    // The same numbers as the runner gives for this configuration (the runs are
    // deterministic; only the wall time differs).
    lab::ContactStudyConfig c;
    c.problem = lab::ContactProblem::RestingBox;
    c.iterations = {1, 4};
    c.dts = {1.0 / 60.0, 1.0 / 30.0};
    c.tEnd = 1.0;
    const lab::ContactStudyResult direct = lab::runContactStudy(c);
    for (size_t i = 0; i < direct.rows.size(); ++i) {
        QCOMPARE(panel.result().rows[i].model, direct.rows[i].model);
        QCOMPARE(panel.result().rows[i].iterations, direct.rows[i].iterations);
        QCOMPARE(panel.result().rows[i].steps, direct.rows[i].steps);
        QCOMPARE(*panel.result().rows[i].drift, *direct.rows[i].drift);
        QCOMPARE(panel.result().rows[i].energyGained, direct.rows[i].energyGained);
        // the table holds the CSV's field for it (column 8: drift), every digit, and
        // shows it with 4 significant digits
        const QStandardItem* drift = panel.tableModel()->item(int(i), 8);
        QCOMPARE(drift->data(Qt::UserRole).toString(),
                 QString::number(*direct.rows[i].drift, 'g', QLocale::FloatingPointShortest));
        QCOMPARE(drift->toolTip(), drift->data(Qt::UserRole).toString());
        QCOMPARE(drift->text(), QString::number(*direct.rows[i].drift, 'g', 4));
        // h as typed: 1/60 and 0.0333333333333333333 (1/h = 30 to 1e-16) read 1/60, 1/30.
        const QString h = panel.tableModel()->item(int(i), 3)->text();
        QCOMPARE(h, direct.rows[i].dt < 0.02 ? QStringLiteral("1/60") : QStringLiteral("1/30"));
    }
    // The legend names each line's model whole, each name different, and the tab says
    // what it is for.
    QApplication::processEvents();   // the chart lays out its new legend
    QSet<QString> names;
    const QLegend* legend = panel.chart()->legend();
    const QFontMetrics fm(legend->font());
    for (const QLegendMarker* marker : legend->markers()) {
        names.insert(marker->label());
        QVERIFY2(fm.horizontalAdvance(marker->label()) < legend->geometry().width(),
                 qPrintable(QStringLiteral("%1: %2 px, the legend %3 px")
                                .arg(marker->label())
                                .arg(fm.horizontalAdvance(marker->label()))
                                .arg(legend->geometry().width())));
    }
    QCOMPARE(names.size(), legend->markers().size());
    QVERIFY(names.contains(QStringLiteral("course model (one impulse per corner)")));
    QVERIFY(names.contains(QStringLiteral("manifold, 4 solver iterations")));
    QVERIFY(panel.introText().contains(QStringLiteral("course model")));
    QVERIFY(panel.introText().contains(QStringLiteral("manifold model")));
    // One line per model and iteration count whose drift is above 0: the course model's,
    // the soft step's (its 5 substeps) and the manifold's (a run that holds the box
    // exactly still is not drawn, and the status says so).
    std::set<std::pair<std::string, int>> lines;
    for (const lab::ContactStudyRow& row : direct.rows) {
        if (*row.drift > 0.0) lines.insert({row.model, row.iterations});
    }
    const int drawable = static_cast<int>(lines.size());
    QCOMPARE(panel.seriesCount(), drawable);
    QVERIFY(panel.seriesCount() >= 2);

    // Export: the CLI's CSV of these rows.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("contacts.csv"));
    QString error;
    QVERIFY2(panel.exportCsv(path, &error), qPrintable(error));
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QCOMPARE(QString::fromUtf8(f.readAll()), contactStudyToCsv(panel.result()));
}

void TestContactStudyPanel::badInputRefused()
{
    ContactStudyPanel panel;
    panel.setIterationsText(QStringLiteral("4, 0"));
    QVERIFY(!panel.startStudy());
    QVERIFY2(panel.statusText().contains(QStringLiteral("iterations: must be whole numbers from 1 to 1000, got 0")),
             qPrintable(panel.statusText()));
    panel.setIterationsText(QStringLiteral("4"));
    panel.setDtText(QStringLiteral("fast"));
    QVERIFY(!panel.startStudy());
    QVERIFY(panel.statusText().contains(QStringLiteral("h: must be numbers > 0, got \"fast\"")));
    QVERIFY(!panel.isRunning());
}

QTEST_MAIN(TestContactStudyPanel)
#include "tst_contact_study_panel.moc"
