// The parameter bar bound to a Session, without the main window: it shows the
// session's scene, writes each control through the session's setters, follows the
// session when a parameter changes elsewhere, refuses a bad h with a message and
// shows the old value again, and reports the playback speed.
#include "app/core/session.h"
#include "app/gui/shell/parameter_bar.h"
#include "physics/engine/integrator_registry.h"
#include "tests/test_support.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QSignalSpy>
#include <QtTest>

using namespace rbw;
using rbw::test::lessonScene;

class TestParameterBar : public QObject {
    Q_OBJECT
private slots:
    void showsTheLoadedScene();
    void controlsWriteThroughTheSession();
    void followsTheSession();
    void badDtIsRefused();
    void speedNotches_data();
    void speedNotches();
    void perBodyIntegratorsDisableTheBox();
    void integratorsByName_data();
    void integratorsByName();
};

void TestParameterBar::showsTheLoadedScene()
{
    Session s;
    ParameterBar bar(&s);
    s.load(lessonScene("07-bounce/scene.json"));   // dt 0.005, explicit Euler, g, c 0.8
    QCOMPARE(bar.findChild<QComboBox*>("dtBox")->currentText(), QString("0.005"));
    // The integrator by its catalogue name, its id as the item's data.
    QCOMPARE(bar.findChild<QComboBox*>("integratorBox")->currentText(), QString("explicit Euler"));
    QCOMPARE(bar.findChild<QComboBox*>("integratorBox")->currentData().toString(), QString("explicit-euler"));
    QVERIFY(bar.findChild<QCheckBox*>("gravityBox")->isChecked());
    QCOMPARE(bar.findChild<QDoubleSpinBox*>("restitutionBox")->value(), 0.8);
    QVERIFY(bar.findChild<QDoubleSpinBox*>("restitutionBox")->isEnabled());   // lesson 7 has a ground plane

    // Lesson 1 cannot collide: c and mu are shown but disabled.
    s.load(lessonScene("01-one-step/scene.json"));
    QCOMPARE(bar.findChild<QComboBox*>("dtBox")->currentText(), QString("2"));
    QVERIFY(!bar.findChild<QDoubleSpinBox*>("restitutionBox")->isEnabled());
    QVERIFY(!bar.findChild<QDoubleSpinBox*>("frictionBox")->isEnabled());
}

void TestParameterBar::controlsWriteThroughTheSession()
{
    Session s;
    ParameterBar bar(&s);
    s.load(lessonScene("07-bounce/scene.json"));
    bar.findChild<QDoubleSpinBox*>("restitutionBox")->setValue(0.3);
    QCOMPARE(s.world()->scene().restitution, 0.3);
    bar.findChild<QDoubleSpinBox*>("frictionBox")->setValue(0.25);
    QCOMPARE(s.world()->scene().friction, 0.25);
    bar.findChild<QCheckBox*>("gravityBox")->setChecked(false);
    QVERIFY(!s.gravityEnabled());
    auto* integrators = bar.findChild<QComboBox*>("integratorBox");
    const int rk4 = integrators->findData("rk4");
    QVERIFY(rk4 >= 0);
    integrators->activated(rk4);   // as a click on the list
    QCOMPARE(s.world()->scene().integrator, std::string("rk4"));
    auto* dt = bar.findChild<QComboBox*>("dtBox");
    dt->setEditText("0.002");
    dt->lineEdit()->editingFinished();   // as Enter
    QCOMPARE(s.world()->scene().dt, 0.002);
    // The keys' versions.
    bar.scaleDt(0.5);
    QCOMPARE(s.world()->scene().dt, 0.001);
    bar.stepRestitution(-1);
    RBW_COMPARE_NEAR_STRICT(s.world()->scene().restitution, 0.25, 1e-12);
    bar.stepFriction(+2);
    RBW_COMPARE_NEAR_STRICT(s.world()->scene().friction, 0.35, 1e-12);
    bar.cycleIntegrator(+1);
    QVERIFY(s.world()->scene().integrator != "rk4");
    bar.cycleIntegrator(-1);
    QCOMPARE(s.world()->scene().integrator, std::string("rk4"));
}

void TestParameterBar::followsTheSession()
{
    Session s;
    ParameterBar bar(&s);
    s.load(lessonScene("07-bounce/scene.json"));
    QVERIFY(s.setDt(0.01));
    QVERIFY(s.setFriction(0.4));
    s.setGravityEnabled(false);
    QCOMPARE(bar.findChild<QComboBox*>("dtBox")->currentText(), QString("0.01"));
    QCOMPARE(bar.findChild<QDoubleSpinBox*>("frictionBox")->value(), 0.4);
    QVERIFY(!bar.findChild<QCheckBox*>("gravityBox")->isChecked());
    // Following the session does not write back into it (no second rebuild).
    QSignalSpy changed(&s, &Session::parametersChanged);
    QVERIFY(s.setRestitution(0.6));
    QCOMPARE(changed.count(), 1);
}

void TestParameterBar::badDtIsRefused()
{
    Session s;
    ParameterBar bar(&s);
    s.load(lessonScene("07-bounce/scene.json"));
    QSignalSpy message(&bar, &ParameterBar::messageRequested);
    auto* dt = bar.findChild<QComboBox*>("dtBox");
    dt->setEditText("abc");
    dt->lineEdit()->editingFinished();
    QCOMPARE(message.count(), 1);
    QVERIFY2(message.first().first().toString().startsWith("h not changed"), qPrintable(message.first().first().toString()));
    QCOMPARE(s.world()->scene().dt, 0.005);
    QCOMPARE(dt->currentText(), QString("0.005"));   // the old value again
}

void TestParameterBar::speedNotches_data()
{
    QTest::addColumn<int>("notches");   // + faster, - slower, from 1x
    QTest::addColumn<double>("speed");
    QTest::newRow("1x") << 0 << 1.0;
    QTest::newRow("2x") << 1 << 2.0;
    QTest::newRow("as fast as possible") << 10 << -1.0;
    QTest::newRow("1/2x") << -1 << 0.5;
    QTest::newRow("1 step/frame") << -10 << 0.0;
}

void TestParameterBar::speedNotches()
{
    QFETCH(int, notches);
    QFETCH(double, speed);
    Session s;
    ParameterBar bar(&s);
    QCOMPARE(bar.speed(), 1.0);
    QSignalSpy changed(&bar, &ParameterBar::speedChanged);
    for (int i = 0; i < std::abs(notches); ++i) notches > 0 ? bar.faster() : bar.slower();
    QCOMPARE(bar.speed(), speed);
    if (notches != 0) QCOMPARE(changed.last().first().toDouble(), speed);
}

void TestParameterBar::perBodyIntegratorsDisableTheBox()
{
    // Lesson 9 sets an integrator per body: the box would change none of them.
    Session s;
    ParameterBar bar(&s);
    s.load(lessonScene("09-tennis-racket/scene.json"));
    QVERIFY(!bar.findChild<QComboBox*>("integratorBox")->isEnabled());
    const std::string before = s.world()->scene().integrator;
    bar.cycleIntegrator(+1);
    QCOMPARE(s.world()->scene().integrator, before);
}

// The Integrator box shows the catalogue's names (issue 20: it showed ids, "rk4"),
// in the catalogue's order; each item carries its id, and choosing it runs that id.
void TestParameterBar::integratorsByName_data()
{
    QTest::addColumn<QString>("id");
    QTest::addColumn<QString>("shown");   // physics/engine/integrator_registry.cpp's title
    QTest::newRow("explicit-euler") << "explicit-euler" << "explicit Euler";
    QTest::newRow("symplectic-euler") << "symplectic-euler" << "symplectic Euler";
    QTest::newRow("rk4") << "rk4" << QStringLiteral("classical Runge–Kutta (RK4)");
    QTest::newRow("implicit-midpoint") << "implicit-midpoint" << "implicit midpoint";
}

void TestParameterBar::integratorsByName()
{
    QFETCH(QString, id);
    QFETCH(QString, shown);
    Session s;
    ParameterBar bar(&s);
    s.load(lessonScene("07-bounce/scene.json"));
    auto* box = bar.findChild<QComboBox*>("integratorBox");
    QCOMPARE(box->count(), static_cast<int>(integratorCatalogue().size()));
    for (int i = 0; i < box->count(); ++i) {
        const IntegratorInfo& info = integratorCatalogue()[static_cast<std::size_t>(i)];
        QCOMPARE(box->itemData(i).toString(), QString::fromLatin1(info.name));
        QCOMPARE(box->itemText(i), QString::fromUtf8(info.title));
        QVERIFY(box->itemText(i) != box->itemData(i).toString());   // a name, never the id
    }
    const int item = box->findText(shown);
    QVERIFY2(item >= 0, qPrintable(shown));
    QCOMPARE(box->itemData(item).toString(), id);
    QCOMPARE(box->findText(id), -1);   // the id itself is nowhere on screen
    emit box->activated(item);   // as a click on the list
    QCOMPARE(QString::fromStdString(s.world()->scene().integrator), id);
    // The box follows the session by id.
    QVERIFY(s.setIntegrator(QStringLiteral("explicit-euler")));
    QCOMPARE(box->currentText(), QStringLiteral("explicit Euler"));
}

QTEST_MAIN(TestParameterBar)
#include "tst_parameter_bar.moc"
