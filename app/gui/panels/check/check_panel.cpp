#include "app/gui/panels/check/check_panel.h"

#include "app/core/step_numbering.h"
#include "app/output/atomic_file.h"

#include "app/exercise/answers_input.h"
#include "app/gui/panels/check/check_model.h"
#include "physics/engine/scene.h"
#include "physics/engine/trace.h"
#include "physics/engine/world.h"

#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QKeyEvent>
#include <QLabel>
#include <QMessageBox>
#include <QPainter>
#include <QPushButton>
#include <QSplitter>
#include <QStyledItemDelegate>
#include <QTableView>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <algorithm>

namespace rbw {

namespace {

// Keeps a verdict's colour visible on the selected row: the cell is drawn unselected
// and framed in the highlight colour instead of being painted over with it.
class VerdictCellDelegate : public QStyledItemDelegate {
public:
    using QStyledItemDelegate::QStyledItemDelegate;
    void paint(QPainter* painter, const QStyleOptionViewItem& option, const QModelIndex& index) const override
    {
        if (!(option.state & QStyle::State_Selected) || !index.data(Qt::BackgroundRole).isValid()) {
            QStyledItemDelegate::paint(painter, option, index);
            return;
        }
        QStyleOptionViewItem plain(option);
        plain.state &= ~QStyle::State_Selected;
        QStyledItemDelegate::paint(painter, plain, index);
        painter->save();
        painter->setPen(QPen(option.palette.highlight().color(), 2));
        painter->drawRect(QRectF(option.rect).adjusted(1, 1, -1, -1));
        painter->restore();
    }
};

} // namespace

CheckPanel::CheckPanel(QWidget* parent) : QWidget(parent)
{
    model_ = new CheckModel(this);

    header_ = new QLabel;
    header_->setObjectName("checkHeader");
    header_->setWordWrap(true);
    // An input slip of the whole step (rbw check's file hint): steps counted from 1.
    stepHint_ = new QLabel;
    stepHint_->setObjectName("checkStepHint");
    stepHint_->setWordWrap(true);
    stepHint_->hide();

    view_ = new QTableView;
    view_->setObjectName("checkTable");
    view_->setModel(model_);
    view_->setSelectionBehavior(QAbstractItemView::SelectRows);
    view_->setSelectionMode(QAbstractItemView::SingleSelection);
    view_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                           QAbstractItemView::AnyKeyPressed | QAbstractItemView::SelectedClicked);
    view_->verticalHeader()->hide();
    view_->setWordWrap(false);
    auto* cellDelegate = new VerdictCellDelegate(view_);
    view_->setItemDelegateForColumn(CheckModel::YoursColumn, cellDelegate);
    view_->setItemDelegateForColumn(CheckModel::MarkColumn, cellDelegate);
    // The Yours column gets the room; the names are capped (their tooltips say more).
    view_->horizontalHeader()->setSectionResizeMode(CheckModel::YoursColumn, QHeaderView::Stretch);
    view_->horizontalHeader()->setSectionResizeMode(CheckModel::QuantityColumn, QHeaderView::Interactive);
    view_->horizontalHeader()->setSectionResizeMode(CheckModel::OfColumn, QHeaderView::Interactive);
    view_->horizontalHeader()->setSectionResizeMode(CheckModel::MarkColumn, QHeaderView::ResizeToContents);
    view_->horizontalHeader()->setSectionResizeMode(CheckModel::UnitColumn, QHeaderView::ResizeToContents);

    explanation_ = new QTextBrowser;
    explanation_->setObjectName("checkExplanation");
    explanation_->setOpenLinks(false);
    explanation_->setMinimumHeight(60);

    whatsWrong_ = new QPushButton(tr("What's wrong?"));
    whatsWrong_->setObjectName("whatsWrongButton");
    whatsWrong_->setToolTip(tr("Explain the selected entry: the mistake it matches and the workbook's number"));
    nextStep_ = new QPushButton(tr("Next step"));
    nextStep_->setObjectName("nextStepButton");
    nextStep_->setToolTip(tr("Select the first quantity you have not filled in"));
    save_ = new QPushButton(tr("Save…"));
    save_->setToolTip(tr("Save your entries of this step as an answers file (rbw check reads it)"));
    load_ = new QPushButton(tr("Load…"));
    load_->setToolTip(tr("Load an answers file"));
    clear_ = new QPushButton(tr("Clear"));
    clear_->setToolTip(tr("Remove your entries of this step"));

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(whatsWrong_);
    buttons->addWidget(nextStep_);
    buttons->addStretch(1);
    buttons->addWidget(save_);
    buttons->addWidget(load_);
    buttons->addWidget(clear_);

    auto* splitter = new QSplitter(Qt::Vertical);
    splitter->addWidget(view_);
    splitter->addWidget(explanation_);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 2);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(header_);
    layout->addWidget(stepHint_);
    layout->addLayout(buttons);
    layout->addWidget(splitter, 1);

    connect(whatsWrong_, &QPushButton::clicked, this, &CheckPanel::showWhatsWrong);
    connect(nextStep_, &QPushButton::clicked, this, &CheckPanel::selectNextEmpty);
    connect(save_, &QPushButton::clicked, this, &CheckPanel::saveWithDialog);
    connect(load_, &QPushButton::clicked, this, &CheckPanel::loadWithDialog);
    connect(clear_, &QPushButton::clicked, model_, &CheckModel::clearEntries);
    connect(view_->selectionModel(), &QItemSelectionModel::currentChanged, this, &CheckPanel::onCurrentChanged);
    connect(model_, &QAbstractItemModel::dataChanged, this, &CheckPanel::onCurrentChanged);
    connect(model_, &QAbstractItemModel::modelReset, this, &CheckPanel::onCurrentChanged);
    connect(model_, &QAbstractItemModel::dataChanged, this, &CheckPanel::updateStepHint);
    connect(model_, &QAbstractItemModel::modelReset, this, &CheckPanel::updateStepHint);
    connect(model_, &QAbstractItemModel::modelReset, this, [this] {
        for (int c : {int(CheckModel::QuantityColumn), int(CheckModel::OfColumn)}) {
            view_->resizeColumnToContents(c);
            view_->setColumnWidth(c, std::min(view_->columnWidth(c), c == CheckModel::QuantityColumn ? 160 : 90));
        }
    });
    view_->installEventFilter(this);
    updateHeader();
    onCurrentChanged();
}

bool CheckPanel::eventFilter(QObject* watched, QEvent* event)
{
    // A window shortcut is looked up before the key reaches the focused widget; the
    // cell's editor (a QLineEdit) claims printable keys itself, but the key that opens
    // the editor (AnyKeyPressed) reaches the table first and would be the shortcut.
    if (watched == view_ && event->type() == QEvent::ShortcutOverride) {
        const auto* key = static_cast<QKeyEvent*>(event);
        const bool printable = !key->text().isEmpty() && key->text().at(0).isPrint() &&
                               !(key->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier));
        const QModelIndex current = view_->currentIndex();
        if (printable && current.isValid() && (current.flags() & Qt::ItemIsEditable)) {
            event->accept();
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

void CheckPanel::setStep(const QString& lesson, std::unique_ptr<World> before, const StepTrace* trace,
                         const SceneDef& scene)
{
    model_->setStep(lesson, std::move(before), trace, scene);
    explanation_->clear();
    updateHeader();
}

void CheckPanel::updateHeader()
{
    const bool has = model_->hasStep();
    // The step's name as every screen words it (app/core/step_numbering.h).
    header_->setText(has ? tr("<b>%1</b>: type your numbers into <b>Yours</b>, e.g. <tt>(-2.4, 4.918, -1.765)</tt>, "
                              "<tt>64/27</tt> or a matrix row by row <tt>4.8 0 0; 0 9.836 0; 0 0 4.412</tt>. "
                              "The rows above an entry are its earlier answers.")
                               .arg(steps::stepSpan(model_->step()))
                         : tr("Take a step (Step) to check your numbers for it."));
    save_->setEnabled(has);
    load_->setEnabled(has);
    clear_->setEnabled(has);
    nextStep_->setEnabled(has);
}

void CheckPanel::updateStepHint()
{
    const QString hint = model_->stepHint();
    stepHint_->setText(hint.isEmpty() ? QString() : tr("<b>Hint:</b> %1").arg(hint.toHtmlEscaped()));
    stepHint_->setVisible(!hint.isEmpty());
}

QString CheckPanel::stepHintText() const
{
    return model_->stepHint().isEmpty() ? QString() : stepHint_->text();
}

void CheckPanel::onCurrentChanged()
{
    const int row = view_->currentIndex().row();
    const auto state = model_->rowState(row);
    whatsWrong_->setEnabled(state == CheckModel::RowState::Wrong || state == CheckModel::RowState::FollowsFromEarlier ||
                            state == CheckModel::RowState::Unreadable);
}

QString CheckPanel::explanationHtml() const
{
    return explanation_->toHtml();
}

void CheckPanel::showWhatsWrong()
{
    const int row = view_->currentIndex().row();
    const QString html = model_->explanationHtml(row);
    explanation_->setHtml(html.isEmpty() ? tr("Select an entry you have filled in.") : html);
}

bool CheckPanel::selectNextEmpty()
{
    const int row = model_->firstEmptyRow();
    if (row < 0) {
        explanation_->setHtml(tr("Every quantity of this step is filled in."));
        return false;
    }
    const QModelIndex idx = model_->index(row, CheckModel::YoursColumn);
    view_->setCurrentIndex(idx);
    view_->scrollTo(idx);
    view_->setFocus();
    return true;
}

bool CheckPanel::saveAnswers(const QString& path, QString* error)
{
    return writeFileAtomically(path, model_->answersJson(), error);
}

bool CheckPanel::loadAnswers(const QString& path, QString* error)
{
    QByteArray bytes;
    QString readError;
    if (!readInputFile(path, &bytes, &readError)) {   // the limit rbw check reads, too
        if (error) *error = readError;
        return false;
    }
    long step = 0;
    if (!model_->loadAnswersJson(bytes, QFileInfo(path).fileName(), error, &step)) return false;
    if (step != model_->step()) {
        explanation_->setHtml(tr("The file holds the answers of step %1; they show when you are at that step "
                                 "(this is step %2).")
                                  .arg(step)
                                  .arg(model_->step()));
    }
    return true;
}

void CheckPanel::saveWithDialog()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Save answers"),
                                                      QStringLiteral("%1-step%2-answers.json").arg(model_->lesson()).arg(model_->step()),
                                                      tr("Answers (*.json)"));
    if (path.isEmpty()) return;
    QString error;
    if (!saveAnswers(path, &error)) QMessageBox::warning(this, tr("Save answers"), error);
}

void CheckPanel::loadWithDialog()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Load answers"), QString(), tr("Answers (*.json)"));
    if (path.isEmpty()) return;
    QString error;
    if (!loadAnswers(path, &error)) QMessageBox::warning(this, tr("Load answers"), error);
}

} // namespace rbw
