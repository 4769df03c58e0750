// The "Check my numbers" dock: the CheckModel's table (type your numbers into the
// Yours column), "What's wrong?" (the selected entry's verdict, its matching mistakes
// and the workbook's number, below the table), "Next step" (selects the first quantity
// not yet filled in) and saving / loading the entries as an answers file
// (answers_file.h). Wiring only: the verdicts come from the model, i.e. the checker.
#pragma once

#include <QWidget>

#include <memory>

class QLabel;
class QPushButton;
class QTableView;
class QTextBrowser;

namespace rbw {

class CheckModel;
class World;
struct SceneDef;
struct StepTrace;

class CheckPanel : public QWidget {
    Q_OBJECT
public:
    explicit CheckPanel(QWidget* parent = nullptr);

    // Shows a step (see CheckModel::setStep).
    void setStep(const QString& lesson, std::unique_ptr<World> before, const StepTrace* trace, const SceneDef& scene);

    CheckModel* model() const { return model_; }
    QTableView* view() const { return view_; }
    // What the explanation pane shows (HTML).
    QString explanationHtml() const;
    // The step's input-slip hint above the table ("steps count from 0: …"), or empty.
    QString stepHintText() const;

    // Writes the entries as an answers file through QSaveFile; reads one.
    bool saveAnswers(const QString& path, QString* error = nullptr);
    bool loadAnswers(const QString& path, QString* error = nullptr);

public slots:
    // Explains the selected entry below the table.
    void showWhatsWrong();
    // Selects the first quantity with nothing written; false if all are filled.
    bool selectNextEmpty();

protected:
    // The table owns the keyboard while a cell is (about to be) edited: a printable key
    // on an editable cell is text, not the app's shortcut ("[" slower, Space play).
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void onCurrentChanged();
    void saveWithDialog();
    void loadWithDialog();
    void updateHeader();
    void updateStepHint();

    CheckModel* model_ = nullptr;
    QTableView* view_ = nullptr;
    QLabel* header_ = nullptr;
    QLabel* stepHint_ = nullptr;
    QTextBrowser* explanation_ = nullptr;
    QPushButton* whatsWrong_ = nullptr;
    QPushButton* nextStep_ = nullptr;
    QPushButton* save_ = nullptr;
    QPushButton* load_ = nullptr;
    QPushButton* clear_ = nullptr;
};

} // namespace rbw
