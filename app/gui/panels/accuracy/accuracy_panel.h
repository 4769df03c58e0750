// The Accuracy tab: runs an accuracy study (physics/workbook/lab/study.h) on the current scene
// and draws error against cost on log-log axes, one line with markers per
// integrator, plus the Pareto front over all of them (study_front.h), above a table
// of the numbers (study_table_model.h).
//
// The study runs off the GUI thread through the study panels' one runner
// (study_runner.h): every progress report comes back in order, Cancel stops it at the
// next step and the runs it finished are shown. A scene
// without an exact answer (two bodies, planes, forces, ...) is refused with the
// runner's reason, shown in the panel; Run stays disabled.
#pragma once

#include "app/gui/panels/accuracy/study_front.h"
#include "app/gui/panels/accuracy/study_runner.h"
#include "physics/workbook/lab/study.h"
#include "physics/engine/scene.h"

#include <QWidget>

#include <atomic>
#include <memory>

class QChart;
class QChartView;
class QBoxLayout;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QTableView;

namespace rbw {

class StudyTableModel;

class AccuracyPanel : public QWidget {
    Q_OBJECT
public:
    explicit AccuracyPanel(QWidget* parent = nullptr);
    ~AccuracyPanel() override;   // cancels a running study and waits for it

    // The scene to study; label names it in the panel ("10-accuracy-lab/scene.json").
    // Cancels a running study. Sets T to the scene's steps x dt.
    void setScene(const SceneDef& scene, const QString& label);

    // Controls, also for tests.
    QStringList integratorNames() const;            // every checkbox, in catalogue order
    QStringList selectedIntegrators() const;
    void setSelectedIntegrators(const QStringList& names);
    QString dtText() const;
    void setDtText(const QString& text);            // "0.1, 0.05, 0.02"
    double endTime() const;
    void setEndTime(double T);
    ErrorMetric errorMetric() const;
    void setErrorMetric(ErrorMetric metric);
    void setTimingBudget(double seconds);           // per run (StudyConfig::timingBudgetSeconds)

    // Starts the study with the current controls; false (and the reason in the status
    // line) if the input is bad or a study is running.
    bool startStudy();
    void cancelStudy();
    bool isRunning() const;
    bool sceneHasExactAnswer() const { return sceneIssues_.isEmpty(); }

    // What the panel shows.
    const lab::StudyResult& result() const;
    const StudyFront& front() const { return front_; }
    QChart* chart() const { return chart_; }
    QProgressBar* progressBar() const { return progress_; }
    QString statusText() const;
    StudyTableModel* tableModel() const { return model_; }
    int seriesCount() const;   // integrator curves drawn (not counting the Pareto front)

    bool exportPng(const QString& path, QString* error = nullptr);
    bool exportCsv(const QString& path, QString* error = nullptr) const;

signals:
    void studyFinished();                     // completed or cancelled
    void progressChanged(int done, int total);

protected:
    // Layout only: the settings beside the chart when the panel is wide, above it when
    // narrow (docked), so the chart and its axis titles never sit off the right edge.
    bool event(QEvent* e) override;
    bool eventFilter(QObject* watched, QEvent* e) override;

private:
    void fitLayout(int availableWidth);
    void onRunClicked();
    void onFinished();
    void onProgress(int done, int total);
    void onExportPng();
    void onExportCsv();
    void redraw();
    void setStatus(const QString& text, bool error);
    void updateButtons();
    // The controls as a study configuration; issues in the command line's terms.
    lab::StudyConfig config(QStringList& problems) const;

    SceneDef scene_;
    bool haveScene_ = false;
    QStringList sceneIssues_;
    QString label_;
    double timingBudget_ = 0.02;

    QBoxLayout* mainLayout_ = nullptr;
    QWidget* controls_ = nullptr;
    QLabel* sceneLabel_ = nullptr;
    QList<QCheckBox*> integratorBoxes_;
    QLineEdit* dtEdit_ = nullptr;
    QDoubleSpinBox* endTime_ = nullptr;
    QComboBox* metric_ = nullptr;
    QPushButton* run_ = nullptr;
    QPushButton* cancel_ = nullptr;
    QPushButton* exportPng_ = nullptr;
    QPushButton* exportCsv_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QLabel* status_ = nullptr;
    QChart* chart_ = nullptr;
    QChartView* chartView_ = nullptr;
    QTableView* table_ = nullptr;
    StudyTableModel* model_ = nullptr;

    StudyFront front_;
    StudyRunner<lab::StudyResult>* runner_ = nullptr;   // the study off the GUI thread
};

} // namespace rbw
