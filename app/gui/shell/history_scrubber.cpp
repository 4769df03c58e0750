#include "app/gui/shell/history_scrubber.h"

#include "app/core/session.h"
#include "app/core/step_numbering.h"

#include <QGridLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QPainter>
#include <QStyle>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QTimer>

#include <algorithm>
#include <climits>

namespace rbw {

namespace {

// A red tick over the slider at one value (the first divergence); the mouse goes
// through it to the slider.
class SliderMark : public QWidget {
public:
    SliderMark(QSlider* slider, const long* mark) : QWidget(slider), slider_(slider), mark_(mark)
    {
        setAttribute(Qt::WA_TransparentForMouseEvents);
        slider->installEventFilter(this);
    }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (watched == slider_ && (event->type() == QEvent::Resize || event->type() == QEvent::Show)) {
            setGeometry(slider_->rect());
        }
        return QWidget::eventFilter(watched, event);
    }
    void paintEvent(QPaintEvent*) override
    {
        const long n = *mark_;
        if (n < slider_->minimum() || n > slider_->maximum() || slider_->maximum() <= slider_->minimum()) return;
        const int handle = slider_->style()->pixelMetric(QStyle::PM_SliderLength, nullptr, slider_);
        const int x = QStyle::sliderPositionFromValue(slider_->minimum(), slider_->maximum(), static_cast<int>(n),
                                                      width() - handle) + handle / 2;
        QPainter p(this);
        p.setRenderHint(QPainter::Antialiasing);
        p.setPen(QPen(QColor(0xb3, 0x26, 0x1e), 2));
        p.drawLine(x, 1, x, height() - 1);
        p.setBrush(QColor(0xb3, 0x26, 0x1e));
        p.drawPolygon(QPolygon({QPoint(x - 4, 0), QPoint(x + 4, 0), QPoint(x, 5)}));
    }

private:
    QSlider* slider_;
    const long* mark_;
};

} // namespace

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

    sliderTip_ = title->toolTip();
    markOverlay_ = new SliderMark(slider_, &mark_);

    label_ = new QLabel;
    label_->setObjectName("historyLabel");
    markButton_ = new QPushButton;
    markButton_->setObjectName("divergenceButton");
    markButton_->setFlat(true);
    markButton_->setFocusPolicy(Qt::TabFocus);
    markButton_->setStyleSheet("QPushButton{color:#b3261e;font-weight:bold;text-align:left;padding:0 4px}");
    // A row of its own, shown only with a mark: beside the label it would widen the
    // scrubber and squeeze the docks at 1366 px (see above).
    markButton_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    markButton_->hide();
    connect(markButton_, &QPushButton::clicked, this, [this] {
        if (mark_ >= 0) emit stepRequested(mark_);
    });
    layout->addWidget(label_, 1, 1);
    layout->addWidget(markButton_, 2, 1, 1, 4);
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
    markOverlay_->update();   // the range changed: the mark moves
}

void HistoryScrubber::setDivergenceMark(long n, const QString& detail)
{
    mark_ = n;
    // The state after n steps, worded as everywhere else (app/core/step_numbering.h).
    const QString where = tr("First divergence: %1").arg(steps::stateName(n));
    markButton_->setText(where);
    markButton_->setToolTip(tr("%1 (n = %2)\n%3\nClick to go there.").arg(where).arg(n).arg(detail));
    markButton_->show();
    slider_->setToolTip(tr("%1\n\nThe red mark: %2. %3").arg(sliderTip_, where, detail));
    markOverlay_->update();
}

void HistoryScrubber::clearDivergenceMark()
{
    mark_ = -1;
    markButton_->hide();
    slider_->setToolTip(sliderTip_);
    markOverlay_->update();
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
