#include "app/gui/shell/parameter_bar.h"

#include "app/core/playback_clock.h"
#include "app/core/session.h"
#include "app/gui/style/field_keys.h"
#include "app/gui/style/number_text.h"
#include "physics/engine/integrator_registry.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QDoubleValidator>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPointer>
#include <QTimer>

#include <algorithm>

namespace rbw {

namespace {

constexpr int kMessageMs = 5000;

} // namespace

ParameterBar::ParameterBar(Session* session, QWidget* parent)
    : QToolBar(tr("Parameters"), parent)
    , session_(session)
{
    setObjectName("parameterToolBar");

    speedBox_ = new QComboBox;
    speedBox_->setObjectName("speedBox");
    speedBox_->setToolTip(tr("Playback speed ([ slower, ] faster)"));
    // Simulated seconds per wall-clock second; 0: one step per frame; -1: as fast as possible.
    const QList<QPair<QString, double>> speeds = {
        {tr("1 step/frame"), PlaybackClock::kOneStepPerTick},
        {tr("¼× real time"), 0.25},
        {tr("½× real time"), 0.5},
        {tr("1× real time"), 1.0},
        {tr("2× real time"), 2.0},
        {tr("5× real time"), 5.0},
        {tr("10× real time"), 10.0},
        {tr("as fast as possible"), PlaybackClock::kAsFastAsPossible}};
    for (const auto& [label, value] : speeds) speedBox_->addItem(label, value);
    speedBox_->setCurrentIndex(3);   // 1x, PlaybackClock's default
    connect(speedBox_, &QComboBox::currentIndexChanged, this, &ParameterBar::onSpeedIndexChanged);
    addWidget(new QLabel(tr(" Speed ")));
    addWidget(speedBox_);

    dtBox_ = new QComboBox;
    dtBox_->setObjectName("dtBox");
    dtBox_->setEditable(true);
    dtBox_->setToolTip(tr("Time step h in seconds (type a value and press Enter)"));
    for (const char* h : {"2", "1", "0.1", "0.05", "0.02", "0.01", "0.005", "0.001", "0.0001"}) dtBox_->addItem(h);
    auto* validator = new QDoubleValidator(1e-9, 1e3, 12, dtBox_);
    validator->setNotation(QDoubleValidator::ScientificNotation);
    dtBox_->setValidator(validator);
    dtBox_->setMinimumContentsLength(9);
    dtBox_->setInsertPolicy(QComboBox::NoInsert);
    connect(dtBox_->lineEdit(), &QLineEdit::editingFinished, this, &ParameterBar::onDtEdited);
    // Picking a listed value applies it as Enter would.
    connect(dtBox_, &QComboBox::activated, this, &ParameterBar::onDtEdited);
    addWidget(new QLabel(tr("  h ")));
    addWidget(dtBox_);

    integratorBox_ = new QComboBox;
    integratorBox_->setObjectName("integratorBox");
    for (const IntegratorInfo& info : integratorCatalogue()) {
        // The catalogue's name on screen ("classical Runge–Kutta (RK4)"), the id ("rk4")
        // as the item's data: the scene file and the session speak ids (issue 20).
        const QString id = QString::fromLatin1(info.name);
        integratorBox_->addItem(*info.title != '\0' ? QString::fromUtf8(info.title) : id, id);
        integratorBox_->setItemData(integratorBox_->count() - 1,
                                    QStringLiteral("%1 (%2)").arg(QString::fromUtf8(info.summary), id), Qt::ToolTipRole);
    }
    connect(integratorBox_, &QComboBox::activated, this, &ParameterBar::onIntegratorActivated);
    addWidget(new QLabel(tr("  Integrator ")));
    addWidget(integratorBox_);

    gravityBox_ = new QCheckBox(tr("Gravity"));
    gravityBox_->setObjectName("gravityBox");
    gravityBox_->setToolTip(tr("Gravity on/off (G)"));
    connect(gravityBox_, &QCheckBox::toggled, this, &ParameterBar::onGravityToggled);
    addWidget(new QLabel("  "));
    addWidget(gravityBox_);

    auto coefficientBox = [this](const QString& name, const QString& label, const QString& tip, double max) {
        auto* box = new QDoubleSpinBox;
        box->setObjectName(name);
        box->setRange(0.0, max);
        box->setSingleStep(0.05);
        box->setDecimals(2);
        box->setToolTip(tip);
        box->setKeyboardTracking(false);
        addWidget(new QLabel(label));
        addWidget(box);
        return box;
    };
    restitutionBox_ = coefficientBox("restitutionBox", tr("  c "),
                                     tr("Coefficient of restitution c (0 plastic, 1 elastic)"), 1.0);
    connect(restitutionBox_, &QDoubleSpinBox::valueChanged, this, &ParameterBar::onRestitutionChanged);
    frictionBox_ = coefficientBox("frictionBox", tr("  μ "), tr("Coulomb friction coefficient μ"), 5.0);
    connect(frictionBox_, &QDoubleSpinBox::valueChanged, this, &ParameterBar::onFrictionChanged);

    connect(session_, &Session::parametersChanged, this, &ParameterBar::syncFromSession);
    syncFromSession();

    // Enter and Escape in the boxes that take typed text hand the keys back (see
    // setFocusReturnTarget); so does a pick in a list. The filter sits on the box itself:
    // a combo box passes its keys to its line edit directly, unseen by a filter there.
    for (QWidget* box : {static_cast<QWidget*>(dtBox_), static_cast<QWidget*>(restitutionBox_),
                         static_cast<QWidget*>(frictionBox_)}) {
        fieldKeys_.append(new FieldKeys(box, focusTarget_, [this] { discardTyping(); }));
    }
    for (QComboBox* box : {speedBox_, integratorBox_}) {
        connect(box, &QComboBox::activated, this, &ParameterBar::returnFocus);
    }
}

void ParameterBar::returnFocus()
{
    // After the box has handled the key (Enter applies the value first).
    QPointer<QWidget> target = focusTarget_;
    QTimer::singleShot(0, this, [target] {
        if (target) target->setFocus(Qt::OtherFocusReason);
    });
}

void ParameterBar::setFocusReturnTarget(QWidget* target)
{
    focusTarget_ = target;
    for (FieldKeys* keys : fieldKeys_) keys->setTarget(target);
}

void ParameterBar::discardTyping()
{
    // What was typed goes; the focus leaves next (FieldKeys), and a box that applies
    // its text on focus-out then applies the session's own value, which changes nothing.
    if (!session_->isLoaded()) return;
    syncing_ = true;
    const SceneDef& scene = session_->world()->scene();
    restitutionBox_->setValue(scene.restitution);
    frictionBox_->setValue(scene.friction);
    dtBox_->setEditText(shortNumber(scene.dt));
    syncing_ = false;
}

double ParameterBar::speed() const
{
    return speedBox_->currentData().toDouble();
}

void ParameterBar::slower()
{
    speedBox_->setCurrentIndex(std::max(0, speedBox_->currentIndex() - 1));
}

void ParameterBar::faster()
{
    speedBox_->setCurrentIndex(std::min(speedBox_->count() - 1, speedBox_->currentIndex() + 1));
}

void ParameterBar::scaleDt(double factor)
{
    if (!session_->isLoaded()) return;
    QString error;
    if (!session_->setDt(session_->world()->scene().dt * factor, &error)) emit messageRequested(error, kMessageMs);
}

void ParameterBar::cycleIntegrator(int direction)
{
    if (!integratorBox_->isEnabled() || integratorBox_->count() == 0 || !session_->isLoaded()) return;
    const int n = integratorBox_->count();
    const int next = (integratorBox_->currentIndex() + direction % n + n) % n;
    QString error;
    if (!session_->setIntegrator(integratorBox_->itemData(next).toString(), &error)) emit messageRequested(error, kMessageMs);
}

void ParameterBar::stepRestitution(int steps)
{
    restitutionBox_->stepBy(steps);
}

void ParameterBar::stepFriction(int steps)
{
    frictionBox_->stepBy(steps);
}

void ParameterBar::syncFromSession()
{
    const World* world = session_->world();
    if (world == nullptr) return;
    syncing_ = true;
    const SceneDef& scene = world->scene();
    // Not while the student is typing a value.
    if (!dtBox_->lineEdit()->hasFocus()) dtBox_->setEditText(shortNumber(scene.dt));
    integratorBox_->setCurrentIndex(integratorBox_->findData(QString::fromStdString(scene.integrator)));
    // A lesson that compares integrators side by side sets one per body: the box
    // would change only the bodies without their own.
    const bool perBody = std::any_of(scene.bodies.begin(), scene.bodies.end(),
                                     [](const BodyDef& b) { return !b.integrator.empty(); });
    integratorBox_->setEnabled(!perBody);
    integratorBox_->setToolTip(perBody ? tr("This lesson sets an integrator for each body (see the lesson text)")
                                       : tr("The integrator of every body"));
    gravityBox_->setChecked(scene.hasGravity());
    const bool collides = world->runsCollisionStage();
    restitutionBox_->setEnabled(collides);
    frictionBox_->setEnabled(collides);
    restitutionBox_->setValue(scene.restitution);
    frictionBox_->setValue(scene.friction);
    syncing_ = false;
}

void ParameterBar::onSpeedIndexChanged(int index)
{
    emit speedChanged(speedBox_->itemData(index).toDouble());
}

void ParameterBar::onDtEdited()
{
    if (syncing_ || !session_->isLoaded()) return;
    bool ok = false;
    // The box shows h in 6 figures ("0.0166667" for 1/60): that text stands for the exact h.
    const double h = fieldNumber(dtBox_->currentText(), session_->world()->scene().dt, &ok);
    if (ok && h == session_->world()->scene().dt) return;
    QString error;
    if (!ok || !session_->setDt(h, &error)) {
        emit messageRequested(tr("h not changed: %1").arg(ok ? error : tr("not a number")), kMessageMs);
        syncFromSession();
    }
}

void ParameterBar::onIntegratorActivated(int index)
{
    if (syncing_ || !session_->isLoaded()) return;
    QString error;
    if (!session_->setIntegrator(integratorBox_->itemData(index).toString(), &error)) {
        emit messageRequested(error, kMessageMs);
        syncFromSession();
    }
}

void ParameterBar::onGravityToggled(bool on)
{
    if (!syncing_ && session_->isLoaded()) session_->setGravityEnabled(on);
}

void ParameterBar::onRestitutionChanged(double c)
{
    QString error;
    if (!syncing_ && session_->isLoaded() && !session_->setRestitution(c, &error)) emit messageRequested(error, kMessageMs);
}

void ParameterBar::onFrictionChanged(double mu)
{
    QString error;
    if (!syncing_ && session_->isLoaded() && !session_->setFriction(mu, &error)) emit messageRequested(error, kMessageMs);
}

} // namespace rbw
