// The app under Xvfb: open lesson 1, press Step, and read the quantities table's
// omega row. Expected: Table 2.1's omega = (-2.4, 4.918033, -1.764706), derived by
// hand in tst_table21.cpp.
#include "app/gui/main_window.h"
#include "app/gui/trace_model.h"

#include <QAbstractItemModelTester>
#include <QAction>
#include <QListWidget>
#include <QTreeView>
#include <QtTest>

namespace {

// Depth-first search for the row whose IdRole is `id`.
QModelIndex findRow(const QAbstractItemModel* model, const QString& id, const QModelIndex& parent = {})
{
    for (int r = 0; r < model->rowCount(parent); ++r) {
        const QModelIndex i = model->index(r, 0, parent);
        if (model->data(i, rbw::TraceModel::IdRole).toString() == id) return i;
        const QModelIndex found = findRow(model, id, i);
        if (found.isValid()) return found;
    }
    return {};
}

} // namespace

class TestAppSkeleton : public QObject {
    Q_OBJECT
private slots:
    void opensOnLesson1();
    void stepShowsOmegaRow();
    void modelIsConsistent();
    void resetClearsTrace();
};

void TestAppSkeleton::opensOnLesson1()
{
    rbw::MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("01-one-step"));
    QCOMPARE(w.currentLessonId(), QString("01-one-step"));
    QVERIFY(w.windowTitle().contains("One Euler step (Table 2.1)"));
    QCOMPARE(w.traceModel()->rowCount(), 0);   // nothing computed before the first Step
}

void TestAppSkeleton::stepShowsOmegaRow()
{
    rbw::MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("01-one-step"));

    auto* step = w.findChild<QAction*>("actionStep");
    QVERIFY(step);
    step->trigger();

    const QAbstractItemModel* model = w.findChild<QTreeView*>("traceView")->model();
    const QModelIndex omega = findRow(model, "angular_velocity");
    QVERIFY(omega.isValid());
    const QString value = model->index(omega.row(), rbw::TraceModel::ValueColumn, omega.parent()).data().toString();
    QCOMPARE(value, QString("(-2.4, 4.918033, -1.764706)"));
    QCOMPARE(model->index(omega.row(), rbw::TraceModel::SymbolColumn, omega.parent()).data().toString(), QString("ω"));
    QCOMPARE(model->index(omega.row(), rbw::TraceModel::FrameColumn, omega.parent()).data().toString(), QString("world"));
    QCOMPARE(model->index(omega.row(), rbw::TraceModel::UnitColumn, omega.parent()).data().toString(), QString("rad/s"));

    // The rest of the hand calculation is in the table too.
    for (const char* id : {"force", "torque", "position", "linear_velocity", "orientation", "angular_momentum",
                           "inertia_body", "inverse_inertia_world", "point_velocity"}) {
        QVERIFY2(findRow(model, id).isValid(), id);
    }
    // Grouped by stage: the omega row sits under Integration -> box.
    QCOMPARE(omega.parent().data().toString(), QString("box"));
    QCOMPARE(omega.parent().parent().data().toString(), QString("Integration"));
}

void TestAppSkeleton::modelIsConsistent()
{
    rbw::MainWindow w;
    QAbstractItemModelTester tester(w.traceModel(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    QVERIFY(w.openLesson("01-one-step"));
    auto* step = w.findChild<QAction*>("actionStep");
    for (int i = 0; i < 3; ++i) step->trigger();   // same shape: dataChanged path
}

void TestAppSkeleton::resetClearsTrace()
{
    rbw::MainWindow w;
    QVERIFY(w.openLesson("01-one-step"));
    w.findChild<QAction*>("actionStep")->trigger();
    QVERIFY(w.traceModel()->rowCount() > 0);
    QCOMPARE(w.world()->stepIndex(), 1L);
    w.findChild<QAction*>("actionReset")->trigger();
    QCOMPARE(w.world()->stepIndex(), 0L);
    QCOMPARE(w.traceModel()->rowCount(), 0);
}

QTEST_MAIN(TestAppSkeleton)
#include "tst_app_skeleton.moc"
