// The contacts half of the accuracy lab (issue 11): runs a contact study
// (physics/workbook/lab/contact_study.h) on one of the contact problems, the course model and
// the manifold model at each solver iteration count, at each h, and draws the chosen
// error (deepest overlap, ground penetration, drift, energy gained) against the cost
// of reaching T on log-log axes: one line per model and iteration count through its
// step sizes, so a student sees what each iteration buys. A table holds every number
// of the runs (the same columns as `rbw contact-study`'s CSV), which Export writes.
//
// The tab explains itself at its top; the legend names each line's model and
// iterations in full; the table shows each number short (h as 1/30) with every digit
// in its tooltip.
//
// The study runs off the GUI thread through the study panels' one runner
// (study_runner.h); Cancel stops it at the next step. The panel shows numbers from the
// study only.
#pragma once

#include "app/gui/panels/accuracy/study_runner.h"
#include "physics/workbook/lab/contact_study.h"

#include <QWidget>

#include <atomic>

class QChart;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QStandardItemModel;
class QTableView;

namespace rbw {

// The error the chart draws.
enum class ContactMetric { Overlap, Below, Drift, EnergyGained };

class ContactStudyPanel : public QWidget {
    Q_OBJECT
public:
    explicit ContactStudyPanel(QWidget* parent = nullptr);
    ~ContactStudyPanel() override;   // cancels a running study and waits for it

    // Controls, also for tests.
    void setProblem(lab::ContactProblem p);
    void setIterationsText(const QString& text);   // "1, 2, 4, 8, 16"
    void setDtText(const QString& text);           // "0.0333333, 0.0166667"
    void setEndTime(double T);
    void setRainBoxes(int n);
    void setMetric(ContactMetric m);

    // Starts the study with the current controls; false (and the reason in the status
    // line) if the input is bad or a study is running.
    bool startStudy();
    void cancelStudy();
    bool isRunning() const;

    const lab::ContactStudyResult& result() const { return result_; }
    QChart* chart() const { return chart_; }
    QStandardItemModel* tableModel() const { return table_; }
    QString statusText() const;
    int seriesCount() const;   // lines drawn, one per model and iteration count
    QString introText() const;   // the tab's explanation at its top

    bool exportCsv(const QString& path, QString* error = nullptr) const;

signals:
    void studyFinished();

private:
    void onFinished();
    void redraw();
    void fillTable();
    void setStatus(const QString& text, bool error);
    void updateButtons();
    lab::ContactStudyConfig config(QStringList& problems) const;

    QComboBox* problem_ = nullptr;
    QSpinBox* boxes_ = nullptr;
    QLineEdit* iterations_ = nullptr;
    QLineEdit* dts_ = nullptr;
    QDoubleSpinBox* endTime_ = nullptr;
    QComboBox* metric_ = nullptr;
    QPushButton* run_ = nullptr;
    QPushButton* cancel_ = nullptr;
    QPushButton* exportCsv_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QLabel* status_ = nullptr;
    QLabel* intro_ = nullptr;   // what the tab is for, at its top
    QChart* chart_ = nullptr;
    QStandardItemModel* table_ = nullptr;
    QTableView* tableView_ = nullptr;

    QString baseStatus_;   // the status line without the note on zeros
    QString zeroNote_;
    lab::ContactStudyResult result_;
    StudyRunner<lab::ContactStudyResult>* runner_ = nullptr;   // the study off the GUI thread
};

} // namespace rbw
