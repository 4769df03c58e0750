#include "app/gui/shell/exercise_actions.h"

#include "app/exercise/exercise.h"
#include "app/gui/shell/lesson_controller.h"
#include "app/gui/shell/worksheet_export.h"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMessageBox>
#include <QRandomGenerator>
#include <QStatusBar>

namespace rbw {

ExerciseActions::ExerciseActions(QWidget* window, LessonController* lessons, QStatusBar* status)
    : QObject(window)
    , window_(window)
    , lessons_(lessons)
    , status_(status)
    , newNumbers_(new QAction(tr("&New numbers…"), window))
    , exportWorksheet_(new QAction(tr("Export &worksheet and answer key…"), window))
{
    newNumbers_->setObjectName("actionNewNumbers");
    connect(newNumbers_, &QAction::triggered, this, &ExerciseActions::newNumbers);
    exportWorksheet_->setObjectName("actionExportWorksheet");
    connect(exportWorksheet_, &QAction::triggered, this, &ExerciseActions::writeWorksheet);
    connect(lessons_, &LessonController::started, this,
            [this](const SceneDef&, const StartedScene& info) { shownSeed_ = info.seed; });
}

std::optional<quint64> ExerciseActions::parseSeed(const QString& text, QString* error)
{
    bool ok = false;
    const quint64 seed = text.trimmed().toULongLong(&ok);
    if (ok) return seed;
    if (error != nullptr) *error = tr("The seed must be a whole number, got \"%1\".").arg(text);
    return std::nullopt;
}

std::optional<quint64> ExerciseActions::askSeed(QWidget* parent, const QString& title, std::optional<quint64> prefill)
{
    QInputDialog dialog(parent);
    dialog.setObjectName("seedDialog");
    dialog.setWindowTitle(title);
    dialog.setLabelText(tr("Seed (the same seed gives the same numbers):"));
    dialog.setTextValue(QString::number(prefill.value_or(QRandomGenerator::global()->bounded(1000000))));
    if (dialog.exec() != QDialog::Accepted) return std::nullopt;
    QString error;
    const std::optional<quint64> seed = parseSeed(dialog.textValue(), &error);
    if (!seed) QMessageBox::warning(parent, title, error);
    return seed;
}

void ExerciseActions::newNumbers()
{
    const std::optional<quint64> seed = askSeed(window_, tr("New numbers"));
    if (!seed) return;
    QString error;
    if (!lessons_->openNewNumbers(*seed, &error)) QMessageBox::warning(window_, tr("New numbers"), error);
}

void ExerciseActions::writeWorksheet()
{
    const ExerciseLoadResult spec = loadExercise(QFileInfo(lessons_->current().scenePath).absolutePath());
    if (!spec.ok()) {
        QMessageBox::information(window_, tr("Worksheet"), tr("This lesson has no exercise.\n\n%1").arg(spec.errors.join('\n')));
        return;
    }
    // The numbers on screen when they are new numbers: the sheet is the exercise shown.
    const std::optional<quint64> seed = askSeed(window_, tr("Worksheet"), shownSeed_);
    if (!seed) return;
    const QString path = QFileDialog::getSaveFileName(window_, tr("Export worksheet"),
                                                      QStringLiteral("worksheet-%1.pdf").arg(*seed),
                                                      tr("PDF (*.pdf);;HTML (*.html)"));
    if (path.isEmpty()) return;
    const GeneratedExercise generated = generateExercise(*spec.spec, *seed);
    WorksheetFiles written;
    QString error;
    if (!generated.ok()) error = generated.errors.join('\n');
    if (error.isEmpty() && !rbw::exportWorksheet(*spec.spec, generated, path, &written, &error) && error.isEmpty()) {
        error = tr("The worksheet could not be written.");
    }
    if (!error.isEmpty()) {
        QMessageBox::warning(window_, tr("Worksheet"), error);
        return;
    }
    status_->showMessage(tr("Wrote %1 and %2").arg(written.worksheet, written.answerKey), 6000);
}

} // namespace rbw
