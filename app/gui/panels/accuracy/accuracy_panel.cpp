#include "app/gui/panels/accuracy/accuracy_panel.h"

#include "app/gui/panels/accuracy/log_axes.h"

#include "app/output/atomic_file.h"
#include "app/output/study_csv.h"
#include "app/gui/panels/accuracy/study_table_model.h"
#include "physics/engine/integrator_registry.h"

#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QColor>
#include <QPen>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QBuffer>
#include <QSplitter>
#include <QTableView>
#include <QVBoxLayout>

#include <cmath>

namespace rbw {

namespace {

QString defaultDtText()
{
    QStringList parts;
    for (double dt : lab::defaultStudyDts()) parts << QString::number(dt, 'g', QLocale::FloatingPointShortest);
    return parts.join(", ");
}

// A log axis range around [lo, hi] with whole decades at both ends.
// Eight distinguishable colours (Tableau 10), one per integrator in catalogue order,
// so a method keeps its colour from one study to the next.
QColor integratorColour(const QString& name)
{
    static const char* const colours[] = {"#4e79a7", "#f28e2b", "#e15759", "#76b7b2",
                                          "#59a14f", "#edc948", "#b07aa1", "#9c755f", "#bab0ac", "#ff9da7"};
    int i = 0;
    for (const IntegratorInfo& info : integratorCatalogue()) {
        if (name == QString::fromUtf8(info.name)) break;
        ++i;
    }
    return QColor(colours[i % 10]);
}

} // namespace

AccuracyPanel::AccuracyPanel(QWidget* parent) : QWidget(parent)
{
    // --- controls -----------------------------------------------------------------
    sceneLabel_ = new QLabel(tr("No scene"), this);
    sceneLabel_->setWordWrap(true);

    auto* integratorsBox = new QGroupBox(tr("Integrators"), this);
    auto* grid = new QGridLayout(integratorsBox);
    int i = 0;
    for (const IntegratorInfo& info : integratorCatalogue()) {
        auto* box = new QCheckBox(QString::fromUtf8(info.name), integratorsBox);
        box->setToolTip(QString::fromUtf8(info.summary));
        box->setChecked(true);
        grid->addWidget(box, i / 2, i % 2);
        integratorBoxes_.append(box);
        ++i;
    }

    dtEdit_ = new QLineEdit(defaultDtText(), this);
    dtEdit_->setToolTip(tr("Step sizes h in seconds, separated by commas; each must divide T into whole steps."));
    endTime_ = new QDoubleSpinBox(this);
    endTime_->setDecimals(4);
    endTime_->setRange(0.0001, 1e5);
    endTime_->setValue(1.0);
    endTime_->setSuffix(tr(" s"));
    metric_ = new QComboBox(this);
    metric_->addItem(tr("orientation error (angle)"), int(ErrorMetric::Orientation));
    metric_->addItem(tr("ω error |ω − ω_exact|"), int(ErrorMetric::Omega));
    metric_->addItem(tr("position error |x − x_exact|"), int(ErrorMetric::Position));

    auto* form = new QFormLayout;
    form->addRow(tr("dt list"), dtEdit_);
    form->addRow(tr("end time T"), endTime_);
    form->addRow(tr("plot error"), metric_);

    run_ = new QPushButton(tr("Run study"), this);
    cancel_ = new QPushButton(tr("Cancel"), this);
    exportPng_ = new QPushButton(tr("Export PNG…"), this);
    exportCsv_ = new QPushButton(tr("Export CSV…"), this);
    progress_ = new QProgressBar(this);
    progress_->setRange(0, 100);
    progress_->setValue(0);
    status_ = new QLabel(this);
    status_->setWordWrap(true);
    status_->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(run_);
    buttons->addWidget(cancel_);
    auto* exports = new QHBoxLayout;
    exports->addWidget(exportPng_);
    exports->addWidget(exportCsv_);

    auto* left = new QWidget(this);
    auto* leftLayout = new QVBoxLayout(left);
    leftLayout->addWidget(sceneLabel_);
    leftLayout->addWidget(integratorsBox);
    leftLayout->addLayout(form);
    leftLayout->addLayout(buttons);
    leftLayout->addWidget(progress_);
    leftLayout->addWidget(status_);
    leftLayout->addLayout(exports);
    leftLayout->addStretch(1);
    left->setMaximumWidth(420);

    // --- chart and table ------------------------------------------------------------
    chart_ = new QChart;
    chart_->setTitle(tr("Error against cost: the speed/accuracy trade"));
    chart_->legend()->setAlignment(Qt::AlignRight);
    chartView_ = new QChartView(chart_, this);
    chartView_->setRenderHint(QPainter::Antialiasing);
    chartView_->setMinimumSize(320, 320);

    model_ = new StudyTableModel(this);
    table_ = new QTableView(this);
    table_->setModel(model_);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->verticalHeader()->setVisible(false);

    auto* splitter = new QSplitter(Qt::Vertical, this);
    splitter->addWidget(chartView_);
    splitter->addWidget(table_);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 2);
    splitter->setSizes({600, 300});

    controls_ = left;
    mainLayout_ = new QBoxLayout(QBoxLayout::LeftToRight, this);
    mainLayout_->addWidget(left);
    mainLayout_->addWidget(splitter, 1);

    runner_ = new StudyRunner<lab::StudyResult>(this);
    connect(runner_, &StudyRunnerSignals::progressed, this, &AccuracyPanel::onProgress);
    connect(runner_, &StudyRunnerSignals::finished, this, &AccuracyPanel::onFinished);
    connect(run_, &QPushButton::clicked, this, &AccuracyPanel::onRunClicked);
    connect(cancel_, &QPushButton::clicked, this, &AccuracyPanel::cancelStudy);
    connect(exportPng_, &QPushButton::clicked, this, &AccuracyPanel::onExportPng);
    connect(exportCsv_, &QPushButton::clicked, this, &AccuracyPanel::onExportCsv);
    connect(metric_, &QComboBox::currentIndexChanged, this, &AccuracyPanel::redraw);

    redraw();
    updateButtons();
}

bool AccuracyPanel::event(QEvent* e)
{
    // In the app the panel sits in a scroll area: follow the width of its viewport.
    if (e->type() == QEvent::ParentChange && parentWidget() != nullptr) parentWidget()->installEventFilter(this);
    if (e->type() == QEvent::Resize || e->type() == QEvent::Show) {
        fitLayout(parentWidget() != nullptr ? parentWidget()->width() : width());
    }
    return QWidget::event(e);
}

bool AccuracyPanel::eventFilter(QObject* watched, QEvent* e)
{
    if (watched == parentWidget() && e->type() == QEvent::Resize) fitLayout(parentWidget()->width());
    return QWidget::eventFilter(watched, e);
}

void AccuracyPanel::fitLayout(int availableWidth)
{
    if (mainLayout_ == nullptr || controls_ == nullptr) return;
    // Side by side only when the chart keeps at least its minimum width beside the settings.
    const int sideBySide = controls_->sizeHint().width() + chartView_->minimumWidth() + 60;
    const QBoxLayout::Direction wanted = availableWidth >= sideBySide ? QBoxLayout::LeftToRight
                                                                      : QBoxLayout::TopToBottom;
    if (mainLayout_->direction() != wanted) {
        mainLayout_->setDirection(wanted);
        redraw();   // the axis titles follow the width (see redraw)
    }
}

AccuracyPanel::~AccuracyPanel()
{
    runner_->cancel();   // the study stops at its next step and is waited for
    runner_->wait();
}

void AccuracyPanel::setScene(const SceneDef& scene, const QString& label)
{
    runner_->cancel();
    runner_->wait();
    scene_ = scene;
    haveScene_ = true;
    label_ = label;
    endTime_->setValue(double(scene.steps) * scene.dt);
    model_->setResult({});
    progress_->setValue(0);
    redraw();

    // Does the scene have an exact answer? (the runner's own check, with the default T)
    sceneIssues_.clear();
    std::vector<SceneIssue> reasons;
    const lab::StudyConfig probe;
    for (const SceneIssue& issue : lab::validateStudy(scene, probe)) {
        if (issue.path == "dt" || issue.path == "t_end") continue;   // the controls can fix these
        sceneIssues_ << QString::fromStdString(issue.path + ": " + issue.reason);
    }
    sceneLabel_->setText(tr("Scene: %1").arg(label));
    if (sceneIssues_.isEmpty()) {
        setStatus(tr("Ready: choose integrators and step sizes, then Run."), false);
    } else {
        setStatus(tr("This scene has no exact answer to measure against:\n%1").arg(sceneIssues_.join('\n')), true);
    }
    updateButtons();
}

QStringList AccuracyPanel::integratorNames() const
{
    QStringList names;
    for (const QCheckBox* box : integratorBoxes_) names << box->text();
    return names;
}

QStringList AccuracyPanel::selectedIntegrators() const
{
    QStringList names;
    for (const QCheckBox* box : integratorBoxes_) {
        if (box->isChecked()) names << box->text();
    }
    return names;
}

void AccuracyPanel::setSelectedIntegrators(const QStringList& names)
{
    for (QCheckBox* box : integratorBoxes_) box->setChecked(names.contains(box->text()));
}

QString AccuracyPanel::dtText() const { return dtEdit_->text(); }
void AccuracyPanel::setDtText(const QString& text) { dtEdit_->setText(text); }
double AccuracyPanel::endTime() const { return endTime_->value(); }
void AccuracyPanel::setEndTime(double T) { endTime_->setValue(T); }

ErrorMetric AccuracyPanel::errorMetric() const { return ErrorMetric(metric_->currentData().toInt()); }

void AccuracyPanel::setErrorMetric(ErrorMetric metric)
{
    metric_->setCurrentIndex(metric_->findData(int(metric)));
}

void AccuracyPanel::setTimingBudget(double seconds) { timingBudget_ = seconds; }

lab::StudyConfig AccuracyPanel::config(QStringList& problems) const
{
    lab::StudyConfig c;
    for (const QString& name : selectedIntegrators()) c.integrators.push_back(name.toStdString());
    if (c.integrators.empty()) problems << tr("integrators: choose at least one");
    const QStringList parts = dtEdit_->text().split(QRegularExpression("[,;\\s]+"), Qt::SkipEmptyParts);
    if (parts.isEmpty()) problems << tr("dt: give at least one step size");
    for (const QString& text : parts) {
        bool ok = false;
        const double dt = text.toDouble(&ok);
        if (!ok) {
            problems << tr("dt: must be a finite number > 0, got \"%1\"").arg(text);
        } else {
            c.dts.push_back(dt);
        }
    }
    c.tEnd = endTime_->value();
    c.timingBudgetSeconds = timingBudget_;
    return c;
}

bool AccuracyPanel::startStudy()
{
    if (isRunning()) return false;
    if (!haveScene_) {
        setStatus(tr("No scene to study."), true);
        return false;
    }
    QStringList problems;
    const lab::StudyConfig c = config(problems);
    if (problems.isEmpty()) {
        for (const SceneIssue& issue : lab::validateStudy(scene_, c)) {
            problems << QString::fromStdString(issue.path + ": " + issue.reason);
        }
    }
    if (!problems.isEmpty()) {
        setStatus(problems.join('\n'), true);
        return false;
    }

    progress_->setValue(0);
    setStatus(tr("Running %1 runs…").arg(int(c.integrators.size() * c.dts.size())), false);
    const SceneDef scene = scene_;
    runner_->start([scene, c](const lab::StudyProgress& progress, const std::atomic<bool>* cancel) {
        return lab::runStudy(scene, c, progress, cancel);
    });
    updateButtons();
    return true;
}

void AccuracyPanel::cancelStudy() { runner_->cancel(); }

bool AccuracyPanel::isRunning() const { return runner_->isRunning(); }

const lab::StudyResult& AccuracyPanel::result() const { return model_->result(); }

QString AccuracyPanel::statusText() const { return status_->text(); }

int AccuracyPanel::seriesCount() const
{
    int n = 0;
    for (const QAbstractSeries* s : chart_->series()) {
        if (s->name() != QStringLiteral("Pareto front")) ++n;
    }
    return n;
}

void AccuracyPanel::onRunClicked() { startStudy(); }

void AccuracyPanel::onProgress(int done, int total)
{
    if (total > 0) progress_->setValue(int(std::lround(100.0 * done / total)));
    emit progressChanged(done, total);
}

void AccuracyPanel::onFinished()
{
    const lab::StudyResult r = runner_->result();
    model_->setResult(r);
    redraw();
    if (r.cancelled) {
        setStatus(tr("Cancelled after %1 of %2 runs.").arg(r.rows.size()).arg(r.runsPlanned), false);
    } else {
        int blown = 0;
        for (const lab::StudyRow& row : r.rows) blown += row.status == lab::RunStatus::BlownUp ? 1 : 0;
        QString text = tr("%1 runs to T = %2 s against the exact answer: %3.")
                           .arg(r.rows.size())
                           .arg(r.tEnd)
                           .arg(QString::fromStdString(r.reference));
        if (blown > 0) text += tr(" %1 blew up (no numbers shown; see the table).").arg(blown);
        if (front_.zeroErrors > 0) {
            text += tr(" %1 exact to the last bit (error 0) cannot be drawn on a log axis.").arg(front_.zeroErrors);
        }
        setStatus(text, false);
        progress_->setValue(100);
    }
    updateButtons();
    emit studyFinished();
}

void AccuracyPanel::redraw()
{
    chart_->removeAllSeries();
    for (QAbstractAxis* axis : chart_->axes()) {
        chart_->removeAxis(axis);
        delete axis;
    }
    front_ = buildFront(model_->result(), errorMetric());

    auto* xAxis = new QLogValueAxis;
    xAxis->setBase(10.0);
    xAxis->setLabelFormat("%g");
    // Docked (narrow), the long cost title would be cut before its unit: a short one
    // there, the whole definition in the tooltip. Tick labels are never elided.
    const bool narrow = mainLayout_ != nullptr && mainLayout_->direction() == QBoxLayout::TopToBottom;
    xAxis->setTitleText(narrow ? QStringLiteral("cost to reach T [ms]") : costTitle());
    chartView_->setToolTip(costTitle());
    xAxis->setTruncateLabels(false);
    auto* yAxis = new QLogValueAxis;
    yAxis->setBase(10.0);
    yAxis->setLabelFormat("%.0e");
    yAxis->setTitleText(metricTitle(errorMetric()));
    yAxis->setTruncateLabels(false);
    chart_->addAxis(xAxis, Qt::AlignBottom);
    chart_->addAxis(yAxis, Qt::AlignLeft);
    if (front_.pointCount() == 0) {
        xAxis->setRange(0.01, 100.0);
        yAxis->setRange(1e-12, 1.0);
        return;
    }
    setDecades(xAxis, front_.minCost, front_.maxCost);
    setDecades(yAxis, front_.minError, front_.maxError);

    for (const IntegratorCurve& curve : front_.curves) {
        if (curve.points.isEmpty()) continue;
        auto* series = new QLineSeries;
        series->setName(curve.integrator);
        series->setPointsVisible(true);
        series->setMarkerSize(7.0);
        QPen pen(integratorColour(curve.integrator));
        pen.setWidthF(2.0);
        series->setPen(pen);
        for (const FrontPoint& p : curve.points) series->append(p.cost_ms, p.error);
        chart_->addSeries(series);
        series->attachAxis(xAxis);
        series->attachAxis(yAxis);
    }
    if (front_.pareto.size() > 1) {
        auto* pareto = new QLineSeries;
        pareto->setName(QStringLiteral("Pareto front"));
        QPen pen(Qt::black);
        pen.setStyle(Qt::DashLine);
        pen.setWidthF(1.5);
        pareto->setPen(pen);
        for (const FrontPoint& p : front_.pareto) pareto->append(p.cost_ms, p.error);
        chart_->addSeries(pareto);
        pareto->attachAxis(xAxis);
        pareto->attachAxis(yAxis);
    }
}

void AccuracyPanel::setStatus(const QString& text, bool error)
{
    status_->setText(text);
    status_->setStyleSheet(error ? QStringLiteral("color: #b00020;") : QString());
}

void AccuracyPanel::updateButtons()
{
    const bool running = isRunning();
    run_->setEnabled(!running && haveScene_ && sceneIssues_.isEmpty());
    cancel_->setEnabled(running);
    const bool haveRows = !model_->result().rows.empty();
    exportPng_->setEnabled(!running && haveRows);
    exportCsv_->setEnabled(!running && haveRows);
}

bool AccuracyPanel::exportPng(const QString& path, QString* error)
{
    const QPixmap pixmap = chartView_->grab();
    QByteArray png;
    QBuffer buffer(&png);
    if (!buffer.open(QIODevice::WriteOnly) || !pixmap.save(&buffer, "PNG")) {
        if (error) *error = tr("%1: cannot write: the PNG could not be encoded").arg(path);
        return false;
    }
    return writeFileAtomically(path, png, error);   // complete or not at all
}

bool AccuracyPanel::exportCsv(const QString& path, QString* error) const
{
    return writeFileAtomically(path, studyToCsv(model_->result()).toUtf8(), error);
}

void AccuracyPanel::onExportPng()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Export plot"), "accuracy-front.png", tr("PNG (*.png)"));
    if (path.isEmpty()) return;
    QString error;
    if (!exportPng(path, &error)) setStatus(error, true);
}

void AccuracyPanel::onExportCsv()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Export numbers"), "study.csv", tr("CSV (*.csv)"));
    if (path.isEmpty()) return;
    QString error;
    if (!exportCsv(path, &error)) setStatus(error, true);
}

} // namespace rbw
