#include "app/gui/panels/accuracy/contact_study_panel.h"

#include "app/exercise/answer_parser.h"
#include "app/output/atomic_file.h"
#include "app/output/study_csv.h"
#include "app/gui/panels/accuracy/log_axes.h"
#include "physics/engine/scene_words.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLineSeries>
#include <QLocale>
#include <QLogValueAxis>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QTableView>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>

namespace rbw {

namespace {

constexpr int kDtColumn = 3;   // contactStudyCsvHeader(): problem, model, iterations, dt, ...

QString metricTitle(ContactMetric m)
{
    switch (m) {
    case ContactMetric::Overlap: return QObject::tr("deepest box-box overlap [m]");
    case ContactMetric::Below: return QObject::tr("deepest corner below the ground [m]");
    case ContactMetric::Drift: return QObject::tr("drift |x(T) - x(0)| [m]");
    case ContactMetric::EnergyGained: return QObject::tr("energy gained, max(E - E0) [J]");
    }
    return {};
}

// The row's error; empty where the run has none (a blown-up run, the rain's drift).
std::optional<double> metricOf(const lab::ContactStudyRow& row, ContactMetric m)
{
    if (row.status != lab::RunStatus::Ok) return std::nullopt;
    switch (m) {
    case ContactMetric::Overlap: return row.deepestOverlap;
    case ContactMetric::Below: return row.deepestBelow;
    case ContactMetric::Drift: return row.drift;
    case ContactMetric::EnergyGained: return row.energyGained;
    }
    return std::nullopt;
}

QString seriesName(const lab::ContactStudyRow& row)
{
    // Told apart by their first words: the legend elides the end of a long name.
    if (row.model == sceneWord(ManifoldSolver::SoftStep)) return QObject::tr("soft step, %1 substeps").arg(row.iterations);
    return row.model == sceneWord(ContactModel::Course) ? QObject::tr("course model (one impulse per corner)")
                                 : (row.iterations == 1 ? QObject::tr("manifold, 1 solver iteration")
                                                        : QObject::tr("manifold, %1 solver iterations").arg(row.iterations));
}

// A step size as a student writes it: 1/30 when 1/h is a whole number (to 1e-9),
// otherwise 4 significant digits; never 0.033333333333333333.
QString shortStep(double h)
{
    const double perSecond = 1.0 / h;
    const double whole = std::round(perSecond);
    if (whole >= 1.0 && std::abs(perSecond - whole) <= 1e-9 * whole) return QStringLiteral("1/%1").arg(whole, 0, 'f', 0);
    return QString::number(h, 'g', 4);
}

// A table cell: the CSV's field (every digit, in the tooltip and Qt::UserRole), shown
// with 4 significant digits (whole numbers above 10^4 without decimals).
QString shortField(const QString& field, bool isStep)
{
    bool ok = false;
    const double v = field.toDouble(&ok);
    if (!ok || field.isEmpty()) return field;
    if (isStep && v > 0.0) return shortStep(v);
    if (std::abs(v) >= 1e4) return QString::number(v, 'f', 0);
    return QString::number(v, 'g', 4);
}

// "0.01" or a fraction "1/60" (h = 1/60 s is the usual game step), read as the check
// panel reads a student's numbers.
double readStep(const QString& text, bool* ok)
{
    const ParsedAnswer a = parseAnswerText(text, 1);
    *ok = a.ok();
    return a.ok() ? a.values[0] : 0.0;
}

} // namespace

ContactStudyPanel::ContactStudyPanel(QWidget* parent) : QWidget(parent)
{
    const lab::ContactStudyConfig defaults;
    problem_ = new QComboBox;
    problem_->setObjectName("contactProblem");
    for (lab::ContactProblem p : {lab::ContactProblem::RestingBox, lab::ContactProblem::Tower, lab::ContactProblem::Rain}) {
        problem_->addItem(QString::fromLatin1(lab::contactProblemName(p)), static_cast<int>(p));
    }
    boxes_ = new QSpinBox;
    boxes_->setRange(1, 10000);
    boxes_->setValue(defaults.rainBoxes);
    boxes_->setToolTip(tr("The number of boxes of the rain (layers of 10 x 10)"));
    iterations_ = new QLineEdit(QStringLiteral("1, 2, 4, 8, 16"));
    iterations_->setToolTip(tr("The manifold model's solver iterations, comma-separated"));
    // The defaults (ContactStudyConfig: 1/30, 1/60, 1/120 s), as fractions.
    dts_ = new QLineEdit(QStringLiteral("1/30, 1/60, 1/120"));
    dts_->setToolTip(tr("Step sizes h in seconds, comma-separated; fractions such as 1/60 are read as such"));
    endTime_ = new QDoubleSpinBox;
    endTime_->setRange(0.01, 1000.0);
    endTime_->setDecimals(2);
    endTime_->setValue(defaults.tEnd);
    endTime_->setSuffix(QStringLiteral(" s"));
    metric_ = new QComboBox;
    // Drift first: the error of the resting box, the first problem.
    metric_->addItem(metricTitle(ContactMetric::Drift), static_cast<int>(ContactMetric::Drift));
    metric_->addItem(metricTitle(ContactMetric::Overlap), static_cast<int>(ContactMetric::Overlap));
    metric_->addItem(metricTitle(ContactMetric::Below), static_cast<int>(ContactMetric::Below));
    metric_->addItem(metricTitle(ContactMetric::EnergyGained), static_cast<int>(ContactMetric::EnergyGained));
    connect(metric_, &QComboBox::currentIndexChanged, this, &ContactStudyPanel::redraw);

    run_ = new QPushButton(tr("Run"));
    cancel_ = new QPushButton(tr("Cancel"));
    exportCsv_ = new QPushButton(tr("Export CSV…"));
    connect(run_, &QPushButton::clicked, this, &ContactStudyPanel::startStudy);
    connect(cancel_, &QPushButton::clicked, this, &ContactStudyPanel::cancelStudy);
    connect(exportCsv_, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export contact study"), QStringLiteral("contact-study.csv"),
                                                          tr("CSV (*.csv)"));
        QString error;
        if (!path.isEmpty() && !exportCsv(path, &error)) setStatus(error, true);
    });
    progress_ = new QProgressBar;
    progress_->setRange(0, 100);
    status_ = new QLabel;
    status_->setWordWrap(true);

    auto* form = new QFormLayout;
    form->addRow(tr("Problem"), problem_);
    form->addRow(tr("Boxes (rain)"), boxes_);
    form->addRow(tr("Solver iterations"), iterations_);
    form->addRow(tr("h [s]"), dts_);
    form->addRow(tr("T"), endTime_);
    form->addRow(tr("Error"), metric_);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(run_);
    buttons->addWidget(cancel_);
    buttons->addWidget(exportCsv_);
    buttons->addStretch();

    intro_ = new QLabel(
        tr("<b>Do the boxes come to rest?</b> Each problem is run with the <i>course model</i> (one impulse per "
           "corner, lessons 3–7) and with the <i>manifold model</i> of lesson 11 at each number of solver "
           "iterations, at each step h. The chart puts each run's error against the time its steps took: "
           "<b>lower is more accurate, further left is cheaper</b>; one line per model through its step sizes. "
           "The table has every number (hover a cell for all its digits)."));
    intro_->setObjectName("contactStudyIntro");
    intro_->setWordWrap(true);

    chart_ = new QChart;
    chart_->setTitle(tr("Contacts: error against the cost of reaching T"));
    // On the right, one entry per line: each name is read whole.
    chart_->legend()->setAlignment(Qt::AlignRight);
    auto* chartView = new QChartView(chart_);
    chartView->setRenderHint(QPainter::Antialiasing);
    chartView->setMinimumHeight(260);

    table_ = new QStandardItemModel(this);
    tableView_ = new QTableView;
    tableView_->setModel(table_);
    tableView_->verticalHeader()->hide();
    tableView_->setMinimumHeight(140);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro_);
    layout->addLayout(form);
    layout->addLayout(buttons);
    layout->addWidget(progress_);
    layout->addWidget(status_);
    layout->addWidget(chartView, 3);
    layout->addWidget(tableView_, 2);

    runner_ = new StudyRunner<lab::ContactStudyResult>(this);
    connect(runner_, &StudyRunnerSignals::progressed, this,
            [this](int done, int total) { progress_->setValue(int(std::lround(100.0 * done / total))); });
    connect(runner_, &StudyRunnerSignals::finished, this, &ContactStudyPanel::onFinished);
    setStatus(tr("The boxes should end at rest without overlap: run a problem to see how far each model gets, "
                 "and at what cost."),
              false);
    redraw();
    updateButtons();
}

ContactStudyPanel::~ContactStudyPanel()
{
    runner_->cancel();   // the study stops at its next step and is waited for
    runner_->wait();
}

void ContactStudyPanel::setProblem(lab::ContactProblem p) { problem_->setCurrentIndex(problem_->findData(static_cast<int>(p))); }
void ContactStudyPanel::setIterationsText(const QString& text) { iterations_->setText(text); }
void ContactStudyPanel::setDtText(const QString& text) { dts_->setText(text); }
void ContactStudyPanel::setEndTime(double T) { endTime_->setValue(T); }
void ContactStudyPanel::setRainBoxes(int n) { boxes_->setValue(n); }
void ContactStudyPanel::setMetric(ContactMetric m) { metric_->setCurrentIndex(metric_->findData(static_cast<int>(m))); }

lab::ContactStudyConfig ContactStudyPanel::config(QStringList& problems) const
{
    lab::ContactStudyConfig c;
    c.problem = static_cast<lab::ContactProblem>(problem_->currentData().toInt());
    c.rainBoxes = boxes_->value();
    c.tEnd = endTime_->value();
    c.iterations.clear();
    for (const QString& part : iterations_->text().split(',', Qt::SkipEmptyParts)) {
        bool ok = false;
        const int n = part.trimmed().toInt(&ok);
        if (!ok) problems << tr("iterations: must be whole numbers, got \"%1\"").arg(part.trimmed());
        else c.iterations.push_back(n);
    }
    c.dts.clear();
    for (const QString& part : dts_->text().split(',', Qt::SkipEmptyParts)) {
        bool ok = false;
        const double h = readStep(part.trimmed(), &ok);
        if (!ok) problems << tr("h: must be numbers > 0, got \"%1\"").arg(part.trimmed());
        else c.dts.push_back(h);
    }
    return c;
}

bool ContactStudyPanel::startStudy()
{
    if (isRunning()) return false;
    QStringList problems;
    const lab::ContactStudyConfig c = config(problems);
    if (problems.isEmpty()) {
        for (const SceneIssue& issue : lab::validateContactStudy(c)) {
            problems << QString::fromStdString(issue.path + ": " + issue.reason);
        }
    }
    if (!problems.isEmpty()) {
        setStatus(problems.join('\n'), true);
        return false;
    }
    progress_->setValue(0);
    setStatus(tr("Running…"), false);
    runner_->start([c](const lab::StudyProgress& progress, const std::atomic<bool>* cancel) {
        return lab::runContactStudy(c, progress, cancel);
    });
    updateButtons();
    return true;
}

void ContactStudyPanel::cancelStudy() { runner_->cancel(); }

bool ContactStudyPanel::isRunning() const { return runner_->isRunning(); }

QString ContactStudyPanel::statusText() const { return status_->text(); }

QString ContactStudyPanel::introText() const { return intro_->text(); }

int ContactStudyPanel::seriesCount() const { return static_cast<int>(chart_->series().size()); }

bool ContactStudyPanel::exportCsv(const QString& path, QString* error) const
{
    return writeFileAtomically(path, contactStudyToCsv(result_).toUtf8(), error);
}

void ContactStudyPanel::onFinished()
{
    result_ = runner_->result();
    fillTable();
    if (result_.cancelled) {
        setStatus(tr("Cancelled after %1 of %2 runs.").arg(result_.rows.size()).arg(result_.runsPlanned), false);
    } else {
        setStatus(tr("%1 runs of %2. Cost: the wall time of the steps to T (the measuring is not timed).")
                      .arg(result_.rows.size())
                      .arg(QString::fromStdString(result_.problem)),
                  false);
        progress_->setValue(100);
    }
    redraw();
    updateButtons();
    emit studyFinished();
}

void ContactStudyPanel::fillTable()
{
    table_->clear();
    table_->setHorizontalHeaderLabels(contactStudyCsvHeader());
    const QStringList lines = contactStudyToCsv(result_).split('\n', Qt::SkipEmptyParts);
    // The CSV's own fields (the one formatting of the numbers), without its header,
    // shown short (h as 1/30); every digit in the tooltip.
    for (int i = 1; i < lines.size(); ++i) {
        QList<QStandardItem*> items;
        const QStringList fields = lines[i].split(',');
        for (int c = 0; c < fields.size(); ++c) {
            auto* item = new QStandardItem(shortField(fields[c], c == kDtColumn));
            item->setData(fields[c], Qt::UserRole);
            item->setToolTip(fields[c]);
            item->setEditable(false);
            items << item;
        }
        table_->appendRow(items);
    }
    tableView_->resizeColumnsToContents();
}

void ContactStudyPanel::redraw()
{
    chart_->removeAllSeries();
    for (QAbstractAxis* axis : chart_->axes()) {
        chart_->removeAxis(axis);
        delete axis;
    }
    const ContactMetric metric = static_cast<ContactMetric>(metric_->currentData().toInt());
    auto* xAxis = new QLogValueAxis;
    xAxis->setLabelFormat("%g");
    xAxis->setTitleText(tr("cost: wall time of the steps to T [ms]"));
    auto* yAxis = new QLogValueAxis;
    yAxis->setLabelFormat("%.0e");
    yAxis->setTitleText(metricTitle(metric));
    chart_->addAxis(xAxis, Qt::AlignBottom);
    chart_->addAxis(yAxis, Qt::AlignLeft);

    // One line per model and iteration count, through its step sizes, in cost order.
    // (model, iterations (0: course)) -> (ms, error): the soft step's substeps may equal an
    // iteration count of the sequential impulses, and they are two lines
    using LineKey = std::pair<std::string, int>;
    std::map<LineKey, std::vector<std::pair<double, double>>> lines;
    std::map<LineKey, QString> names;
    double xmin = std::numeric_limits<double>::infinity(), xmax = 0.0;
    double ymin = std::numeric_limits<double>::infinity(), ymax = 0.0;
    int zeros = 0;
    for (const lab::ContactStudyRow& row : result_.rows) {
        const std::optional<double> e = metricOf(row, metric);
        if (!e) continue;
        const double ms = row.nsPerStep * double(row.steps) * 1e-6;
        if (!(*e > 0.0) || !(ms > 0.0)) {
            ++zeros;   // 0 has no place on a log axis
            continue;
        }
        lines[{row.model, row.iterations}].emplace_back(ms, *e);
        names[{row.model, row.iterations}] = seriesName(row);
        xmin = std::min(xmin, ms);
        xmax = std::max(xmax, ms);
        ymin = std::min(ymin, *e);
        ymax = std::max(ymax, *e);
    }
    if (lines.empty()) {
        xAxis->setRange(0.01, 100.0);
        yAxis->setRange(1e-9, 1.0);
    } else {
        setDecades(xAxis, xmin, xmax);
        setDecades(yAxis, ymin, ymax);
    }
    for (auto& [key, points] : lines) {
        std::sort(points.begin(), points.end());
        auto* series = new QLineSeries;
        series->setName(names[key]);
        series->setPointsVisible(true);
        if (key.second == 0) {
            QPen pen(Qt::black);
            pen.setWidthF(2.0);
            pen.setStyle(Qt::DashLine);
            series->setPen(pen);
        }
        for (const auto& [ms, e] : points) series->append(ms, e);
        chart_->addSeries(series);
        series->attachAxis(xAxis);
        series->attachAxis(yAxis);
    }
    zeroNote_ = zeros > 0 ? tr(" %1 runs with an error of exactly 0 cannot be drawn on a log axis: see the table.").arg(zeros)
                          : QString();
    status_->setText(baseStatus_ + zeroNote_);
}

void ContactStudyPanel::setStatus(const QString& text, bool error)
{
    baseStatus_ = text;
    status_->setText(error ? text : text + zeroNote_);
    status_->setStyleSheet(error ? QStringLiteral("color: #b00020") : QString());
}

void ContactStudyPanel::updateButtons()
{
    const bool running = isRunning();
    run_->setEnabled(!running);
    cancel_->setEnabled(running);
    exportCsv_->setEnabled(!running && !result_.rows.empty());
}

} // namespace rbw
