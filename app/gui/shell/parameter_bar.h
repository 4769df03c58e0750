// The parameter bar: playback speed, h, the integrator, gravity, the coefficient of
// restitution c and the friction coefficient μ. Bound to a Session: it shows the
// session's current scene, writes every change through the session's setters (which
// validate and rebuild the world), and follows the session when its parameters
// change from elsewhere (a key, a new lesson, reset). The speed is not the
// session's: it paces Play, so the bar only reports it (speedChanged).
#pragma once

#include <QList>
#include <QToolBar>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;

namespace rbw {

class FieldKeys;
class Session;

class ParameterBar : public QToolBar {
    Q_OBJECT
public:
    explicit ParameterBar(Session* session, QWidget* parent = nullptr);

    // Simulated seconds per wall-clock second; 0 one step per frame; -1 as fast as possible.
    double speed() const;

    // The keys' versions of the controls (Help -> Keys): one speed notch slower or
    // faster, h times a factor, the next or previous integrator, c or μ by one step
    // of their box (0.05).
    void slower();
    void faster();
    void scaleDt(double factor);
    void cycleIntegrator(int direction);
    void stepRestitution(int steps);
    void stepFriction(int steps);

    // Shows the session's parameters (called when they change).
    void syncFromSession();

    // Where the keys go after an edit: Enter (apply) or Escape (discard the typed text)
    // in h, c or μ, and a pick in a drop-down list, hand the keyboard focus to this
    // widget (the 3D view), so S, Space and the arrows step and play again instead of
    // typing into the box.
    // The keys of the typed boxes are FieldKeys (app/gui/style/field_keys.h), the one
    // Enter/Escape rule of every field.
    void setFocusReturnTarget(QWidget* target);
    QWidget* focusReturnTarget() const { return focusTarget_; }

signals:
    void speedChanged(double speed);
    // A refused change, for the status bar: "h not changed: ...".
    void messageRequested(const QString& text, int timeoutMs);

private:
    void onSpeedIndexChanged(int index);
    void onDtEdited();
    void onIntegratorActivated(int index);
    void onGravityToggled(bool on);
    void onRestitutionChanged(double c);
    void onFrictionChanged(double mu);

    Session* session_;
    QComboBox* speedBox_ = nullptr;
    QComboBox* dtBox_ = nullptr;
    QComboBox* integratorBox_ = nullptr;
    QCheckBox* gravityBox_ = nullptr;
    QDoubleSpinBox* restitutionBox_ = nullptr;
    QDoubleSpinBox* frictionBox_ = nullptr;
    bool syncing_ = false;   // the controls are being set from the session
    QWidget* focusTarget_ = nullptr;
    QList<FieldKeys*> fieldKeys_;   // on h, c and μ

    void returnFocus();
    void discardTyping();   // Escape: the boxes show the session's values again
};

} // namespace rbw
