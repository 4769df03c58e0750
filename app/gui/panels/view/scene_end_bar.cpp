#include "app/gui/panels/view/scene_end_bar.h"

#include "app/core/session.h"
#include "app/core/step_numbering.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

#include <algorithm>
#include <climits>

namespace rbw {

SceneEndBar::SceneEndBar(const Session* session, QWidget* parent)
    : QWidget(parent)
    , session_(session)
{
    setObjectName("sceneEndBar");
    setAutoFillBackground(true);
    setStyleSheet("#sceneEndBar{background:#fff4c4} #sceneEndBar QLabel{font-weight:bold}");
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(8, 3, 8, 3);
    label_ = new QLabel;
    label_->setObjectName("sceneEndLabel");
    layout->addWidget(label_, 1);
    resetButton_ = new QPushButton(tr("Reset"));
    resetButton_->setObjectName("sceneEndReset");
    resetButton_->setToolTip(tr("Back to the start of the scene (R)"));
    continueButton_ = new QPushButton(tr("Continue"));
    continueButton_->setObjectName("sceneEndContinue");
    continueButton_->setToolTip(tr("Play on past the end of the scene (Space)"));
    // The keys stay with the 3D view: a click on a button must not take them.
    for (QPushButton* b : {resetButton_, continueButton_}) {
        b->setFocusPolicy(Qt::NoFocus);
        layout->addWidget(b);
    }
    connect(resetButton_, &QPushButton::clicked, this, &SceneEndBar::resetRequested);
    connect(continueButton_, &QPushButton::clicked, this, [this] {
        hide();
        emit continueRequested();
    });
    connect(session_, &Session::sessionReset, this, [this] {
        armed_ = false;
        hide();
    });
    connect(session_, &Session::stateChanged, this, &SceneEndBar::follow);
    hide();
}

long SceneEndBar::endStep() const
{
    return session_->isLoaded() ? std::max(0L, session_->world()->scene().steps) : 0;
}

void SceneEndBar::playStarted()
{
    armed_ = endStep() > 0 && session_->world()->stepIndex() < endStep();
    hide();
}

int SceneEndBar::stepsAllowed(int due) const
{
    if (!armed_ || !session_->isLoaded()) return due;
    const long left = std::max(0L, endStep() - session_->world()->stepIndex());
    return static_cast<int>(std::min<long>(due, std::min<long>(left, INT_MAX)));
}

bool SceneEndBar::checkEnd()
{
    if (!armed_ || !session_->isLoaded() || session_->world()->stepIndex() < endStep()) return false;
    armed_ = false;
    label_->setText(tr("End of the scene (%1, %2 = %3 s) — Reset or Continue")
                        .arg(steps::stepsTaken(endStep()), steps::timeName(endStep()))
                        .arg(session_->world()->time(), 0, 'g', 6));
    show();
    emit endReached();
    return true;
}

void SceneEndBar::follow()
{
    // Back before the end (Step back, the slider, Reset): the note no longer applies.
    if (isVisible() && session_->isLoaded() && session_->world()->stepIndex() < endStep()) hide();
}

} // namespace rbw
