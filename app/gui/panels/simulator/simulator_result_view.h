// What Compare with my simulator found (issue 23, docs/simulator-protocol.md), shown for
// one finished diagnosis (app/simulator/diagnose_run.h): the verdict in words, the
// mistakes named with their equation and the right one (the checker's catalogue,
// physics/workbook/checker/mistakes.h), the restitution fitted to collision probes, the
// first divergence in words, the template's public tests; a table of the probes with
// their verdicts; and for the selected probe, per answer, the workbook's and the
// student's x, v, ω and r side by side, the probe's first divergence highlighted, with
// a slider over its answers that jumps to it. Every number comes from the diagnosis.
#pragma once

#include "app/simulator/diagnose_report.h"

#include <QWidget>

#include <vector>

class QLabel;
class QPushButton;
class QSlider;
class QSplitter;
class QTableWidget;
class QTextBrowser;

namespace rbw {

class SimulatorResultView : public QWidget {
    Q_OBJECT
public:
    explicit SimulatorResultView(QWidget* parent = nullptr);

    // A diagnosed run and the right algorithm's answers beside it (rightAnswers()).
    void showRun(const DiagnoseRun& run, const std::vector<probes::Answers>& right);
    // A run that could not be diagnosed: its message (the one rbw diagnose prints) and
    // the program's last lines on standard error.
    void showFailure(const QString& message, const QStringList& stderrTail);
    void clear();

    // The probe whose answers the step table shows (-1: none), and its answer on the slider.
    void selectProbe(int probe);
    int selectedProbe() const { return probe_; }
    void selectAnswer(int answer);

    // The sentences shown, for tests: the verdict line, the details, the error.
    QString verdictText() const;
    QString detailsText() const;
    QString errorText() const;

    // "angular velocity ω" for "omega".
    static QString quantityWords(const std::string& quantity);

private:
    void fillProbeTable();
    void fillStepTable();
    QString divergenceWords(int probe, const probes::Divergence& d) const;

    DiagnoseRun run_;
    std::vector<probes::Answers> right_;
    int probe_ = -1;
    QLabel* verdict_ = nullptr;
    QLabel* error_ = nullptr;
    QTextBrowser* details_ = nullptr;
    QTableWidget* probes_ = nullptr;
    QSplitter* tables_ = nullptr;
    QLabel* probeDivergence_ = nullptr;
    QSlider* slider_ = nullptr;
    QLabel* sliderLabel_ = nullptr;
    QPushButton* jump_ = nullptr;
    QTableWidget* steps_ = nullptr;
};

} // namespace rbw
