// Tools → Compare with my simulator (issue 23, docs/simulator-protocol.md, docs/user-guide.md):
// the app's face of `rbw diagnose`. The student chooses the command line that starts
// their program (a file picker for the program) or a folder of answers written offline
// (`rbw probes --output DIR` and their program; a CSV file for --trajectory), the probe
// group and the timeout; Run calls the same code as rbw diagnose
// (app/simulator/diagnose_run.h) on a thread of its own (QtConcurrent::run), with the
// progress per probe and Cancel, which stops the program being run (its process group
// killed) within about 50 ms. The result (SimulatorResultView) or the message rbw
// diagnose would print for bad input appears in the dialog.
#pragma once

#include "app/simulator/diagnose_report.h"
#include "physics/workbook/probes/probes.h"

#include <QDialog>
#include <QFutureWatcher>

#include <atomic>
#include <memory>
#include <optional>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QRadioButton;

namespace rbw {

class SimulatorResultView;

// What a run hands back to the GUI thread.
struct CompareOutcome {
    DiagnoseRun run;
    std::vector<probes::Answers> right;   // the right algorithm's answers, when diagnosed
};

class SimulatorDialog : public QDialog {
    Q_OBJECT
public:
    explicit SimulatorDialog(QWidget* parent = nullptr);
    ~SimulatorDialog() override;   // cancels a running check and waits for it (no child left)

    // The controls, also for tests.
    void setCommand(const QString& commandLine);   // and chooses "run my program"
    void setAnswersPath(const QString& path);      // a folder or a .csv file; chooses "answers written offline"
    void setProbeGroup(std::optional<probes::ProbeGroup> group);   // nullopt: all
    void setTimeoutSeconds(double seconds);

    // Starts the check with the current controls; false when one is running.
    bool run();
    void cancel();
    bool isRunning() const;
    // The last finished run (empty before the first).
    const CompareOutcome& outcome() const { return outcome_; }
    SimulatorResultView* resultView() const { return result_; }

    // "Open in the main window": asks for the selected probe (else the one with the first
    // divergence) of a diagnosed run; the shell opens it (openInMainWindowRequested).
    void openInMainWindow();
    bool canOpenInMainWindow() const;

signals:
    void checkFinished();   // a run ended: diagnosed, failed or cancelled
    // The shell opens probe `probe` of outcome() as the main window's scene.
    void openInMainWindowRequested(int probe);

protected:
    void reject() override;   // Close while running cancels first

private:
    void browseProgram();
    void browseAnswers();
    void onProgress(int done, int total, const QString& name);
    void onFinished();
    void updateControls();

    QRadioButton* useProgram_ = nullptr;
    QRadioButton* useAnswers_ = nullptr;
    QLineEdit* command_ = nullptr;
    QLineEdit* answers_ = nullptr;
    QComboBox* group_ = nullptr;
    QDoubleSpinBox* timeout_ = nullptr;
    QPushButton* run_ = nullptr;
    QPushButton* cancel_ = nullptr;
    QPushButton* openInWindow_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QLabel* status_ = nullptr;
    SimulatorResultView* result_ = nullptr;
    QFutureWatcher<CompareOutcome>* watcher_ = nullptr;
    std::shared_ptr<std::atomic<bool>> cancelFlag_;
    CompareOutcome outcome_;
};

} // namespace rbw
