// Simulation → New numbers… and Export worksheet and answer key… (docs/exercises.md):
// the current lesson's exercise for a seed. Both ask for the seed in the one seed
// dialog (askSeed); the new numbers start through the LessonController like any scene.
// The worksheet's dialog offers the seed of the new numbers on screen, so the sheet is
// the exercise the student sees (issue 20).
#pragma once

#include <QObject>
#include <QString>

#include <optional>

class QAction;
class QStatusBar;
class QWidget;

namespace rbw {

class LessonController;

class ExerciseActions : public QObject {
    Q_OBJECT
public:
    ExerciseActions(QWidget* window, LessonController* lessons, QStatusBar* status);

    QAction* newNumbersAction() const { return newNumbers_; }
    QAction* exportWorksheetAction() const { return exportWorksheet_; }

    // The seed a student typed: a whole number ≥ 0, surrounding spaces allowed; else
    // nothing, with the message in *error.
    static std::optional<quint64> parseSeed(const QString& text, QString* error);
    // The seed dialog (objectName "seedDialog"), prefilled with `prefill` (else a random
    // seed); nothing if cancelled, or (after a warning titled `title`) if the text is no seed.
    static std::optional<quint64> askSeed(QWidget* parent, const QString& title,
                                          std::optional<quint64> prefill = std::nullopt);

private:
    void newNumbers();
    void writeWorksheet();

    QWidget* window_;
    LessonController* lessons_;
    QStatusBar* status_;
    QAction* newNumbers_;
    QAction* exportWorksheet_;
    std::optional<quint64> shownSeed_;   // the seed of the new numbers on screen, if they are
};

} // namespace rbw
