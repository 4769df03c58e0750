#include "app/gui/panels/simulator/simulator_dialog.h"

#include "app/gui/panels/simulator/simulator_result_view.h"
#include "app/simulator/diagnose_run.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QRadioButton>
#include <QScreen>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>

namespace rbw {

namespace {

// A path as one word of a command line: quoted when it holds a space or a quote.
QString commandWord(const QString& path)
{
    if (!path.contains(' ') && !path.contains('"') && !path.contains('\'')) return path;
    return '"' + QString(path).replace("\"", "\\\"") + '"';
}

} // namespace

SimulatorDialog::SimulatorDialog(QWidget* parent) : QDialog(parent)
{
    setObjectName("compareSimulatorDialog");
    setWindowTitle(tr("Compare with my simulator"));

    auto* intro = new QLabel(tr("The workbook sends your simulator small scenes (probes) through the simulator "
                                "protocol, compares its answers with the course algorithm and with each common "
                                "mistake, and names the mistake that explains them (docs/simulator-protocol.md)."),
                             this);
    intro->setWordWrap(true);

    useProgram_ = new QRadioButton(tr("Run my &program:"), this);
    useProgram_->setObjectName("useProgramRadio");
    useAnswers_ = new QRadioButton(tr("Read &answers written offline:"), this);
    useAnswers_->setObjectName("useAnswersRadio");
    auto* sourceGroup = new QButtonGroup(this);
    sourceGroup->addButton(useProgram_);
    sourceGroup->addButton(useAnswers_);
    useProgram_->setChecked(true);
    command_ = new QLineEdit(this);
    command_->setObjectName("commandEdit");
    command_->setPlaceholderText(tr("the command line that starts it, e.g. python3 my_simulator.py"));
    answers_ = new QLineEdit(this);
    answers_->setObjectName("answersEdit");
    answers_->setPlaceholderText(tr("a folder of rbw probes --output DIR with your .states files, or a .csv file"));
    auto* browseProgram = new QPushButton(tr("Program…"), this);
    browseProgram->setObjectName("browseProgramButton");
    auto* browseAnswers = new QPushButton(tr("Folder…"), this);
    browseAnswers->setObjectName("browseAnswersButton");
    connect(browseProgram, &QPushButton::clicked, this, &SimulatorDialog::browseProgram);
    connect(browseAnswers, &QPushButton::clicked, this, &SimulatorDialog::browseAnswers);
    connect(command_, &QLineEdit::textEdited, this, [this] { useProgram_->setChecked(true); });
    connect(answers_, &QLineEdit::textEdited, this, [this] { useAnswers_->setChecked(true); });
    connect(useProgram_, &QRadioButton::toggled, this, &SimulatorDialog::updateControls);
    auto* offlineHint = new QLabel(tr("Offline: rbw probes --output DIR writes each probe as DIR/<probe>.commands; "
                                      "run your program on each into DIR/<probe>.states."),
                                   this);
    offlineHint->setWordWrap(true);

    group_ = new QComboBox(this);
    group_->setObjectName("probesCombo");
    group_->addItem(tr("all (motion and collision)"), "all");
    group_->addItem(tr("motion"), "motion");
    group_->addItem(tr("collision"), "collision");
    timeout_ = new QDoubleSpinBox(this);
    timeout_->setObjectName("timeoutSpin");
    timeout_->setRange(0.1, kMaxProbeTimeout);
    timeout_->setDecimals(1);
    timeout_->setValue(kDefaultProbeTimeout);
    timeout_->setSuffix(tr(" s per probe"));
    run_ = new QPushButton(tr("&Run"), this);
    run_->setObjectName("runButton");
    run_->setDefault(true);
    cancel_ = new QPushButton(tr("&Cancel"), this);
    cancel_->setObjectName("cancelButton");
    connect(run_, &QPushButton::clicked, this, &SimulatorDialog::run);
    connect(cancel_, &QPushButton::clicked, this, &SimulatorDialog::cancel);
    progress_ = new QProgressBar(this);
    progress_->setObjectName("progressBar");
    progress_->setTextVisible(true);
    status_ = new QLabel(this);
    status_->setObjectName("statusLabel");

    auto* source = new QGridLayout;
    source->addWidget(useProgram_, 0, 0);
    source->addWidget(command_, 0, 1);
    source->addWidget(browseProgram, 0, 2);
    source->addWidget(useAnswers_, 1, 0);
    source->addWidget(answers_, 1, 1);
    source->addWidget(browseAnswers, 1, 2);
    source->addWidget(offlineHint, 2, 1, 1, 2);
    source->setColumnStretch(1, 1);
    auto* runRow = new QHBoxLayout;
    runRow->addWidget(new QLabel(tr("Probes:"), this));
    runRow->addWidget(group_);
    runRow->addWidget(new QLabel(tr("Timeout:"), this));
    runRow->addWidget(timeout_);
    runRow->addWidget(run_);
    runRow->addWidget(cancel_);
    runRow->addWidget(progress_, 1);
    runRow->addWidget(status_, 1);

    result_ = new SimulatorResultView(this);
    auto* close = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(close, &QDialogButtonBox::rejected, this, &SimulatorDialog::reject);
    // The selected probe as the main window's scene, the student's numbers in its table.
    openInWindow_ = close->addButton(tr("&Open in the main window"), QDialogButtonBox::ActionRole);
    openInWindow_->setObjectName("openInMainWindowButton");
    openInWindow_->setToolTip(tr("Open the selected probe (else the one with the first divergence) as the main "
                                 "window's scene: the quantities table gets a Yours column with your program's "
                                 "numbers, the history slider a mark at the first divergence"));
    connect(openInWindow_, &QPushButton::clicked, this, &SimulatorDialog::openInMainWindow);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(source);
    layout->addLayout(runRow);
    layout->addWidget(result_, 1);
    layout->addWidget(close);

    watcher_ = new QFutureWatcher<CompareOutcome>(this);
    connect(watcher_, &QFutureWatcher<CompareOutcome>::finished, this, &SimulatorDialog::onFinished);

    // Readable on a 1366×768 screen: at most the screen's available area.
    QSize size(1200, 720);
    if (const QScreen* screen = QGuiApplication::primaryScreen()) {
        size = size.boundedTo(screen->availableGeometry().size() - QSize(40, 60));
    }
    resize(size);
    updateControls();
    command_->setFocus();
}

SimulatorDialog::~SimulatorDialog()
{
    cancel();
    watcher_->waitForFinished();   // the run kills its program before it returns
}

void SimulatorDialog::setCommand(const QString& commandLine)
{
    command_->setText(commandLine);
    useProgram_->setChecked(true);
}

void SimulatorDialog::setAnswersPath(const QString& path)
{
    answers_->setText(path);
    useAnswers_->setChecked(true);
}

void SimulatorDialog::setProbeGroup(std::optional<probes::ProbeGroup> group)
{
    const char* name = !group                                          ? "all"
                       : *group == probes::ProbeGroup::Motion    ? "motion"
                       : *group == probes::ProbeGroup::Collision ? "collision"
                                                                 : "all";
    group_->setCurrentIndex(group_->findData(QString::fromLatin1(name)));
}

void SimulatorDialog::setTimeoutSeconds(double seconds)
{
    timeout_->setValue(seconds);
}

bool SimulatorDialog::isRunning() const
{
    return watcher_->isRunning();
}

bool SimulatorDialog::run()
{
    if (isRunning()) return false;
    DiagnoseSettings settings;
    settings.group = probes::probeGroupNamed(group_->currentData().toString().toStdString());
    settings.timeoutSeconds = timeout_->value();
    const bool live = useProgram_->isChecked();
    const QString text = live ? command_->text() : answers_->text().trimmed();
    const bool trajectory = !live && QFileInfo(text).isFile();
    // offline without a group choice reads the probes found (as rbw diagnose DIR)
    const std::optional<probes::ProbeGroup> offlineGroup =
        group_->currentData().toString() == QLatin1String("all") ? std::nullopt : settings.group;

    cancelFlag_ = std::make_shared<std::atomic<bool>>(false);
    result_->clear();
    progress_->setRange(0, 0);
    status_->setText(live ? tr("Starting your program…") : tr("Reading the answers…"));
    const std::shared_ptr<std::atomic<bool>> flag = cancelFlag_;
    watcher_->setFuture(QtConcurrent::run([this, live, text, trajectory, settings, offlineGroup, flag]() {
        CompareOutcome o;
        if (live) {
            auto progress = [this](int done, int total, const QString& name) {
                QMetaObject::invokeMethod(
                    this, [this, done, total, name] { onProgress(done, total, name); }, Qt::QueuedConnection);
            };
            o.run = runSimulatorDiagnosis(text, settings, progress, flag.get());
        } else {
            o.run = readAnswersDiagnosis(text, trajectory, offlineGroup);
        }
        if (o.run.failure.isEmpty()) o.right = rightAnswers(o.run);
        return o;
    }));
    updateControls();
    return true;
}

void SimulatorDialog::cancel()
{
    if (cancelFlag_) cancelFlag_->store(true);
}

void SimulatorDialog::reject()
{
    if (isRunning()) {
        cancel();
        watcher_->waitForFinished();
    }
    QDialog::reject();
}

void SimulatorDialog::onProgress(int done, int total, const QString& name)
{
    if (!isRunning()) return;
    progress_->setRange(0, total);
    progress_->setValue(done);
    status_->setText(name.isEmpty() ? tr("Comparing with every mistake model…")
                                    : tr("Probe %1 of %2: %3").arg(done + 1).arg(total).arg(name));
}

void SimulatorDialog::onFinished()
{
    outcome_ = watcher_->result();
    progress_->setRange(0, 1);
    progress_->setValue(outcome_.run.failure.isEmpty() ? 1 : 0);
    if (outcome_.run.cancelled) {
        status_->setText(tr("Cancelled."));
        result_->showFailure(outcome_.run.failure, {});
    } else if (!outcome_.run.failure.isEmpty()) {
        status_->setText(tr("Could not check it."));
        result_->showFailure(outcome_.run.failure, outcome_.run.stderrTail);
    } else {
        status_->setText(tr("Done: %1 probes.").arg(outcome_.run.probes.size()));
        result_->showRun(outcome_.run, outcome_.right);
    }
    updateControls();
    emit checkFinished();
}

void SimulatorDialog::openInMainWindow()
{
    if (!canOpenInMainWindow()) return;
    int probe = result_->selectedProbe();
    if (probe < 0 || probe >= static_cast<int>(outcome_.run.probes.size())) probe = std::max(0, outcome_.run.diagnosis.divergenceProbe);
    emit openInMainWindowRequested(probe);
}

bool SimulatorDialog::canOpenInMainWindow() const
{
    const DiagnoseRun& run = outcome_.run;
    return !isRunning() && run.failure.isEmpty() && !run.probes.empty() && run.given.size() == run.probes.size() &&
           outcome_.right.size() == run.probes.size();
}

void SimulatorDialog::updateControls()
{
    const bool running = isRunning();
    openInWindow_->setEnabled(canOpenInMainWindow());
    run_->setEnabled(!running);
    cancel_->setEnabled(running);
    timeout_->setEnabled(useProgram_->isChecked());
}

void SimulatorDialog::browseProgram()
{
    const QString start = command_->text().isEmpty() ? QDir::homePath() : QFileInfo(command_->text()).absolutePath();
    const QString path = QFileDialog::getOpenFileName(this, tr("Your simulator program"), start);
    if (path.isEmpty()) return;
    setCommand(commandWord(QDir::toNativeSeparators(path)));
}

void SimulatorDialog::browseAnswers()
{
    const QString start = answers_->text().isEmpty() ? QDir::homePath() : answers_->text();
    const QString path = QFileDialog::getExistingDirectory(this, tr("The folder of your answers"), start);
    if (!path.isEmpty()) setAnswersPath(path);
}

} // namespace rbw
