// The quantities of the step in the whole window under Xvfb: the table's values,
// symbols, frames and units (Table 2.1's omega = (-2.4, 4.918033, -1.764706), see
// tst_table21.cpp; lesson 3's J = 64/27, see tst_collision_lessons.cpp), the formula
// pane, the typeset derivation, Show code of a row, the contacts grouped by pair,
// and the values kept on screen beside long group names.
#include "app/gui/shell/main_window.h"
#include "tests/app/gui/shell/window_test_support.h"
#include "tests/test_support.h"

#include <QAction>
#include <QDockWidget>
#include <QSettings>
#include <QStandardPaths>
#include <QtTest>

#include <functional>
#include "app/gui/panels/quantities/code_view.h"
#include "app/gui/panels/quantities/formula_pane.h"
#include "app/scene/scene_loader.h"

#include <QAbstractItemModelTester>
#include <QFile>
#include <QFileInfo>
#include <QTreeView>

using namespace rbw;
using namespace rbw::test;

class TestQuantitiesTable : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void lesson1OmegaInPanelAndDerivation();
    void lesson3CollisionStep();
    void showCodeOfAQuantity();
    void modelIsConsistent();
    void contactsGroupedByPair();
    void valuesStayOnScreenWithLongGroupNames();
};

void TestQuantitiesTable::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);   // QSettings go to a test location
    QSettings().clear();
    Warnings::install();
}

void TestQuantitiesTable::lesson1OmegaInPanelAndDerivation()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("01-one-step"));
    w.findChild<QDockWidget*>("derivationDock")->raise();
    w.findChild<QAction*>("actionStep")->trigger();

    const QAbstractItemModel* model = w.findChild<QTreeView*>("traceView")->model();
    const QModelIndex omega = findRow(model, "angular_velocity");
    QVERIFY(omega.isValid());
    // A column, as in the derivation: one component per line.
    QCOMPARE(valueText(model, omega), QString("-2.4\n4.918033\n-1.764706"));
    QCOMPARE(model->index(omega.row(), TraceModel::SymbolColumn, omega.parent()).data().toString(), QString("ω"));
    QCOMPARE(model->index(omega.row(), TraceModel::FrameColumn, omega.parent()).data().toString(), QString("world"));
    QCOMPARE(model->index(omega.row(), TraceModel::UnitColumn, omega.parent()).data().toString(), QString("rad/s"));
    QCOMPARE(omega.parent().data().toString(), QString("box"));

    // Before and after the step (issue 10): Table 2.1 starts at rest, so v_0 = 0 and
    // v_1 = v_0 + h F/M = 2 (1, 1, 0)/2 = (1, 1, 0); r_0 = [cos 45°, 0, 0, sin 45°].
    const QModelIndex v = findRow(model, "linear_velocity");
    QCOMPARE(model->index(v.row(), TraceModel::BeforeColumn, v.parent()).data().toString(), QString("0\n0\n0"));
    QCOMPARE(valueText(model, v), QString("1\n1\n0"));
    const QModelIndex r = findRow(model, "orientation");
    QCOMPARE(model->index(r.row(), TraceModel::BeforeColumn, r.parent()).data().toString(),
             QString("w 0.7071068\nx 0\ny 0\nz 0.7071068"));
    // Step k = 0 goes from t₀ to t₁ (one step numbering, app/core/step_numbering.h).
    QCOMPARE(model->headerData(TraceModel::BeforeColumn, Qt::Horizontal).toString(), QStringLiteral("Before, t₀"));
    QCOMPARE(model->headerData(TraceModel::ValueColumn, Qt::Horizontal).toString(), QStringLiteral("After, t₁"));
    // A force has no value before the step: it is computed in it (negative control).
    const QModelIndex f = findRow(model, "force");
    QVERIFY(model->index(f.row(), TraceModel::BeforeColumn, f.parent()).data().toString().isEmpty());
    // The formula pane typesets the selected row's formula and both values.
    const QString pane = FormulaPane::rowBodyHtml(v);
    QVERIFY2(pane.contains(QLatin1String("before: ")) && pane.contains(QLatin1String("after: ")), qPrintable(pane));
    QVERIFY(pane.contains(QLatin1String("physics/engine/integrators/explicit_euler.cpp")));
    QVERIFY(!FormulaPane::rowBodyHtml(f).contains(QLatin1String("before: ")));
    QCOMPARE(omega.parent().parent().data().toString(), QString("Integration"));

    // The typeset page: rendered by KaTeX without errors, and the omega numbers in it.
    DerivationView* page = w.derivationView();
    QVERIFY(waitRendered(page));
    QVERIFY(page->katexCount() > 10);
    QCOMPARE(page->errorCount(), 0);
    const QString text = pageText(page);
    for (const char* number : {"-2.4", "4.918033", "-1.764706"}) {
        // KaTeX typesets a minus sign as U+2212.
        const QString n = QString::fromLatin1(number);
        QVERIFY2(text.contains(n) || text.contains(QString(n).replace('-', QChar(0x2212))), number);
    }
}

void TestQuantitiesTable::lesson3CollisionStep()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("03-two-box-collision"));
    w.findChild<QDockWidget*>("derivationDock")->raise();
    auto* step = w.findChild<QAction*>("actionStep");
    // Step until the first contact (tst_collision_lessons derives when it comes).
    int k = 0;
    while (k < 200 && (w.session()->currentTrace() == nullptr || w.session()->currentTrace()->contacts.empty())) {
        step->trigger();
        ++k;
    }
    QVERIFY(k < 200);
    const QAbstractItemModel* model = w.traceModel();
    for (const char* id : {"point", "normal", "relative_velocity", "numerator", "denominator", "impulse"}) {
        QVERIFY2(findRow(model, id).isValid(), id);
    }
    // J = 64/27 = 2.370370...
    QVERIFY2(valueText(model, findRow(model, "impulse")).startsWith("2.37037"), qPrintable(valueText(model, findRow(model, "impulse"))));
    DerivationView* page = w.derivationView();
    QVERIFY(waitRendered(page));
    QCOMPARE(page->errorCount(), 0);
    const QString text = pageText(page);
    QVERIFY2(text.contains("2.37037"), "J's value on the page");
    QVERIFY(w.derivationHtml().contains("numerator") || w.derivationHtml().contains("Numerator"));
}

void TestQuantitiesTable::showCodeOfAQuantity()
{
    // Lesson 1's omega row names the physics statement that computed it; Show code
    // opens that file at that line, highlighted, with the equation comment above it
    // on screen.
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("01-one-step"));
    w.findChild<QAction*>("actionStep")->trigger();
    auto* view = w.findChild<QTreeView*>("traceView");
    const QAbstractItemModel* model = view->model();
    const QModelIndex omega = findRow(model, "angular_velocity");
    QVERIFY(omega.isValid());
    view->setCurrentIndex(omega);

    // The Source column: "file.cpp:line", with the path in the tree as its tooltip.
    const QModelIndex sourceCell = model->index(omega.row(), TraceModel::SourceColumn, omega.parent());
    QCOMPARE(model->headerData(TraceModel::SourceColumn, Qt::Horizontal).toString(), QString("Source"));
    const QString source = sourceCell.data(Qt::ToolTipRole).toString();
    static const QRegularExpression located(QStringLiteral(R"(^(physics/[a-z0-9_/]+\.cpp):(\d+)$)"));
    const QRegularExpressionMatch m = located.match(source);
    QVERIFY2(m.hasMatch(), qPrintable(source));
    const QString file = m.captured(1);
    const int line = m.captured(2).toInt();
    QCOMPARE(sourceCell.data().toString(), QFileInfo(file).fileName() + ':' + QString::number(line));
    QVERIFY(omega.data(Qt::ToolTipRole).toString().contains(source));   // also on the quantity's tooltip

    // Show code is in the row's context menu and has a key.
    auto* showCode = w.findChild<QAction*>("actionShowCode");
    QVERIFY(showCode != nullptr);
    QVERIFY(view->actions().contains(showCode));
    QCOMPARE(view->contextMenuPolicy(), Qt::ActionsContextMenu);
    QVERIFY(!showCode->shortcuts().isEmpty());
    showCode->trigger();

    CodeView* code = w.codeView();
    QTRY_VERIFY(code->isVisible());
    QCOMPARE(code->file(), file);
    QCOMPARE(code->highlightedLine(), line);
    QCOMPARE(code->headerText(), source);
    // The highlighted line is the file's line, and it is code, not a blank or a comment.
    QFile onDisk(QStringLiteral(RBW_SOURCE_DIR "/") + file);
    QVERIFY(onDisk.open(QIODevice::ReadOnly | QIODevice::Text));
    const QStringList lines = QString::fromUtf8(onDisk.readAll()).split('\n');
    QVERIFY(line >= 1 && line <= lines.size());
    QCOMPARE(code->lineText(line), lines[line - 1]);
    const QString statement = code->lineText(line).trimmed();
    QVERIFY2(!statement.isEmpty() && !statement.startsWith("//"), qPrintable(statement));
    QVERIFY2(statement.contains("omega"), qPrintable(statement));   // the statement that records omega
    // On screen: the line and the context above it, where the equation comment is.
    QTRY_VERIFY(code->lineOnScreen(line));
    QCOMPARE(code->firstVisibleLine(), std::max(1, line - CodeView::kContextLines));
    bool commentAbove = false;
    for (int k = std::max(1, line - CodeView::kContextLines); k < line; ++k) {
        QVERIFY2(code->lineOnScreen(k), qPrintable(QString::number(k)));
        commentAbove = commentAbove || code->lineText(k).trimmed().startsWith("//");
    }
    QVERIFY2(commentAbove, "the equation comment above the statement is on screen");

    // Negative control: a group row has no code.
    view->setCurrentIndex(omega.parent());
    view->selectionModel()->clearSelection();
    QVERIFY(!w.showCodeOfCurrentRow());
    QCOMPARE(code->highlightedLine(), line);   // unchanged
}

void TestQuantitiesTable::modelIsConsistent()
{
    MainWindow w;
    QAbstractItemModelTester tester(w.traceModel(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    QVERIFY(w.openLesson("03-two-box-collision"));
    auto* step = w.findChild<QAction*>("actionStep");
    for (int i = 0; i < 30; ++i) step->trigger();
    w.findChild<QAction*>("actionStepBack")->trigger();
    // The tester has checked every change above; the table shows step 29's trace.
    QCOMPARE(w.world()->stepIndex(), 29L);
    QCOMPARE(w.traceModel()->trace().step, 28L);
}

void TestQuantitiesTable::contactsGroupedByPair()
{
    // Lesson 6: three cubes land on a vertex (1 contact), an edge (2) and a face (4).
    // The table groups the face's 4 corners (and the edge's 2) under one node of the
    // pair, and lists the vertex's single contact on its own.
    const SceneLoadResult loaded = loadSceneFile(QStringLiteral(RBW_SOURCE_DIR "/lessons/06-box-on-plane/scene.json"));
    QVERIFY(loaded.ok());
    World world(*loaded.scene);
    StepTrace trace;
    bool fourCorners = false;
    for (int k = 0; k < 400 && !fourCorners; ++k) {
        QVERIFY(world.step(&trace).ok);
        int faceContacts = 0;
        for (const ContactHeader& c : trace.contacts) faceContacts += c.bodyA == 2 ? 1 : 0;
        fourCorners = faceContacts == 4;
    }
    QVERIFY2(fourCorners, "the face cube never had 4 contacts at once");
    TraceModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    model.setTrace(trace, *loaded.scene);
    QModelIndex collisions;
    for (int r = 0; r < model.rowCount(); ++r) {
        if (model.index(r, 0).data().toString() == QLatin1String("Collisions")) collisions = model.index(r, 0);
    }
    QVERIFY(collisions.isValid());
    QModelIndex facePair;
    for (int r = 0; r < model.rowCount(collisions); ++r) {
        if (model.index(r, 0, collisions).data().toString() == QStringLiteral("face ↔ ground · 4 contacts")) {
            facePair = model.index(r, 0, collisions);
        }
    }
    QVERIFY(facePair.isValid());
    QCOMPARE(model.rowCount(facePair), 4);
    // Each point node holds that contact's rows, the impulse among them.
    const QModelIndex point = model.index(0, 0, facePair);
    QVERIFY(point.data().toString().startsWith(QLatin1String("contact ")));
    QVERIFY(findRow(&model, QStringLiteral("impulse"), point).isValid());
}

// Lesson 11 (manifold model) names each point's group with its pair, feature and
// point ("contact 7 · stack-1 ↔ stack-2 · face-face (reference A) · point 3 of 4"),
// far wider than a quantity's name. Sized to its contents, the Quantity column pushed
// Before and After off the table at the default window size. A group's label now
// spans its row (its full text also in the tooltip), so the After column starts on
// screen.
void TestQuantitiesTable::valuesStayOnScreenWithLongGroupNames()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("11-resting-contact"));
    auto* step = w.findChild<QAction*>("actionStep");
    for (int k = 0; k < 12; ++k) step->trigger();
    QCoreApplication::processEvents();
    auto* view = w.findChild<QTreeView*>("traceView");
    QVERIFY(view != nullptr);
    const int width = view->viewport()->width();
    // At least 40 px of the After column (its first digits) are on screen.
    const int after = view->columnViewportPosition(TraceModel::ValueColumn);
    QVERIFY2(after + 40 <= width, qPrintable(QStringLiteral("After starts at %1 of %2").arg(after).arg(width)));
    // The control: with the group labels in the Quantity column (not spanning their
    // rows) and the column sized to its contents, After is pushed off screen.
    const int capped = view->columnWidth(TraceModel::QuantityColumn);
    std::function<void(const QModelIndex&, bool)> span = [&](const QModelIndex& parent, bool on) {
        for (int r = 0; r < view->model()->rowCount(parent); ++r) {
            const QModelIndex i = view->model()->index(r, 0, parent);
            if (view->model()->rowCount(i) == 0) continue;
            QVERIFY(view->isFirstColumnSpanned(r, parent) == !on);   // spanned as the table shows it
            view->setFirstColumnSpanned(r, parent, on);
            span(i, on);
        }
    };
    span(QModelIndex(), false);
    view->resizeColumnToContents(TraceModel::QuantityColumn);
    QVERIFY2(view->columnViewportPosition(TraceModel::ValueColumn) + 40 > width,
             qPrintable(QStringLiteral("natural width %1 px").arg(view->columnWidth(TraceModel::QuantityColumn))));
    span(QModelIndex(), true);
    view->setColumnWidth(TraceModel::QuantityColumn, capped);
    // A group's whole label is its tooltip, for where it is elided.
    const QModelIndex collisions = [&] {
        for (int r = 0; r < w.traceModel()->rowCount(); ++r) {
            const QModelIndex i = w.traceModel()->index(r, 0);
            if (i.data().toString() == QLatin1String("Collisions")) return i;
        }
        return QModelIndex();
    }();
    QVERIFY(collisions.isValid());
    QModelIndex pair;   // the first group under Collisions (a pair of bodies)
    for (int r = 0; r < w.traceModel()->rowCount(collisions) && !pair.isValid(); ++r) {
        const QModelIndex i = w.traceModel()->index(r, 0, collisions);
        if (w.traceModel()->rowCount(i) > 0) pair = i;
    }
    QVERIFY(pair.isValid());
    QVERIFY(!pair.data().toString().isEmpty());
    QCOMPARE(pair.data(Qt::ToolTipRole).toString(), pair.data().toString());
}

RBW_WINDOW_TEST_MAIN(TestQuantitiesTable)

#include "tst_quantities_table.moc"
