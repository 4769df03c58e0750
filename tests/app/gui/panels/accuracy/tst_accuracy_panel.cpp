// The Accuracy panel under Xvfb: a small study runs off the GUI thread to completion
// with progress reaching 100 %, one series per integrator on log-log axes, the table
// model passes QAbstractItemModelTester, Cancel stops a long study, a scene without
// an exact answer is refused with the reason, and the plot and numbers export.
//
// With RBW_ACCURACY_FRONT_PNG=path set, exportDocsImage runs the default study of
// lesson 10 (every integrator, the default dts) and writes the plot there: that is
// docs/images/accuracy-front.png (and the whole panel as accuracy-panel.png).
#include "app/output/study_csv.h"
#include "app/gui/panels/accuracy/accuracy_panel.h"
#include "app/gui/panels/accuracy/study_table_model.h"
#include "tests/test_support.h"

#include <QAbstractItemModelTester>
#include <QChart>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QLogValueAxis>
#include <QProgressBar>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using rbw::AccuracyPanel;
using rbw::test::lessonScene;

namespace {

const QString kLab = QStringLiteral("10-accuracy-lab/");

} // namespace

class TestAccuracyPanel : public QObject {
    Q_OBJECT
private slots:
    void smallStudyRunsToCompletion();
    void errorMetricSwitchesTheYAxis();
    void cancelStopsEarly();
    void refusedScene();
    void badDtList();
    void exportsPngAndCsv();
    void exportDocsImage();
};

void TestAccuracyPanel::smallStudyRunsToCompletion()
{
    AccuracyPanel panel;
    panel.resize(1400, 900);
    panel.show();
    QAbstractItemModelTester tester(panel.tableModel(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    panel.setScene(lessonScene(kLab + "symmetric-top.json"), "10-accuracy-lab/symmetric-top.json");
    QVERIFY(panel.sceneHasExactAnswer());
    QCOMPARE(panel.endTime(), 2.0);   // the scene's steps x dt = 200 x 0.01
    panel.setSelectedIntegrators({"explicit-euler", "midpoint", "rk4"});
    panel.setDtText("0.1, 0.05, 0.02");
    panel.setEndTime(1.0);
    panel.setTimingBudget(0.0);
    QSignalSpy finished(&panel, &AccuracyPanel::studyFinished);
    QSignalSpy progress(&panel, &AccuracyPanel::progressChanged);
    QVERIFY(panel.startStudy());
    QVERIFY(!panel.startStudy());   // one study at a time
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
    QVERIFY(!panel.isRunning());
    QCOMPARE(panel.progressBar()->value(), 100);
    QCOMPARE(progress.count(), 9);
    QCOMPARE(progress.last().at(0).toInt(), 9);
    QCOMPARE(progress.last().at(1).toInt(), 9);
    QVERIFY(!panel.result().cancelled);
    QCOMPARE(panel.tableModel()->rowCount(), 9);
    // one line per integrator, each with its 3 points (the errors are all > 0)
    QCOMPARE(panel.seriesCount(), 3);
    QCOMPARE(panel.front().curves.size(), 3);
    for (const rbw::IntegratorCurve& c : panel.front().curves) QCOMPARE(c.points.size(), 3);
    QCOMPARE(panel.front().pointCount(), 9);
    // log-log axes
    const QList<QAbstractAxis*> axes = panel.chart()->axes();
    QCOMPARE(axes.size(), 2);
    for (QAbstractAxis* a : axes) QVERIFY(qobject_cast<QLogValueAxis*>(a) != nullptr);
    // the Pareto front ends at the most accurate point: rk4 at the smallest h
    QVERIFY(!panel.front().pareto.isEmpty());
    QCOMPARE(panel.front().pareto.last().integrator, QString("rk4"));
    QCOMPARE(panel.front().pareto.last().dt, 0.02);
}

void TestAccuracyPanel::errorMetricSwitchesTheYAxis()
{
    AccuracyPanel panel;
    panel.setScene(lessonScene(kLab + "projectile.json"), "projectile");
    panel.setSelectedIntegrators({"explicit-euler", "rk4"});
    panel.setDtText("0.1, 0.05");
    panel.setTimingBudget(0.0);
    QSignalSpy finished(&panel, &AccuracyPanel::studyFinished);
    QVERIFY(panel.startStudy());
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
    panel.setErrorMetric(rbw::ErrorMetric::Position);
    const QAbstractAxis* y = panel.chart()->axes(Qt::Vertical).value(0);
    QVERIFY(y != nullptr);
    QVERIFY(y->titleText().startsWith("position error"));
    // explicit Euler's position error is 1/2 |g| h T > 0 (drawn); rk4's is rounding-size
    // or exactly 0 (then counted, not drawn on the log axis)
    QCOMPARE(panel.front().curves[0].points.size(), 2);
    QCOMPARE(panel.front().curves[1].points.size() + panel.front().zeroErrors, 2);
    panel.setErrorMetric(rbw::ErrorMetric::Omega);
    QVERIFY(panel.chart()->axes(Qt::Vertical).value(0)->titleText().startsWith("ω error"));
}

void TestAccuracyPanel::cancelStopsEarly()
{
    AccuracyPanel panel;
    panel.setScene(lessonScene(kLab + "scene.json"), "tumbling book");
    // 8 integrators x 4 dts to T = 20 s: many seconds of work, most of it at h = 1e-3
    panel.setDtText("0.1, 0.01, 0.002, 0.001");
    panel.setEndTime(20.0);
    panel.setTimingBudget(0.05);
    QSignalSpy finished(&panel, &AccuracyPanel::studyFinished);
    QSignalSpy progress(&panel, &AccuracyPanel::progressChanged);
    QVERIFY(panel.startStudy());
    QTRY_VERIFY_WITH_TIMEOUT(progress.count() >= 1, 60000);
    panel.cancelStudy();
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
    QVERIFY(panel.result().cancelled);
    QCOMPARE(panel.result().runsPlanned, 32);
    QVERIFY(int(panel.result().rows.size()) < 32);
    QVERIFY(panel.progressBar()->value() < 100);
    QVERIFY(panel.statusText().startsWith("Cancelled"));
}

void TestAccuracyPanel::refusedScene()
{
    AccuracyPanel panel;
    panel.setScene(lessonScene("03-two-box-collision/scene.json"), "03-two-box-collision");
    QVERIFY(!panel.sceneHasExactAnswer());
    QVERIFY2(panel.statusText().contains("bodies: an exact reference needs exactly one body"),
             qPrintable(panel.statusText()));
    QVERIFY(!panel.startStudy());
    QVERIFY(!panel.isRunning());
}

void TestAccuracyPanel::badDtList()
{
    AccuracyPanel panel;
    panel.setScene(lessonScene(kLab + "constant-spin.json"), "constant spin");
    panel.setDtText("0.1, abc");
    QVERIFY(!panel.startStudy());
    QVERIFY2(panel.statusText().contains("dt: must be a finite number > 0, got \"abc\""), qPrintable(panel.statusText()));
    panel.setDtText("0.03");
    panel.setEndTime(1.0);
    QVERIFY(!panel.startStudy());
    QVERIFY2(panel.statusText().contains("does not divide"), qPrintable(panel.statusText()));
    panel.setDtText("0.1");
    panel.setSelectedIntegrators({});
    QVERIFY(!panel.startStudy());
    QVERIFY(panel.statusText().contains("integrators"));
}

void TestAccuracyPanel::exportsPngAndCsv()
{
    AccuracyPanel panel;
    panel.resize(1200, 800);
    panel.show();
    panel.setScene(lessonScene(kLab + "constant-spin.json"), "constant spin");
    panel.setSelectedIntegrators({"explicit-euler", "rk4"});
    panel.setDtText("0.1, 0.05");
    panel.setTimingBudget(0.0);
    QSignalSpy finished(&panel, &AccuracyPanel::studyFinished);
    QVERIFY(panel.startStudy());
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
    QTemporaryDir dir;
    QString error;
    QVERIFY2(panel.exportPng(dir.filePath("front.png"), &error), qPrintable(error));
    const QImage image(dir.filePath("front.png"));
    QVERIFY(!image.isNull());
    QVERIFY(image.width() > 200 && image.height() > 200);
    QVERIFY2(panel.exportCsv(dir.filePath("front.csv"), &error), qPrintable(error));
    QFile csv(dir.filePath("front.csv"));
    QVERIFY(csv.open(QIODevice::ReadOnly));
    QCOMPARE(QString::fromUtf8(csv.readAll()), rbw::studyToCsv(panel.result()));
    // a path that cannot be written: a clear error, no crash
    QVERIFY(!panel.exportCsv(dir.filePath("no/such/dir/x.csv"), &error));
    QVERIFY(error.contains("cannot write"));
}

void TestAccuracyPanel::exportDocsImage()
{
    const QString path = qEnvironmentVariable("RBW_ACCURACY_FRONT_PNG");
    if (path.isEmpty()) QSKIP("set RBW_ACCURACY_FRONT_PNG to write docs/images/accuracy-front.png");
    AccuracyPanel panel;
    panel.resize(1400, 950);
    panel.show();
    panel.setScene(lessonScene(kLab + "scene.json"), "10-accuracy-lab/scene.json");
    panel.setTimingBudget(0.05);
    QSignalSpy finished(&panel, &AccuracyPanel::studyFinished);
    QVERIFY(panel.startStudy());
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 280000);
    QString error;
    QVERIFY2(panel.exportPng(path, &error), qPrintable(error));
    const QString csvPath = qEnvironmentVariable("RBW_ACCURACY_FRONT_CSV");
    if (!csvPath.isEmpty()) QVERIFY2(panel.exportCsv(csvPath, &error), qPrintable(error));
    // the whole panel, next to the plot
    panel.grab().save(QFileInfo(path).dir().filePath("accuracy-panel.png"));
}

QTEST_MAIN(TestAccuracyPanel)
#include "tst_accuracy_panel.moc"
