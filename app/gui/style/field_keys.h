// How every field the student types into gives the keys back (issue 20, item 5):
// Enter applies what was typed and Escape discards it, and both hand the keyboard
// focus to the 3D view, so S, Space and the arrows step and play again without a
// click. FieldKeys is an event filter on the field the focus is in: the QComboBox of
// an editable box (h), a QSpinBox (Go to step), a QDoubleSpinBox (c, μ).
//
// It must sit on that widget, not on its inner QLineEdit: a combo box and a spin box
// keep the focus themselves and pass the keys on to their line edit with a direct
// call, which no filter on the line edit sees (why Escape in h did nothing).
//
//   new FieldKeys(box, view, [this] { /* put the session's value back in box */ });
//
// Enter: the field applies its text as it always does (editingFinished, valueChanged),
// then the focus goes to the target. Escape: `discard` puts the current value back
// (before the focus leaves, so a field that applies on focus-out applies nothing),
// then the focus goes to the target; the key goes no further.
#pragma once

#include <QEvent>
#include <QKeyEvent>
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <QWidget>

#include <functional>
#include <utility>

namespace rbw {

class FieldKeys : public QObject {
public:
    FieldKeys(QWidget* field, QWidget* target, std::function<void()> discard)
        : QObject(field)
        , target_(target)
        , discard_(std::move(discard))
    {
        field->installEventFilter(this);
    }

    void setTarget(QWidget* target) { target_ = target; }
    QWidget* target() const { return target_; }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() != QEvent::KeyPress || target_ == nullptr) return QObject::eventFilter(watched, event);
        const int key = static_cast<QKeyEvent*>(event)->key();
        if (key == Qt::Key_Escape) {
            if (discard_) discard_();
            target_->setFocus(Qt::OtherFocusReason);
            return true;
        }
        if (key == Qt::Key_Return || key == Qt::Key_Enter) {
            // After the field has handled the key (it applies the value first).
            QPointer<QWidget> target = target_;
            QTimer::singleShot(0, this, [target] {
                if (target) target->setFocus(Qt::OtherFocusReason);
            });
        }
        return QObject::eventFilter(watched, event);
    }

private:
    QPointer<QWidget> target_;
    std::function<void()> discard_;
};

} // namespace rbw
