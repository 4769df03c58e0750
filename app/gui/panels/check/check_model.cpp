#include "app/gui/panels/check/check_model.h"

#include "app/exercise/answers_file.h"
#include "app/exercise/answers_input.h"
#include "app/output/value_format.h"
#include "physics/workbook/checker/mistakes.h"

#include <QBrush>
#include <QColor>
#include <QFont>
#include <QStringList>

#include <algorithm>
#include <set>
#include <variant>

namespace rbw {

namespace {

// rbw check's default --tolerance: the panel's verdicts and hints are the command's.
constexpr double kCheckTolerance = 1e-3;

int valueCount(const TraceValue& v)
{
    if (std::holds_alternative<double>(v)) return 1;
    if (std::holds_alternative<Vec3>(v)) return 3;
    if (std::holds_alternative<Quat>(v)) return 4;
    return 9;
}

// Pale enough for black text; the Mark column repeats the verdict in words.
QColor stateColour(CheckModel::RowState s)
{
    switch (s) {
    case CheckModel::RowState::Correct: return QColor(0xc6, 0xef, 0xce);
    case CheckModel::RowState::Wrong: return QColor(0xf8, 0xc4, 0xc4);
    case CheckModel::RowState::FollowsFromEarlier: return QColor(0xff, 0xe2, 0x9a);
    case CheckModel::RowState::Unreadable: return QColor(0xe4, 0xe4, 0xe4);
    default: return {};
    }
}

QString verdictWords(CheckModel::RowState s)
{
    switch (s) {
    case CheckModel::RowState::Correct: return QStringLiteral("right");
    case CheckModel::RowState::Wrong: return QStringLiteral("wrong");
    case CheckModel::RowState::FollowsFromEarlier: return QStringLiteral("follows from an earlier error");
    default: return {};
    }
}

} // namespace

CheckModel::CheckModel(QObject* parent) : QAbstractTableModel(parent) {}
CheckModel::~CheckModel() = default;

QString CheckModel::rowKey(const Answer& a)
{
    return QStringLiteral("%1|%2|%3|%4").arg(QString::fromStdString(a.quantity)).arg(a.body).arg(a.contact).arg(a.index);
}

void CheckModel::setStep(const QString& lesson, std::unique_ptr<World> before, const StepTrace* trace,
                         const SceneDef& scene)
{
    beginResetModel();
    lesson_ = lesson;
    scene_ = scene;
    if (trace != nullptr && before != nullptr) {
        before_ = std::move(before);
        trace_ = *trace;
    } else {
        before_.reset();
        trace_ = StepTrace{};
    }
    earlier_.reset();
    rebuildRows();
    recheck();
    endResetModel();
}

void CheckModel::clear()
{
    beginResetModel();
    before_.reset();
    trace_ = StepTrace{};
    rows_.clear();
    stepHint_.clear();
    earlier_.reset();
    endResetModel();
}

void CheckModel::rebuildRows()
{
    rows_.clear();
    if (before_ == nullptr) return;
    std::set<QString> seen;
    for (const TraceEntry& e : trace_.entries) {
        Row r;
        r.answer.quantity = e.info->id;
        if (e.info->indexKind == IndexKind::Contact) {
            r.answer.contact = e.index;
        } else {
            r.answer.body = e.body;
            r.answer.index = e.index;
        }
        r.count = valueCount(e.value);
        // Only what the checker can take (the first entry of a quantity, as it reads it).
        Answer probe = r.answer;
        probe.value.assign(static_cast<size_t>(r.count), 0.0);
        if (!answerProblem(trace_, probe).empty()) continue;
        r.key = rowKey(r.answer);
        if (!seen.insert(r.key).second) continue;
        r.entry = &e;
        if (r.answer.contact >= 0) {
            r.of = tr("contact %1").arg(r.answer.contact);
        } else {
            if (e.body >= 0 && e.body < static_cast<int>(scene_.bodies.size())) {
                r.of = QString::fromStdString(scene_.bodies[e.body].name);
            }
            if (e.index >= 0) {
                const QString which = QStringLiteral("%1 %2").arg(QString::fromUtf8(indexKindName(e.info->indexKind))).arg(e.index);
                r.of = r.of.isEmpty() ? which : r.of + QStringLiteral(", ") + which;
            }
        }
        rows_.push_back(std::move(r));
    }
}

void CheckModel::recheck()
{
    std::vector<Answer> answers;
    std::vector<int> rowOfAnswer;
    stepHint_.clear();
    for (int i = 0; i < static_cast<int>(rows_.size()); ++i) {
        Row& r = rows_[static_cast<size_t>(i)];
        const QString text = store_.text(lesson_, trace_.step, r.key);
        r.result = AnswerResult{};
        r.hint.clear();
        if (text.trimmed().isEmpty()) {
            r.parsed = ParsedAnswer{};
            r.state = RowState::Empty;
            continue;
        }
        r.parsed = parseAnswerText(text, r.count);
        if (!r.parsed.ok()) {
            r.state = RowState::Unreadable;
            continue;
        }
        Answer a = r.answer;
        a.value = r.parsed.values;
        answers.push_back(std::move(a));
        rowOfAnswer.push_back(i);
        r.state = RowState::NotChecked;
    }
    if (answers.empty() || before_ == nullptr) return;
    // All entries together, in table order: the rows above are the earlier answers.
    const std::vector<AnswerResult> results = checkAnswers(*before_, trace_, answers, kCheckTolerance);
    for (size_t k = 0; k < results.size(); ++k) {
        Row& r = rows_[static_cast<size_t>(rowOfAnswer[k])];
        r.result = results[k];
        r.hint = slipHint(answers[k], results[k], kCheckTolerance);
        switch (results[k].verdict) {
        case Verdict::Correct:
        case Verdict::Imprecise: r.state = RowState::Correct; break;
        case Verdict::Wrong: r.state = RowState::Wrong; break;
        case Verdict::FollowsFromEarlier: r.state = RowState::FollowsFromEarlier; break;
        }
    }
    // Steps counted from 1: the same test as rbw check's, on step k - 1 simulated once.
    const bool allRight = std::all_of(results.begin(), results.end(), [](const AnswerResult& r) { return countsAsCorrect(r.verdict); });
    if (!allRight && trace_.step > 0 && trace_.step <= kStepHintLimit) {
        if (earlier_ == nullptr) {
            earlier_ = std::make_unique<StepStates>(scene_);
            QString blowUp;
            earlier_->prepare({trace_.step - 1}, &blowUp);
        }
        stepHint_ = stepSlipHint(answers, results, trace_.step, *earlier_, kCheckTolerance);
    }
}

QString CheckModel::rowHint(int row) const
{
    if (row < 0 || row >= static_cast<int>(rows_.size())) return {};
    return rows_[static_cast<size_t>(row)].hint;
}

int CheckModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(rows_.size());
}

int CheckModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant CheckModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || index.row() >= static_cast<int>(rows_.size())) return {};
    const Row& r = rows_[static_cast<size_t>(index.row())];
    switch (role) {
    case IdRole: return QString::fromStdString(r.answer.quantity);
    case KeyRole: return r.key;
    case StateRole: return static_cast<int>(r.state);
    case MistakesRole: {
        QStringList ids;
        for (const char* id : r.result.mistakes) ids << QString::fromUtf8(id);
        for (const PossibleMistake& p : r.result.possibleMistakes) ids << QString::fromUtf8(p.id);
        return ids;
    }
    default: break;
    }
    const int col = index.column();
    if (role == Qt::DisplayRole || role == Qt::EditRole) {
        switch (col) {
        case QuantityColumn:
            return QStringLiteral("%1  %2").arg(QString::fromUtf8(r.entry->info->text), QString::fromStdString(r.answer.quantity));
        case OfColumn: return r.of;
        case YoursColumn: return store_.text(lesson_, trace_.step, r.key);
        case MarkColumn:
            switch (r.state) {
            case RowState::Empty: return QString();
            case RowState::Unreadable: return QStringLiteral("? %1").arg(r.parsed.error);
            case RowState::Correct: return QStringLiteral("✓ right");
            case RowState::Wrong: return r.hint.isEmpty() ? QStringLiteral("✗ wrong") : QStringLiteral("✗ wrong (hint)");
            case RowState::FollowsFromEarlier: return QStringLiteral("↪ follows");
            case RowState::NotChecked: return QString();
            }
            return QString();
        case UnitColumn: return QString::fromUtf8(r.entry->info->unit);
        default: return {};
        }
    }
    if (role == Qt::BackgroundRole && (col == YoursColumn || col == MarkColumn)) {
        const QColor c = stateColour(r.state);
        return c.isValid() ? QVariant(QBrush(c)) : QVariant();
    }
    if (role == Qt::ForegroundRole && (col == YoursColumn || col == MarkColumn) && r.state != RowState::Empty) {
        return QBrush(Qt::black);
    }
    if (role == Qt::FontRole && col == MarkColumn && r.state != RowState::Empty) {
        QFont f;
        f.setBold(true);
        return f;
    }
    if (role == Qt::ToolTipRole) {
        if (col == YoursColumn && r.state != RowState::Empty) return store_.text(lesson_, trace_.step, r.key);
        if (col == OfColumn) return r.of;
        if (col == YoursColumn) {
            return tr("Type %1: e.g. %2").arg(r.count == 1 ? tr("a number") : r.count == 3 ? tr("a vector") : r.count == 4 ? tr("a quaternion [w x y z]") : tr("a matrix, row by row"),
                                              r.count == 1 ? QStringLiteral("64/27") : r.count == 3 ? QStringLiteral("(-2.4, 4.918, -1.765)") : r.count == 4 ? QStringLiteral("[1 0 0 0]") : QStringLiteral("4.8 0 0; 0 9.836 0; 0 0 4.412"));
        }
        if (col == MarkColumn && r.state == RowState::Unreadable) return r.parsed.error;
        if (col == MarkColumn && !r.hint.isEmpty()) return tr("%1; hint: %2").arg(verdictWords(r.state), r.hint);
        if (col == MarkColumn && !verdictWords(r.state).isEmpty()) return verdictWords(r.state);
        if (col == QuantityColumn) {
            return QStringLiteral("%1  %2").arg(QString::fromUtf8(r.entry->info->text), QString::fromStdString(r.answer.quantity));
        }
    }
    return {};
}

bool CheckModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    if (role != Qt::EditRole || !index.isValid() || index.column() != YoursColumn) return false;
    return setAnswerText(index.row(), value.toString());
}

bool CheckModel::setAnswerText(int row, const QString& text)
{
    if (row < 0 || row >= static_cast<int>(rows_.size())) return false;
    store_.setText(lesson_, trace_.step, rows_[static_cast<size_t>(row)].key, text.trimmed());
    recheck();
    // One entry can change the verdict of every later one (follows from earlier).
    emit dataChanged(this->index(0, 0), this->index(rowCount() - 1, ColumnCount - 1));
    return true;
}

Qt::ItemFlags CheckModel::flags(const QModelIndex& index) const
{
    if (!index.isValid()) return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (index.column() == YoursColumn) f |= Qt::ItemIsEditable;
    return f;
}

QVariant CheckModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
    case QuantityColumn: return tr("Quantity");
    case OfColumn: return tr("Of");
    case YoursColumn: return tr("Yours");
    case MarkColumn: return tr("Mark");
    case UnitColumn: return tr("Unit");
    default: return {};
    }
}

int CheckModel::rowOf(const QString& id, int body, int contact, int index) const
{
    Answer a;
    a.quantity = id.toStdString();
    a.body = contact >= 0 ? -1 : body;
    a.contact = contact;
    a.index = contact >= 0 ? -1 : index;
    const QString key = rowKey(a);
    for (int i = 0; i < static_cast<int>(rows_.size()); ++i) {
        if (rows_[static_cast<size_t>(i)].key == key) return i;
    }
    return -1;
}

CheckModel::RowState CheckModel::rowState(int row) const
{
    if (row < 0 || row >= static_cast<int>(rows_.size())) return RowState::Empty;
    return rows_[static_cast<size_t>(row)].state;
}

int CheckModel::firstEmptyRow() const
{
    for (int i = 0; i < static_cast<int>(rows_.size()); ++i) {
        if (rows_[static_cast<size_t>(i)].state == RowState::Empty) return i;
    }
    return -1;
}

QString CheckModel::explanationHtml(int row) const
{
    if (row < 0 || row >= static_cast<int>(rows_.size())) return {};
    const Row& r = rows_[static_cast<size_t>(row)];
    const QString what = QStringLiteral("<b>%1</b> %2").arg(QString::fromUtf8(r.entry->info->text).toHtmlEscaped(),
                                                           (QString::fromStdString(r.answer.quantity) + (r.of.isEmpty() ? QString() : QStringLiteral(" (") + r.of + QLatin1Char(')'))).toHtmlEscaped());
    switch (r.state) {
    case RowState::Empty: return {};
    case RowState::NotChecked: return what;
    case RowState::Unreadable:
        return tr("%1: your entry cannot be read: %2.").arg(what, r.parsed.error.toHtmlEscaped());
    case RowState::Correct:
        return r.result.verdict == Verdict::Imprecise
                   ? tr("%1 is right (✓). %2").arg(what, QString::fromStdString(r.result.explanation).toHtmlEscaped())
                   : tr("%1 is right (✓).").arg(what);
    default: break;
    }
    QString html = tr("%1 is %2 (%3).").arg(what, verdictWords(r.state), r.state == RowState::Wrong ? QStringLiteral("✗") : QStringLiteral("↪"));
    if (!r.result.explanation.empty()) {
        html += QStringLiteral("<p>%1</p>").arg(QString::fromStdString(r.result.explanation).toHtmlEscaped());
    }
    for (const QString& hint : {r.hint, stepHint_}) {
        if (!hint.isEmpty()) html += tr("<p><b>Hint:</b> %1</p>").arg(hint.toHtmlEscaped());
    }
    if (!r.result.mistakes.empty()) {
        html += QStringLiteral("<p>%1</p><ul>").arg(r.result.mistakes.size() == 1 ? tr("It matches this mistake:") : tr("It matches these mistakes:"));
        for (const char* id : r.result.mistakes) {
            const MistakeInfo* m = findMistake(id);
            // The checker's explanation above is usually this mistake's: not twice.
            const QString why = m && r.result.explanation != m->explanation ? QString::fromUtf8(m->explanation) : QString();
            html += QStringLiteral("<li><code>%1</code>: <i>%2</i>%3</li>")
                        .arg(QString::fromUtf8(id).toHtmlEscaped(),
                             m ? QString::fromUtf8(m->equation).toHtmlEscaped() : QString(),
                             why.isEmpty() ? QString() : QStringLiteral("<br>") + why.toHtmlEscaped());
        }
        html += QStringLiteral("</ul>");
    } else if (!r.result.possibleMistakes.empty()) {
        html += QStringLiteral("<p>%1</p><ul>").arg(tr("It may be:"));
        for (const PossibleMistake& p : r.result.possibleMistakes) {
            const MistakeInfo* m = findMistake(p.id);
            html += QStringLiteral("<li><code>%1</code>: <i>%2</i> (%3)</li>")
                        .arg(QString::fromUtf8(p.id).toHtmlEscaped(), m ? QString::fromUtf8(m->equation).toHtmlEscaped() : QString(),
                             QString::fromStdString(p.reason).toHtmlEscaped());
        }
        html += QStringLiteral("</ul>");
    } else if (r.state == RowState::Wrong) {
        html += tr("<p>No known mistake gives this number.</p>");
    }
    html += tr("<p>The workbook's number: <b>%1</b> %2</p>").arg(formatValue(r.entry->value, 7).toHtmlEscaped(),
                                                                  QString::fromUtf8(r.entry->info->unit).toHtmlEscaped());
    return html;
}

QByteArray CheckModel::answersJson() const
{
    std::vector<Answer> answers;
    for (const Row& r : rows_) {
        if (r.state == RowState::Empty || r.state == RowState::Unreadable) continue;
        Answer a = r.answer;
        a.value = r.parsed.values;
        answers.push_back(std::move(a));
    }
    return answersToJson(answers, trace_.step, scene_);
}

bool CheckModel::loadAnswersJson(const QByteArray& json, const QString& label, QString* error, long* fileStep)
{
    // What rbw check refuses, refused here with the same message (one code path:
    // app/exercise/answers_input.h).
    const AnswersInput in = readAnswersInput(json, label, scene_);
    QStringList problems = in.errors;
    if (problems.isEmpty()) {
        if (in.step == trace_.step) {
            problems = answersProblems(in, trace_, scene_, label);
        } else {
            StepStates states(scene_);
            QString blowUp;
            if (!states.prepare({in.step}, &blowUp)) problems << QStringLiteral("%1: step %2: %3").arg(label).arg(in.step).arg(blowUp);
            else problems = answersProblems(in, states.trace(in.step), scene_, label);
        }
    }
    if (!problems.isEmpty()) {
        if (error) *error = problems.join(QLatin1Char('\n'));
        return false;
    }
    const AnswersFile& file = in.file;
    const long step = in.step;
    if (fileStep) *fileStep = step;
    for (const Answer& a : file.answers) {
        Answer key = a;
        key.value.clear();
        store_.setText(lesson_, step, rowKey(key), answerText(a.value));
    }
    if (step == trace_.step && before_ != nullptr) {
        recheck();
        if (!rows_.empty()) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
    }
    return true;
}

void CheckModel::clearEntries()
{
    store_.clearStep(lesson_, trace_.step);
    recheck();
    if (!rows_.empty()) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
}

} // namespace rbw
