#include "app/gui/shell/history_scrubber.h"

#include "app/core/session.h"
#include "app/core/step_numbering.h"

#include <QGridLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QTimer>

#include <algorithm>
#include <climits>

namespace rbw {

HistoryScrubber::HistoryScrubber(Session* session, QWidget* parent)
    : QWidget(parent)
    , session_(session)
{
    setObjectName("historyScrubber");
    // Two rows: the slider and Go to on the first, where the history stands (and any
    // note) on the second, so that the row fits beside a readable Lesson panel and the
    // quantities table at 1366 px (one row was about 650 px wide and squeezed the docks).
    auto* layout = new QGridLayout(this);
    layout->setContentsMargins(8, 3, 8, 3);
    layout->setHorizontalSpacing(8);
    layout->setVerticalSpacing(0);
    layout->setColumnStretch(1, 1);

    auto* title = new QLabel(tr("History"));
    title->setToolTip(tr("Every recorded step (up to the last 1000; fewer in a scene with many bodies, whose steps "
                         "take more memory). Drag to see the state and the numbers of "
                         "any recorded step exactly as they were computed. Stepping or playing from an earlier "
                         "step discards the later ones."));
    layout->addWidget(title, 0, 0);

    slider_ = new QSlider(Qt::Horizontal);
    slider_->setObjectName("historySlider");
    slider_->setRange(0, 0);
    slider_->setFocusPolicy(Qt::ClickFocus);
    slider_->setToolTip(title->toolTip());
    connect(slider_, &QSlider::valueChanged, this, &HistoryScrubber::onSliderValueChanged);
    layout->addWidget(slider_, 0, 1);

    label_ = new QLabel;
    label_->setObjectName("historyLabel");
    layout->addWidget(label_, 1, 1);
    note_ = new QLabel;
    note_->setObjectName("historyNote");
    note_->setStyleSheet("QLabel{color:#b3261e;font-weight:bold}");
    note_->setWordWrap(true);
    note_->hide();
    layout->addWidget(note_, 1, 2, 1, 3);
    noteTimer_ = new QTimer(this);
    noteTimer_->setSingleShot(true);
    noteTimer_->setInterval(8000);
    connect(noteTimer_, &QTimer::timeout, note_, &QWidget::hide);

    // The box takes n, the steps taken (the state at t_n, after step k = n - 1).
    layout->addWidget(new QLabel(tr("Go to n =")), 0, 2);
    stepBox_ = new QSpinBox;
    stepBox_->setObjectName("goToStepBox");
    stepBox_->setRange(0, 10000000);
    stepBox_->setKeyboardTracking(false);
    stepBox_->setFocusPolicy(Qt::ClickFocus);   // never takes the keys the view's shortcuts need by itself
    stepBox_->setToolTip(tr("n steps taken: the state at t_n, after step k = n − 1. A recorded step is shown exactly "
                            "as recorded; a later one is reached by stepping on."));
    layout->addWidget(stepBox_, 0, 3);
    goButton_ = new QPushButton(tr("Go"));
    goButton_->setObjectName("goToStepButton");
    goButton_->setFocusPolicy(Qt::TabFocus);
    connect(goButton_, &QPushButton::clicked, this, [this] {
        note_->hide();
        stepBox_->interpretText();
        emit stepRequested(stepBox_->value());
    });
    connect(stepBox_, &QSpinBox::editingFinished, this, [this] {
        if (!stepBox_->hasFocus()) return;
        note_->hide();
        emit stepRequested(stepBox_->value());
    });
    layout->addWidget(goButton_, 0, 4);
    stepBox_->installEventFilter(this);
    sync();
}

bool HistoryScrubber::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == stepBox_ && event->type() == QEvent::KeyPress &&
        static_cast<QKeyEvent*>(event)->key() == Qt::Key_Escape) {
        emit focusReturnRequested();   // the box loses the focus first ...
        sync();                        // ... so this drops what was typed
        return true;
    }
    return QWidget::eventFilter(watched, event);
}

void HistoryScrubber::sync()
{
    const World* world = session_->world();
    const StepHistory& h = session_->history();
    const bool any = world != nullptr && !h.empty();
    setEnabled(any);
    if (!any) {
        label_->setText(tr("no steps yet"));
        return;
    }
    // After a blow-up the world is one step past the last kept state (its numbers are
    // not results): the scrubber shows the kept state the run stopped after.
    const bool blownUp = !world->status().ok && world->stepIndex() != h.current().state.stepIndex;
    const long shown = blownUp ? h.current().state.stepIndex : world->stepIndex();
    syncing_ = true;
    {
        const QSignalBlocker block(slider_);
        const int first = static_cast<int>(std::min<long>(h.firstStep(), INT_MAX));
        const int last = static_cast<int>(std::min<long>(h.lastStep(), INT_MAX));
        slider_->setRange(first, last);
        slider_->setValue(static_cast<int>(std::min<long>(shown, INT_MAX)));
        slider_->setPageStep(std::max(1, (last - first) / 20));
    }
    syncing_ = false;
    // The box shows the current step, unless the student is typing one.
    if (!stepBox_->hasFocus()) {
        const QSignalBlocker block(stepBox_);
        stepBox_->setValue(static_cast<int>(std::min<long>(shown, stepBox_->maximum())));
    }
    // The slider's positions are states: n steps taken, shown by the step that led there
    // (app/core/step_numbering.h), as the 3D view's top line names it.
    QString text = tr("%1 · %2 of %3 steps").arg(steps::stateName(shown)).arg(shown).arg(h.lastStep());
    if (h.firstStep() > 0) text += tr(" (from n = %1)").arg(h.firstStep());
    if (blownUp) text += tr(" · the next step blew up");
    label_->setText(text);
}

void HistoryScrubber::showNote(const QString& text)
{
    note_->setText(text);
    note_->setToolTip(text);
    note_->show();
    noteTimer_->start();
}

void HistoryScrubber::onSliderValueChanged(int value)
{
    if (!syncing_) emit stepRequested(value);
}

} // namespace rbw
