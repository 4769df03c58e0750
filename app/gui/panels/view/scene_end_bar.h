// The end of the scene: Play stops at the scene's `steps` (the run its lesson
// describes: one step in lesson 1, 600 in lesson 11) and this bar says so under the 3D
// view, "End of the scene (step N) — Reset or Continue". Continue plays on past the
// end: a run started at or after the end never stops there again. Step (S) and Go to
// step are not limited; only Play is.
//
// The bar only decides and shows; the window owns the play timer and calls it
// (app/gui/panels/view/README.md, "The end of the scene"):
//   starting Play:       bar->playStarted();
//   each tick of Play:   due = bar->stepsAllowed(due); take them; bar->checkEnd();
//   endReached          -> stop playing
//   resetRequested      -> reset the lesson;  continueRequested -> play again
#pragma once

#include <QWidget>

class QLabel;
class QPushButton;

namespace rbw {

class Session;

class SceneEndBar : public QWidget {
    Q_OBJECT
public:
    explicit SceneEndBar(const Session* session, QWidget* parent = nullptr);

    // The step Play stops at: the scene's `steps`; 0 when the scene sets none.
    long endStep() const;
    // Play starts: a run that starts before the end stops at it; one that starts at
    // or after it (Continue, or Play again) goes on.
    void playStarted();
    // Whether the running Play stops at the end.
    bool stopsAtEnd() const { return armed_; }
    // The steps one tick of Play may take: `due`, but no step past the end.
    int stepsAllowed(int due) const;
    // After a tick: at the end of a run that stops there, shows the bar, emits
    // endReached and returns true (once).
    bool checkEnd();

    QLabel* label() const { return label_; }
    QPushButton* resetButton() const { return resetButton_; }
    QPushButton* continueButton() const { return continueButton_; }

signals:
    void endReached();
    void resetRequested();
    void continueRequested();

private:
    void follow();

    const Session* session_;
    QLabel* label_ = nullptr;
    QPushButton* resetButton_ = nullptr;
    QPushButton* continueButton_ = nullptr;
    bool armed_ = false;
};

} // namespace rbw
