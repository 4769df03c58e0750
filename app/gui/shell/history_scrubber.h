// The history scrubber: a slider over the recorded steps of the session (from the
// oldest kept state to the newest recorded one) and "Go to step N". Moving the
// slider shows the state and trace of that step exactly as they were recorded
// (Session::goToStep restores them; nothing is recomputed). A step beyond the
// newest recorded one is reached by stepping on. Taking a step (or playing) from
// an earlier step discards the later history, as typing after an undo drops the
// redo; the slider then ends at the current step. After a blow-up the world has
// gone one step past the last kept state: the label says "step 5 of 5 · the next step
// blew up" (never "step 6 of 5") and the slider stays on the last kept step.
#pragma once

#include <QWidget>

class QLabel;
class QPushButton;
class QSlider;
class QSpinBox;
class QTimer;

namespace rbw {

class Session;

class HistoryScrubber : public QWidget {
    Q_OBJECT
public:
    explicit HistoryScrubber(Session* session, QWidget* parent = nullptr);

    // Follows the session: the slider's range is the recorded history, its value the
    // current step. Cheap; the main window calls it when the state changed.
    void sync();
    // A note beside the slider for a few seconds: why "Go to step" did not go (a step
    // no longer kept, a step not reached). Cleared by the next request.
    void showNote(const QString& text);

    // The first divergence of a student's own simulator from the workbook (Compare with
    // my simulator → Open in the main window, issue 23): a red mark on the slider at
    // state n (while n is recorded) and a button "First divergence: after step k = n − 1"
    // that goes there; `detail` (body, quantity, numbers) is its tooltip and the slider's.
    void setDivergenceMark(long n, const QString& detail);
    void clearDivergenceMark();
    long divergenceMark() const { return mark_; }   // -1: none
    QPushButton* divergenceButton() const { return markButton_; }

    QSlider* slider() const { return slider_; }
    QSpinBox* stepBox() const { return stepBox_; }
    QPushButton* goButton() const { return goButton_; }
    QLabel* label() const { return label_; }
    QLabel* note() const { return note_; }

signals:
    // The student asked for step k (slider or Go). The main window stops playing and
    // calls Session::goToStep(k).
    void stepRequested(long k);
    // Escape in the step box: the keys go back to the view, nothing else happens.
    void focusReturnRequested();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void onSliderValueChanged(int value);

    Session* session_;
    QSlider* slider_ = nullptr;
    QLabel* label_ = nullptr;
    QLabel* note_ = nullptr;
    QTimer* noteTimer_ = nullptr;
    QSpinBox* stepBox_ = nullptr;
    QPushButton* goButton_ = nullptr;
    QPushButton* markButton_ = nullptr;
    QWidget* markOverlay_ = nullptr;   // paints the mark over the slider
    QString sliderTip_;
    long mark_ = -1;
    bool syncing_ = false;
};

} // namespace rbw
