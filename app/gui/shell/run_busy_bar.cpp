#include "app/gui/shell/run_busy_bar.h"

#include "app/core/session.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTimer>

namespace rbw {

RunBusyBar::RunBusyBar(Session* session, QWidget* parent)
    : QWidget(parent)
    , session_(session)
    , ticker_(new QTimer(this))
{
    setObjectName("runBusyBar");
    setAttribute(Qt::WA_StyledBackground);
    setStyleSheet("#runBusyBar{background:#fff4d6;border-top:1px solid #e0c060}");
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(8, 3, 8, 3);
    label_ = new QLabel;
    label_->setObjectName("runBusyLabel");
    // Never wider than the view it sits under: showing the bar must not push the docks.
    label_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    layout->addWidget(label_, 1);
    bar_ = new QProgressBar;
    bar_->setRange(0, 0);   // a step has no fraction done to show: a running bar
    bar_->setMaximumWidth(160);
    bar_->setTextVisible(false);
    layout->addWidget(bar_);
    cancelButton_ = new QPushButton(tr("Cancel"));
    cancelButton_->setObjectName("cancelStepButton");
    cancelButton_->setToolTip(tr("Stop computing: the scene stays at the last finished step."));
    connect(cancelButton_, &QPushButton::clicked, this, &RunBusyBar::cancel);
    layout->addWidget(cancelButton_);
    ticker_->setInterval(250);
    connect(ticker_, &QTimer::timeout, this, &RunBusyBar::updateText);
    connect(session_, &Session::busyChanged, this, &RunBusyBar::onBusyChanged);
    hide();
}

void RunBusyBar::setWaitMs(int stepWaitMs, int playWaitMs, int goWaitMs)
{
    stepWaitMs_ = stepWaitMs;
    playWaitMs_ = playWaitMs;
    goWaitMs_ = goWaitMs >= 0 ? goWaitMs : stepWaitMs;
}

void RunBusyBar::cancel()
{
    if (!session_->busy()) return;
    session_->cancelRun();
    emit cancelled(session_->world() != nullptr ? session_->world()->stepIndex() : 0);
}

void RunBusyBar::onBusyChanged(bool busy)
{
    if (busy) {
        since_.start();
        updateText();
        ticker_->start();
        show();
    } else {
        ticker_->stop();
        hide();
    }
}

void RunBusyBar::updateText()
{
    const World* world = session_->world();
    const long k = world != nullptr ? world->stepIndex() : 0;
    const double seconds = static_cast<double>(since_.elapsed()) * 1e-3;
    const long target = session_->goToTarget();
    if (target >= 0) {
        label_->setText(tr("Going to step %1 … %2 s (the scene shows step %3, the last one finished)")
                            .arg(target)
                            .arg(seconds, 0, 'f', 1)
                            .arg(k));
    } else {
        label_->setText(tr("Computing the next step … %1 s (the scene shows step %2, the last one finished)")
                            .arg(seconds, 0, 'f', 1)
                            .arg(k));
    }
    label_->setToolTip(label_->text());
}

} // namespace rbw
