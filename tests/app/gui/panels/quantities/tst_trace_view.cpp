// The quantities table fits (issue 20, item 3). At 1366x768 the window gives the
// table's dock max(560, 45 % of 1366) = 614 px (MainWindow's first layout), so the
// table is 612 px wide. In lessons 4 (fifty boxes), 5, 9 and 11, after steps that
// give every value its full length, each cell of Before, After, Frame and Unit must
// be no wider than its column (its widest line in its own font, with the delegate's
// margins, measured here independently of the view), and those four columns must lie
// inside the viewport (no scrolling to see Frame or Unit).
//
// A quantity's name is never elided (its text with its indentation fits the Quantity
// column), a group's label spans its row, and a matrix has no trailing zeros.
//
// Negative control: the old sizing (resize to contents, Symbol at most 48 px,
// Quantity at most a third) in the same 612 px leaves a value or Unit off screen.
//
// Nothing scrolls sideways: the Source column takes the room that is left (its tooltip
// has the whole path). Also: the start before the first step; a collision step lists the collision first
// and says that integration's After is before the impulse.
#include "app/gui/panels/quantities/trace_model.h"
#include "app/gui/panels/quantities/trace_view.h"
#include "app/output/value_format.h"
#include "physics/engine/quantities.h"
#include "physics/engine/world.h"
#include "tests/test_support.h"

#include <QHeaderView>
#include <QScrollBar>
#include <QStyle>
#include <QtTest>

#include <functional>
#include <memory>

using namespace rbw;

namespace {

constexpr int kTableWidth = 612;   // 614 px dock at 1366x768, less its frame
constexpr int kValueColumns[] = {TraceModel::BeforeColumn, TraceModel::ValueColumn, TraceModel::FrameColumn,
                                 TraceModel::UnitColumn};

struct Stepped {
    std::unique_ptr<World> world;
    StepTrace trace;
};

Stepped stepScene(const QString& scene, int steps)
{
    Stepped s;
    s.world = std::make_unique<World>(test::lessonScene(scene));
    for (int k = 0; k < steps; ++k) {
        if (!s.world->step(&s.trace).ok) qFatal("%s blew up at step %d", qPrintable(scene), k);
    }
    return s;
}

void forEachRow(const QAbstractItemModel* m, const QModelIndex& parent, const std::function<void(const QModelIndex&)>& f)
{
    for (int r = 0; r < m->rowCount(parent); ++r) {
        const QModelIndex i = m->index(r, 0, parent);
        f(i);
        forEachRow(m, i, f);
    }
}

// The text's widest line in the cell's font plus QStyledItemDelegate's margins.
int textWidth(const QTreeView& view, const QModelIndex& i)
{
    const QString text = i.data(Qt::DisplayRole).toString();
    if (text.isEmpty()) return 0;
    const QVariant f = i.data(Qt::FontRole);
    const QFontMetrics fm(f.isValid() ? f.value<QFont>() : view.font());
    int w = 0;
    for (const QString& line : text.split('\n')) w = std::max(w, fm.horizontalAdvance(line));
    return w + 2 * (view.style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, &view) + 1);
}

// Every clipped cell and every value column outside the viewport, one line each.
QStringList misfits(const QTreeView& view, bool names = true)
{
    QStringList out;
    int cells = 0;
    forEachRow(view.model(), QModelIndex(), [&](const QModelIndex& row) {
        // A quantity's name is never elided: its text, indented by its depth (and the
        // root's decoration), fits its column; a group's label spans the whole row.
        if (!names) {
        } else if (view.model()->rowCount(row) > 0) {
            if (!view.isFirstColumnSpanned(row.row(), row.parent())) out << QStringLiteral("group %1 is not spanned").arg(row.data().toString());
        } else {
            int depth = 1;
            for (QModelIndex p = row.parent(); p.isValid(); p = p.parent()) ++depth;
            const int need = textWidth(view, row) + depth * view.indentation();
            if (need > view.columnWidth(TraceModel::QuantityColumn)) {
                out << QStringLiteral("name \"%1\" needs %2 px, has %3").arg(row.data().toString()).arg(need)
                           .arg(view.columnWidth(TraceModel::QuantityColumn));
            }
        }
        for (int c : kValueColumns) {
            const QModelIndex i = row.siblingAtColumn(c);
            const int need = textWidth(view, i);
            if (need > 0) ++cells;
            if (need > view.columnWidth(c)) {
                out << QStringLiteral("%1 / column %2: \"%3\" needs %4 px, has %5")
                           .arg(row.data().toString()).arg(c).arg(i.data().toString().replace('\n', " | "))
                           .arg(need).arg(view.columnWidth(c));
            }
        }
    });
    for (int c : kValueColumns) {
        const int right = view.columnViewportPosition(c) + view.columnWidth(c);
        if (right > view.viewport()->width()) {
            out << QStringLiteral("column %1 ends at %2 px, the viewport at %3").arg(c).arg(right).arg(view.viewport()->width());
        }
    }
    if (!out.isEmpty()) {
        for (int c : kValueColumns) {
            QString widest;
            int w = 0;
            forEachRow(view.model(), QModelIndex(), [&](const QModelIndex& row) {
                const int need = textWidth(view, row.siblingAtColumn(c));
                if (need > w) {
                    w = need;
                    widest = row.data().toString() + ": " + row.siblingAtColumn(c).data().toString().replace('\n', " | ");
                }
            });
            out << QStringLiteral("widest in column %1: %2").arg(c).arg(widest);
        }
        QStringList widths;
        for (int c = 0; c < TraceModel::FormulaColumn; ++c) widths << QString::number(view.columnWidth(c));
        out << QStringLiteral("column widths: %1").arg(widths.join(", "));
    }
    // A matrix (three lines) never shows trailing zeros ("1.000000", "0.2500").
    static const QRegularExpression trailingZero(QStringLiteral(R"(\d\.\d*0(?!\d))"));
    if (names) {
        forEachRow(view.model(), QModelIndex(), [&](const QModelIndex& row) {
            for (int c : {TraceModel::BeforeColumn, TraceModel::ValueColumn}) {
                const QString text = row.siblingAtColumn(c).data().toString();
                if (text.count('\n') == 2 && !text.startsWith('w') && text.contains(trailingZero)) {
                    out << QStringLiteral("%1: matrix with trailing zeros: %2").arg(row.data().toString(), QString(text).replace('\n', " | "));
                }
            }
        });
    }
    if (cells == 0) out << QStringLiteral("no cells at all");   // nothing checked is no pass
    return out;
}

// The sizing the window used before TraceView.
void oldSizing(QTreeView& view)
{
    view.expandAll();
    for (int c = 0; c < TraceModel::FormulaColumn; ++c) {
        view.resizeColumnToContents(c);
        if (c == TraceModel::SymbolColumn) view.setColumnWidth(c, std::min(view.columnWidth(c), 48));
        if (c == TraceModel::QuantityColumn) {
            view.setColumnWidth(c, std::min(view.columnWidth(c), std::max(170, view.viewport()->width() / 3)));
        }
    }
}

} // namespace

class TestTraceView : public QObject {
    Q_OBJECT
private slots:
    void valuesFitAt1366_data();
    void valuesFitAt1366();
    void startBeforeTheFirstStep();
    void collisionFirst();
    void namesComeFromTheCatalogue_data();
    void namesComeFromTheCatalogue();
    void matrixWithoutTrailingZeros();
};

void TestTraceView::valuesFitAt1366_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<int>("steps");
    QTest::addColumn<bool>("oldSizingFails");   // the negative control bites here
    QTest::newRow("lesson 4, fifty boxes") << "04-many-boxes/fifty-boxes.json" << 120 << true;
    QTest::newRow("lesson 5") << "05-spinning/scene.json" << 40 << true;
    QTest::newRow("lesson 9") << "09-tennis-racket/scene.json" << 150 << true;
    QTest::newRow("lesson 11") << "11-resting-contact/scene.json" << 45 << true;
}

void TestTraceView::valuesFitAt1366()
{
    QFETCH(QString, scene);
    QFETCH(int, steps);
    QFETCH(bool, oldSizingFails);
    Stepped s = stepScene(scene, steps);
    TraceModel model;
    TraceView view(&model);
    view.resize(kTableWidth, 480);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    model.setTrace(s.trace, s.world->scene());
    QApplication::processEvents();
    QStringList bad = misfits(view);
    QVERIFY2(bad.isEmpty(), qPrintable(bad.mid(0, 8).join('\n')));
    QVERIFY(model.matrixDigits() >= 3);
    QCOMPARE(view.horizontalScrollBar()->value(), 0);
    // Nothing to scroll sideways: Source takes the room that is left, elided there, with
    // its whole path in the tooltip (issue 20, item 3).
    QCOMPARE(view.horizontalScrollBar()->maximum(), 0);
    QVERIFY(view.header()->sectionPosition(TraceModel::SourceColumn) + view.columnWidth(TraceModel::SourceColumn)
            <= view.viewport()->width());

    // Playing on: the same rows with new values (dataChanged only); still no clipping.
    for (int k = 0; k < 7; ++k) QVERIFY(s.world->step(&s.trace).ok);
    model.setTrace(s.trace, s.world->scene());
    QApplication::processEvents();
    bad = misfits(view);
    QVERIFY2(bad.isEmpty(), qPrintable(bad.mid(0, 8).join('\n')));

    // A quantity's name is never elided (its text with its indentation fits the Quantity
// column), a group's label spans its row, and a matrix has no trailing zeros.
//
// Negative control: the old sizing in the same width leaves something off screen.
    TraceModel oldModel;
    QTreeView old;
    old.setModel(&oldModel);
    old.setColumnHidden(TraceModel::FormulaColumn, true);
    old.setIndentation(12);
    old.resize(kTableWidth, 480);
    old.show();
    QVERIFY(QTest::qWaitForWindowExposed(&old));
    oldModel.setTrace(s.trace, s.world->scene());
    oldSizing(old);
    QCOMPARE(!misfits(old, false).isEmpty(), oldSizingFails);   // the values alone
}

void TestTraceView::startBeforeTheFirstStep()
{
    // Lesson 1 (Table 2.1) before its step: x0 = (0, 0, 0), v0 = (0, 0, 0) and
    // omega0 = (1, 1, 1) rad/s... read from the world, shown in Before, After empty.
    World world(test::lessonScene("01-one-step/scene.json"));
    TraceModel model;
    TraceView view(&model);
    view.resize(kTableWidth, 480);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QCOMPARE(model.rowCount(), 0);
    model.setStart(world);
    QVERIFY(model.showsStart());
    QCOMPARE(model.rowCount(), 1);
    const QModelIndex group = model.index(0, 0);
    QVERIFY2(group.data().toString().startsWith("Start"), qPrintable(group.data().toString()));
    int rows = 0;
    forEachRow(&model, group, [&](const QModelIndex& row) {
        if (model.entryAt(row) == nullptr) return;
        ++rows;
        QVERIFY(!row.siblingAtColumn(TraceModel::BeforeColumn).data().toString().isEmpty());
        QVERIFY(row.siblingAtColumn(TraceModel::ValueColumn).data().toString().isEmpty());
        QVERIFY(row.siblingAtColumn(TraceModel::SourceColumn).data().toString().isEmpty());
    });
    QCOMPARE(rows, 7 * static_cast<int>(world.states().size()));   // x, v, q, R, L, I^-1, omega per body
    // The value is the world's: omega of body 0 in Before, as the trace would print it.
    const BodyState& s0 = world.states().front();
    bool found = false;
    forEachRow(&model, group, [&](const QModelIndex& row) {
        const TraceEntry* e = model.entryAt(row);
        if (e == nullptr || e->body != 0 || std::string_view(e->info->id) != "angular_velocity") return;
        found = true;
        QCOMPARE(row.siblingAtColumn(TraceModel::BeforeColumn).data().toString(), formatValueLines(TraceValue(s0.omega_W)));
    });
    QVERIFY(found);
    QVERIFY(misfits(view).isEmpty());
    // The first step replaces the start.
    StepTrace trace;
    QVERIFY(world.step(&trace).ok);
    model.setTrace(trace, world.scene());
    QVERIFY(!model.showsStart());
    QVERIFY(!model.index(0, 0).data().toString().startsWith("Start"));
}

void TestTraceView::collisionFirst()
{
    // Lesson 3: the corner hits the face in its second step (k = 1, docs of the lesson);
    // find the first step with a contact that is not separating.
    World world(test::lessonScene("03-two-box-collision/scene.json"));
    StepTrace trace;
    bool impulse = false;
    for (int k = 0; k < 3 && !impulse; ++k) {
        QVERIFY(world.step(&trace).ok);
        for (const ContactHeader& c : trace.contacts) impulse = impulse || !c.separating;
    }
    QVERIFY(impulse);
    TraceModel model;
    model.setTrace(trace, world.scene());
    QVERIFY(model.integrationBeforeImpulse());
    QCOMPARE(model.index(0, 0).data().toString(), QStringLiteral("Collisions"));
    bool integrationMarked = false;
    for (int r = 0; r < model.rowCount(); ++r) {
        const QString label = model.index(r, 0).data().toString();
        if (label.startsWith("Integration")) integrationMarked = label.contains("before the collision impulse");
    }
    QVERIFY(integrationMarked);
    // Negative control: a step without a collision keeps the pipeline's order.
    World free(test::lessonScene("02-single-body/scene.json"));
    QVERIFY(free.step(&trace).ok);
    model.setTrace(trace, free.scene());
    QVERIFY(!model.integrationBeforeImpulse());
    QCOMPARE(model.index(0, 0).data().toString(), QStringLiteral("Forces"));
}

// The Quantity column shows the catalogue's display name (QuantityInfo::name), with the
// force's or probe's number; a contact's rows carry no number (the group is the contact).
// The old names were made by replacing " a" with " A", which gave "kinetic energy After".
void TestTraceView::namesComeFromTheCatalogue_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<QString>("id");
    QTest::addColumn<QString>("name");
    const QString collision = QStringLiteral("03-two-box-collision/scene.json");
    const QString single = QStringLiteral("02-single-body/scene.json");
    const auto id = [](const QuantityInfo& q) { return QString::fromLatin1(q.id); };
    QTest::newRow("energy before") << collision << id(q::kinetic_energy_before) << QStringLiteral("kinetic energy before");
    QTest::newRow("energy after") << collision << id(q::kinetic_energy_after) << QStringLiteral("kinetic energy after");
    QTest::newRow("contact point") << collision << id(q::contact_point) << QStringLiteral("contact point");
    QTest::newRow("body A") << collision << id(q::velocity_a) << QStringLiteral("velocity A");
    QTest::newRow("inverse mass") << collision << id(q::inv_mass_a) << QStringLiteral("inverse mass A");
    QTest::newRow("omega") << single << id(q::angular_velocity) << QStringLiteral("angular velocity");
    QTest::newRow("force #0") << single << id(q::applied_force) << QStringLiteral("applied force #0");
    QTest::newRow("probe 0") << single << id(q::probe_position) << QStringLiteral("probe position (probe 0)");
}

void TestTraceView::namesComeFromTheCatalogue()
{
    QFETCH(QString, scene);
    QFETCH(QString, id);
    QFETCH(QString, name);
    // Lesson 3 up to its first impulse (as collisionFirst), lesson 2 one step.
    World world(test::lessonScene(scene));
    StepTrace trace;
    bool impulse = false;
    for (int k = 0; k < 3 && !impulse; ++k) {
        QVERIFY(world.step(&trace).ok);
        for (const ContactHeader& c : trace.contacts) impulse = impulse || !c.separating;
    }
    TraceModel model;
    model.setTrace(trace, world.scene());
    QString shown;
    forEachRow(&model, QModelIndex(), [&](const QModelIndex& row) {
        if (shown.isEmpty() && row.data(TraceModel::IdRole).toString() == id) shown = row.data(TraceModel::NameRole).toString();
    });
    QCOMPARE(shown, name);   // empty (the row was not found) fails too
}

// Lesson 5 at its start: R = Id and I⁻¹ = 6·Id show as "1", "6" and "0" (no
// "6.000000"), the tooltip has the whole value; a matrix with decimals keeps its points
// aligned (the same number of characters up to the point in every row).
void TestTraceView::matrixWithoutTrailingZeros()
{
    World w(test::lessonScene("05-spinning/scene.json"));
    TraceModel model;
    model.setStart(w);
    int matrices = 0;
    forEachRow(&model, QModelIndex(), [&](const QModelIndex& row) {
        if (row.data().toString() != QLatin1String("inverse inertia world")) return;
        const QModelIndex cell = row.siblingAtColumn(TraceModel::BeforeColumn);
        const QStringList lines = cell.data().toString().split('\n');
        QCOMPARE(lines.size(), 3);
        const QString fig(QChar(0x2007));
        QCOMPARE(lines[0], QString("6") + fig + "0" + fig + "0");
        QCOMPARE(lines[1], QString("0") + fig + "6" + fig + "0");
        QVERIFY2(cell.data(Qt::ToolTipRole).toString().contains("[[6, 0, 0], [0, 6, 0], [0, 0, 6]]"),
                 qPrintable(cell.data(Qt::ToolTipRole).toString()));
        ++matrices;
    });
    QCOMPARE(matrices, 2);
    // Decimals: entries 0.5, 12.25 and 3 in one column align on the point.
    Mat3 m = Mat3::Identity();
    m(0, 0) = 0.5;
    m(1, 0) = 12.25;
    m(2, 0) = 3.0;
    const QStringList lines = matrixLines(m, 7).split('\n');
    QCOMPARE(lines[0].indexOf('.'), lines[1].indexOf('.'));
    QVERIFY(lines[0].startsWith(QString(QChar(0x2007)) + "0.5"));
    QVERIFY(lines[2].startsWith(QString(QChar(0x2007)) + "3" + QChar(0x2008)));
}

QTEST_MAIN(TestTraceView)
#include "tst_trace_view.moc"
