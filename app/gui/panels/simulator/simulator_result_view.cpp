#include "app/gui/panels/simulator/simulator_result_view.h"
#include "app/core/step_numbering.h"

#include "physics/workbook/checker/mistakes.h"
#include "physics/workbook/probes/probe_verdict.h"
#include "physics/workbook/probes/replay.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QSplitter>
#include <QTableWidget>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <algorithm>
#include <iterator>

namespace rbw {

namespace {

const QColor kDivergenceBackground(255, 205, 200);

QString numbers(const std::vector<double>& v, std::size_t from, std::size_t count)
{
    QStringList parts;
    for (std::size_t i = from; i < from + count && i < v.size(); ++i) parts << QString::number(v[i], 'g', 9);
    return QLatin1Char('(') + parts.join(", ") + QLatin1Char(')');
}

QString verdictSentence(probes::Verdict v)
{
    switch (v) {
    case probes::Verdict::Matches:
        return QObject::tr("your simulator gives the course algorithm's answers on every probe.");
    case probes::Verdict::Explained:
        return QObject::tr("your simulator makes a mistake the workbook knows: it gives your answers on every probe.");
    case probes::Verdict::PartlyExplained:
        return QObject::tr("a mistake the workbook knows gives your answers on some probes, not on all.");
    case probes::Verdict::Unexplained:
        return QObject::tr("your answers differ, and no mistake the workbook knows gives them.");
    }
    return {};
}

// The quantities of an answer: name, first number, count.
struct Part {
    const char* id;
    std::size_t from, count;
};
const Part kParts[] = {{"x", 0, 3}, {"v", 3, 3}, {"omega", 6, 3}, {"r", 9, 4}};

QTableWidgetItem* item(const QString& text)
{
    auto* i = new QTableWidgetItem(text);
    i->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
    return i;
}

} // namespace

QString SimulatorResultView::quantityWords(const std::string& quantity)
{
    if (quantity == "x") return tr("position x");
    if (quantity == "v") return tr("velocity v");
    if (quantity == "omega") return tr("angular velocity ω");
    if (quantity == "r") return tr("orientation r");
    return QString::fromStdString(quantity);
}

SimulatorResultView::SimulatorResultView(QWidget* parent) : QWidget(parent)
{
    verdict_ = new QLabel(this);
    verdict_->setObjectName("verdictLabel");
    verdict_->setWordWrap(true);
    verdict_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QFont big = verdict_->font();
    big.setPointSizeF(big.pointSizeF() * 1.2);
    big.setBold(true);
    verdict_->setFont(big);
    error_ = new QLabel(this);
    error_->setObjectName("errorLabel");
    error_->setWordWrap(true);
    error_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    error_->setStyleSheet("QLabel { color: #a00000; }");
    details_ = new QTextBrowser(this);
    details_->setObjectName("detailsText");
    details_->setOpenLinks(false);

    probes_ = new QTableWidget(0, 4, this);
    probes_->setObjectName("probesTable");
    probes_->setHorizontalHeaderLabels({tr("Probe"), tr("Result"), tr("Reproduced by"), tr("What it brings out")});
    probes_->setSelectionBehavior(QAbstractItemView::SelectRows);
    probes_->setSelectionMode(QAbstractItemView::SingleSelection);
    probes_->verticalHeader()->setVisible(false);
    probes_->horizontalHeader()->setStretchLastSection(true);
    probes_->setWordWrap(false);
    connect(probes_, &QTableWidget::currentCellChanged, this,
            [this](int row, int, int, int) { selectProbe(row); });

    probeDivergence_ = new QLabel(this);
    probeDivergence_->setObjectName("probeDivergenceLabel");
    probeDivergence_->setWordWrap(true);
    probeDivergence_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    slider_ = new QSlider(Qt::Horizontal, this);
    slider_->setObjectName("stepSlider");
    slider_->setTickPosition(QSlider::TicksBelow);
    slider_->setPageStep(1);
    sliderLabel_ = new QLabel(this);
    sliderLabel_->setObjectName("stepSliderLabel");
    sliderLabel_->setMinimumWidth(sliderLabel_->fontMetrics().horizontalAdvance("answer 88 · after step k = 88 · body 8  "));
    jump_ = new QPushButton(tr("Go to the first divergence"), this);
    jump_->setObjectName("divergenceButton");
    connect(slider_, &QSlider::valueChanged, this, &SimulatorResultView::selectAnswer);
    connect(jump_, &QPushButton::clicked, this, [this] {
        if (probe_ < 0 || !run_.diagnosis.probes[probe_].divergence) return;
        selectAnswer(run_.diagnosis.probes[probe_].divergence->answer);
    });

    steps_ = new QTableWidget(0, 6, this);
    steps_->setObjectName("stepsTable");
    steps_->setHorizontalHeaderLabels({tr("#"), tr("State"), tr("Body"), tr("Quantity"), tr("Workbook"), tr("Yours")});
    steps_->setSelectionBehavior(QAbstractItemView::SelectRows);
    steps_->verticalHeader()->setVisible(false);
    steps_->horizontalHeader()->setStretchLastSection(true);
    steps_->setWordWrap(false);

    auto* sliderRow = new QHBoxLayout;
    sliderRow->addWidget(new QLabel(tr("Answer:"), this));
    sliderRow->addWidget(slider_, 1);
    sliderRow->addWidget(sliderLabel_);
    sliderRow->addWidget(jump_);
    auto* probePane = new QWidget(this);
    auto* probeLayout = new QVBoxLayout(probePane);
    probeLayout->setContentsMargins(0, 0, 0, 0);
    probeLayout->addWidget(probeDivergence_);
    probeLayout->addLayout(sliderRow);
    probeLayout->addWidget(steps_, 1);

    tables_ = new QSplitter(Qt::Horizontal, this);
    tables_->addWidget(probes_);
    tables_->addWidget(probePane);
    tables_->setStretchFactor(0, 1);
    tables_->setStretchFactor(1, 4);
    auto* split = new QSplitter(Qt::Vertical, this);
    split->setObjectName("resultSplitter");
    split->addWidget(details_);
    split->addWidget(tables_);
    split->setStretchFactor(0, 2);
    split->setStretchFactor(1, 3);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(verdict_);
    layout->addWidget(error_);
    layout->addWidget(split, 1);
    clear();
}

void SimulatorResultView::clear()
{
    run_ = DiagnoseRun{};
    right_.clear();
    probe_ = -1;
    verdict_->clear();
    verdict_->hide();
    error_->clear();
    error_->hide();
    details_->clear();
    probes_->setRowCount(0);
    steps_->setRowCount(0);
    probeDivergence_->clear();
    slider_->setRange(0, 0);
    slider_->setEnabled(false);
    sliderLabel_->clear();
    jump_->setEnabled(false);
}

void SimulatorResultView::showFailure(const QString& message, const QStringList& stderrTail)
{
    clear();
    QString text = message;
    if (!stderrTail.isEmpty()) text += "\n" + tr("Its last lines on standard error:") + "\n  " + stderrTail.join("\n  ");
    error_->setText(text);
    error_->show();
}

QString SimulatorResultView::divergenceWords(int probe, const probes::Divergence& d) const
{
    // d.step: the steps before the answer, n; worded as every screen words a state
    // (step_numbering.h): "after step k = n - 1", "before step k = 0"
    return tr("probe %1 (%2), %3, body %4, %5: expected %6, yours %7")
        .arg(probe + 1)
        .arg(QString::fromStdString(run_.probes[probe].name))
        .arg(steps::stateName(d.step))
        .arg(d.body)
        .arg(quantityWords(d.quantity), numbers(d.expected, 0, d.expected.size()), numbers(d.given, 0, d.given.size()));
}

void SimulatorResultView::showRun(const DiagnoseRun& run, const std::vector<probes::Answers>& right)
{
    clear();
    run_ = run;
    right_ = right;
    const probes::SimulatorDiagnosis& d = run_.diagnosis;
    verdict_->setText(tr("Verdict: %1 — %2").arg(QString::fromLatin1(probes::verdictName(d.verdict)),
                                                  verdictSentence(d.verdict)));
    verdict_->show();

    QString html;
    auto describe = [&html](const std::string& id) {
        const MistakeInfo* m = findMistake(id);
        if (m == nullptr) return;
        html += QStringLiteral("<p><b>%1</b><br>your equation: <code>%2</code><br>the right one: %3</p>")
                    .arg(QString::fromLatin1(m->id).toHtmlEscaped(), QString::fromLatin1(m->equation).toHtmlEscaped(),
                         QString::fromLatin1(m->explanation).toHtmlEscaped());
    };
    if (!d.mistakes.empty()) html += "<h3>" + tr("The mistake") + "</h3>";
    for (const std::string& id : d.mistakes) describe(id);
    if (!d.possibleMistakes.empty()) {
        html += "<h3>" + tr("Possible mistakes (each explains your answers equally well)") + "</h3>";
    }
    for (const std::string& id : d.possibleMistakes) describe(id);
    for (const probes::RestitutionOf& r : d.restitution) {
        html += "<p>" +
                tr("Restitution fitted to your collision answers: c = %1 (%2)")
                    .arg(QString::number(r.c, 'g', 6), QString::fromStdString(r.model).toHtmlEscaped()) +
                "</p>";
    }
    if (d.firstDivergence) {
        html += "<p><b>" + tr("First divergence from the right algorithm:") + "</b> " +
                divergenceWords(d.divergenceProbe, *d.firstDivergence).toHtmlEscaped() + "</p>";
    } else {
        html += "<p>" + tr("No divergence: every number agrees with the right algorithm.") + "</p>";
    }
    if (!run_.templateTests.empty()) {
        int passed = 0;
        QStringList lines;
        for (const TemplateTestResult& t : run_.templateTests) {
            passed += t.failure ? 0 : 1;
            const QString line = QString::fromStdString(t.test->name) +
                                 (t.test->version.empty() ? QString() : " (" + QString::fromStdString(t.test->version) + ")") +
                                 ": " + (t.failure ? tr("fails") : tr("passes")) + " — " + tr("it expects ") +
                                 QString::fromStdString(t.test->expects);
            lines << line.toHtmlEscaped();
        }
        html += "<p><b>" + tr("The template's public tests: %1 of %2 pass.").arg(passed).arg(lines.size()) + "</b><br>" +
                lines.join("<br>") + "<br>" +
                tr("A correct simulator fails TestRigidBodiesAfterForceApplication: it expects the template's "
                   "transposed world inertia (lesson 8).") +
                "</p>";
    }
    html += "<p><small>" +
            tr("Numbers match within %1 of the largest |value| of that quantity in the probe (float round-off "
               "matches).")
                .arg(probes::kRelativeTolerance) +
            "</small></p>";
    details_->setHtml(html);
    fillProbeTable();
    // the values side by side get four fifths of the width (at 1366×768 none is cut)
    const int width = tables_->width();
    if (width > 0) tables_->setSizes({width / 5, width - width / 5});
    if (!run_.probes.empty()) {
        const int first = d.divergenceProbe >= 0 ? d.divergenceProbe : 0;
        probes_->setCurrentCell(first, 0);
        selectProbe(first);
    }
}

void SimulatorResultView::fillProbeTable()
{
    const probes::SimulatorDiagnosis& d = run_.diagnosis;
    probes_->setRowCount(static_cast<int>(d.probes.size()));
    for (std::size_t p = 0; p < d.probes.size(); ++p) {
        const int row = static_cast<int>(p);
        QStringList by;
        for (const std::string& l : d.probes[p].reproducedBy) by << QString::fromStdString(l);
        probes_->setItem(row, 0, item(QStringLiteral("%1 %2").arg(p + 1).arg(QString::fromStdString(run_.probes[p].name))));
        probes_->setItem(row, 1, item(d.probes[p].matchesRight ? tr("matches") : tr("differs")));
        probes_->setItem(row, 2, item(by.join(", ")));
        probes_->setItem(row, 3, item(QString::fromStdString(run_.probes[p].purpose)));
        probes_->item(row, 3)->setToolTip(QString::fromStdString(run_.probes[p].purpose));
        if (!d.probes[p].matchesRight) probes_->item(row, 1)->setBackground(kDivergenceBackground);
    }
    probes_->resizeColumnsToContents();
}

void SimulatorResultView::selectProbe(int probe)
{
    if (probe < 0 || probe >= static_cast<int>(run_.probes.size())) return;
    if (probes_->currentRow() != probe) probes_->setCurrentCell(probe, 0);
    if (probe == probe_) return;
    probe_ = probe;
    fillStepTable();
    const std::optional<probes::Divergence>& div = run_.diagnosis.probes[probe].divergence;
    probeDivergence_->setText(div ? tr("First divergence: %1").arg(divergenceWords(probe, *div))
                                  : tr("Probe %1 (%2): every number agrees with the right algorithm.")
                                        .arg(probe + 1)
                                        .arg(QString::fromStdString(run_.probes[probe].name)));
    const int answers = static_cast<int>(run_.given[probe].size());
    slider_->setRange(0, std::max(0, answers - 1));
    slider_->setEnabled(answers > 1);
    jump_->setEnabled(div.has_value());
    const int start = div ? div->answer : 0;
    if (slider_->value() == start) selectAnswer(start);
    else slider_->setValue(start);
}

void SimulatorResultView::fillStepTable()
{
    const probes::Probe& probe = run_.probes[probe_];
    const probes::Answers& given = run_.given[probe_];
    const probes::Answers& right = right_[probe_];
    const std::vector<probes::AnswerSlot> where = probes::answerSlots(probe);
    const std::optional<probes::Divergence>& div = run_.diagnosis.probes[probe_].divergence;
    steps_->setRowCount(0);
    for (std::size_t a = 0; a < given.size(); ++a) {
        for (const Part& part : kParts) {
            const bool yours = given[a].size() >= part.from + part.count;
            const int row = steps_->rowCount();
            steps_->insertRow(row);
            steps_->setItem(row, 0, item(QString::number(a)));
            steps_->setItem(row, 1, item(steps::stateName(where[a].step)));
            steps_->setItem(row, 2, item(QString::number(where[a].body)));
            steps_->setItem(row, 3, item(quantityWords(part.id)));
            steps_->setItem(row, 4, item(numbers(right[a], part.from, part.count)));
            steps_->setItem(row, 5, item(yours ? numbers(given[a], part.from, part.count) : tr("(not printed)")));
            if (div && div->answer == static_cast<int>(a) && div->quantity == part.id) {
                for (int c = 0; c < steps_->columnCount(); ++c) {
                    steps_->item(row, c)->setBackground(kDivergenceBackground);
                    QFont f = steps_->item(row, c)->font();
                    f.setBold(true);
                    steps_->item(row, c)->setFont(f);
                }
                steps_->item(row, 5)->setToolTip(tr("the first divergence in this probe"));
            }
        }
    }
    steps_->resizeColumnsToContents();
}

void SimulatorResultView::selectAnswer(int answer)
{
    if (probe_ < 0 || answer < 0 || answer >= static_cast<int>(run_.given[probe_].size())) return;
    if (slider_->value() != answer) {
        slider_->setValue(answer);   // comes back here
        return;
    }
    const std::vector<probes::AnswerSlot> where = probes::answerSlots(run_.probes[probe_]);
    sliderLabel_->setText(tr("answer %1 · %2 · body %3").arg(answer).arg(steps::stateName(where[answer].step)).arg(where[answer].body));
    const int parts = static_cast<int>(std::size(kParts));
    int row = answer * parts;
    const std::optional<probes::Divergence>& div = run_.diagnosis.probes[probe_].divergence;
    if (div && div->answer == answer) {
        for (int k = 0; k < parts; ++k) {
            if (div->quantity == kParts[k].id) row += k;
        }
    }
    steps_->setCurrentCell(row, 0);
    steps_->scrollToItem(steps_->item(row, 0), QAbstractItemView::PositionAtCenter);
}

QString SimulatorResultView::verdictText() const
{
    return verdict_->text();
}

QString SimulatorResultView::detailsText() const
{
    return details_->toPlainText();
}

QString SimulatorResultView::errorText() const
{
    return error_->text();
}

} // namespace rbw
