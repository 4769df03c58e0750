// Every field the student types into gives the keys back (issue 20, items 3 and 5):
// Enter applies and Escape discards, and after either S (a window shortcut, as Step
// is) steps again without a click. One row per kind of field the window has: the
// editable combo box of h, the spin box of Go to step, the double spin boxes of c and
// μ. The keys are sent to the widget that has the focus, as X delivers them.
//
// The negative control is the old wiring (the filter on the combo box's inner line
// edit): there Escape neither discards nor gives the keys back, the bug the issue
// found under X.
//
// And the h field's text: h = 1/60 reads "0.0166667", as in the view's overlay, and
// that text stands for the exact 1/60 (fieldNumber), so Enter on it changes nothing.
#include "app/gui/style/field_keys.h"
#include "app/gui/style/number_text.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QSpinBox>
#include <QtTest>

using namespace rbw;

namespace {

// A window like the workbook's: a target that takes the keys (the 3D view, click
// focus only), the S shortcut, and one field that applies its value to `applied`.
struct Window {
    QWidget window;
    QWidget* view = nullptr;
    QWidget* field = nullptr;
    QAction* stepAction = nullptr;
    int steps = 0;
    double applied = 0.0;   // the "session's" value
    double start = 0.0;

    Window(const QString& kind, double value, bool filterOnInnerLineEdit = false)
        : applied(value)
        , start(value)
    {
        auto* layout = new QHBoxLayout(&window);
        view = new QWidget;
        view->setObjectName("view");
        view->setFocusPolicy(Qt::ClickFocus);
        view->setMinimumSize(100, 60);
        stepAction = new QAction(&window);
        stepAction->setShortcut(QKeySequence(Qt::Key_S));
        window.addAction(stepAction);
        QObject::connect(stepAction, &QAction::triggered, &window, [this] { ++steps; });
        std::function<void()> discard;
        if (kind == "h") {
            auto* box = new QComboBox;
            box->setEditable(true);
            box->setInsertPolicy(QComboBox::NoInsert);
            box->setValidator(new QDoubleValidator(1e-9, 1e3, 12, box));
            box->setEditText(shortNumber(value));
            QObject::connect(box->lineEdit(), &QLineEdit::editingFinished, box, [this, box] {
                bool ok = false;
                const double h = fieldNumber(box->currentText(), applied, &ok);
                if (ok) applied = h;
            });
            discard = [this, box] { box->setEditText(shortNumber(applied)); };
            field = box;
        } else if (kind == "step") {
            auto* box = new QSpinBox;
            box->setRange(0, 1000);
            box->setKeyboardTracking(false);
            box->setValue(static_cast<int>(value));
            QObject::connect(box, &QSpinBox::editingFinished, box, [this, box] {
                if (box->hasFocus()) applied = box->value();
            });
            discard = [this, box] { box->setValue(static_cast<int>(applied)); };
            field = box;
        } else {
            auto* box = new QDoubleSpinBox;
            box->setRange(0.0, 5.0);
            box->setDecimals(2);
            box->setKeyboardTracking(false);
            box->setValue(value);
            QObject::connect(box, &QDoubleSpinBox::valueChanged, box, [this](double v) { applied = v; });
            discard = [this, box] {
                const QSignalBlocker block(box);
                box->setValue(applied);
            };
            field = box;
        }
        QWidget* filtered = field;
        if (filterOnInnerLineEdit) filtered = field->findChild<QLineEdit*>();
        new FieldKeys(filtered, view, discard);
        layout->addWidget(view);
        layout->addWidget(field);
    }
};

void typeInto(QWidget* field, const QString& text)
{
    field->setFocus(Qt::MouseFocusReason);
    QTRY_VERIFY(field->hasFocus());
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(QApplication::focusWidget(), text);
}

} // namespace

class TestFieldKeys : public QObject {
    Q_OBJECT
private slots:
    void enterAppliesEscapeDiscards_data();
    void enterAppliesEscapeDiscards();
    void innerLineEditFilterMissesTheKeys();
    void shortNumberStandsForTheExactValue_data();
    void shortNumberStandsForTheExactValue();
};

void TestFieldKeys::enterAppliesEscapeDiscards_data()
{
    QTest::addColumn<QString>("kind");
    QTest::addColumn<double>("start");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<int>("key");
    QTest::addColumn<double>("expected");   // the applied value afterwards
    const double h = 1.0 / 60.0;            // lesson 11
    QTest::newRow("h, Enter applies") << "h" << h << "0.04" << int(Qt::Key_Return) << 0.04;
    QTest::newRow("h, Escape discards") << "h" << h << "0.04" << int(Qt::Key_Escape) << h;
    QTest::newRow("Go to step, Enter applies") << "step" << 0.0 << "12" << int(Qt::Key_Enter) << 12.0;
    QTest::newRow("Go to step, Escape discards") << "step" << 0.0 << "12" << int(Qt::Key_Escape) << 0.0;
    QTest::newRow("c, Enter applies") << "c" << 1.0 << "0.5" << int(Qt::Key_Return) << 0.5;
    QTest::newRow("c, Escape discards") << "c" << 1.0 << "0.5" << int(Qt::Key_Escape) << 1.0;
    QTest::newRow("mu, Enter applies") << "mu" << 0.0 << "0.25" << int(Qt::Key_Enter) << 0.25;
    QTest::newRow("mu, Escape discards") << "mu" << 0.0 << "0.25" << int(Qt::Key_Escape) << 0.0;
}

void TestFieldKeys::enterAppliesEscapeDiscards()
{
    QFETCH(QString, kind);
    QFETCH(double, start);
    QFETCH(QString, typed);
    QFETCH(int, key);
    QFETCH(double, expected);
    Window w(kind, start);
    w.window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w.window));
    QApplication::setActiveWindow(&w.window);
    typeInto(w.field, typed);
    // While the field has the keys, S is typed into it (or refused), no step.
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_S);
    QCOMPARE(w.steps, 0);
    QTest::keyClick(QApplication::focusWidget(), Qt::Key(key));
    QTRY_VERIFY2(w.view->hasFocus(), qPrintable(QStringLiteral("focus in %1").arg(
                                         QApplication::focusWidget() ? QApplication::focusWidget()->metaObject()->className()
                                                                     : "nothing")));
    QCOMPARE(w.applied, expected);
    // S steps again, and nothing typed is applied later (the focus has left already).
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_S);
    QCOMPARE(w.steps, 1);
    w.field->setFocus(Qt::MouseFocusReason);
    w.view->setFocus(Qt::MouseFocusReason);
    QCOMPARE(w.applied, expected);
}

void TestFieldKeys::innerLineEditFilterMissesTheKeys()
{
    // The old wiring: a filter on the combo box's line edit. The combo box keeps the
    // focus and hands the keys to its line edit directly: Escape is never seen.
    Window w("h", 1.0 / 60.0, /*filterOnInnerLineEdit=*/true);
    w.window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w.window));
    QApplication::setActiveWindow(&w.window);
    typeInto(w.field, "0.04");
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Escape);
    QTest::qWait(50);
    QVERIFY(!w.view->hasFocus());
    QCOMPARE(static_cast<QComboBox*>(w.field)->currentText(), QStringLiteral("0.04"));
}

void TestFieldKeys::shortNumberStandsForTheExactValue_data()
{
    QTest::addColumn<double>("h");
    QTest::addColumn<QString>("text");   // as the overlay prints it: 'g' with 6 digits
    QTest::newRow("1/60, lesson 11") << 1.0 / 60.0 << "0.0166667";
    QTest::newRow("1/30") << 1.0 / 30.0 << "0.0333333";
    QTest::newRow("0.01, lesson 2") << 0.01 << "0.01";
    QTest::newRow("0.001") << 0.001 << "0.001";
    QTest::newRow("1e-05") << 1e-5 << "1e-05";
    QTest::newRow("2") << 2.0 << "2";
}

void TestFieldKeys::shortNumberStandsForTheExactValue()
{
    QFETCH(double, h);
    QFETCH(QString, text);
    QCOMPARE(shortNumber(h), text);
    QVERIFY(text.size() <= 9);   // fits the h box (9 characters wide)
    bool ok = false;
    QCOMPARE(fieldNumber(text, h, &ok), h);   // exactly, not the rounded 0.0166667
    QVERIFY(ok);
    QCOMPARE(fieldNumber(QStringLiteral(" %1 ").arg(text), h, &ok), h);
    // Typed while another value is shown, the text is read as typed.
    QCOMPARE(fieldNumber(text, 0.5, &ok), text.toDouble());
    fieldNumber(QStringLiteral("0.0x"), h, &ok);
    QVERIFY(!ok);
}

QTEST_MAIN(TestFieldKeys)
#include "tst_field_keys.moc"
