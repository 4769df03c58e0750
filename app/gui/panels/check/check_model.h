// "Check my numbers": a table of the quantities of one step (body quantities, probes,
// contact fields, in the trace's order) with an editable "Yours" cell. Every filled
// entry is read (answer_parser.h) and all of them are handed to the checker together,
// in table order, so the rows above an entry are its "earlier answers"; the verdict
// colours the entry (green right, red wrong, amber following from an earlier error)
// and the Mark column says it in words and a sign as well, for readers who do not
// tell the colours apart. The model never computes a physical number: the expected
// values, verdicts and mistakes are the checker's (physics/workbook/checker/checker.h).
// The texts live in an AnswersStore, per lesson and step.
#pragma once

#include "app/exercise/answer_parser.h"
#include "app/exercise/answers_input.h"
#include "app/exercise/answers_store.h"
#include "physics/workbook/checker/checker.h"
#include "physics/engine/scene.h"
#include "physics/engine/trace.h"
#include "physics/engine/world.h"

#include <QAbstractTableModel>
#include <QString>

#include <memory>
#include <vector>

namespace rbw {

class CheckModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { QuantityColumn, OfColumn, YoursColumn, MarkColumn, UnitColumn, ColumnCount };
    enum Role {
        IdRole = Qt::UserRole + 1,   // the quantity's trace id
        KeyRole,                     // the row's key (rowKey)
        StateRole,                   // a RowState as int
        MistakesRole,                // QStringList of mistake ids (a wrong entry)
    };
    enum class RowState { Empty, Unreadable, Correct, Wrong, FollowsFromEarlier, NotChecked };

    explicit CheckModel(QObject* parent = nullptr);
    ~CheckModel() override;

    // Shows this step: `before` is the world at its start (nullptr, with a null trace,
    // at step 0: the table is empty then). The entries come back from the store.
    void setStep(const QString& lesson, std::unique_ptr<World> before, const StepTrace* trace, const SceneDef& scene);
    void clear();
    QString lesson() const { return lesson_; }
    long step() const { return trace_.step; }
    bool hasStep() const { return before_ != nullptr; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    // The row of a quantity: id, body (-1 none), contact (-1 none), index (-1 none); -1 if absent.
    int rowOf(const QString& id, int body, int contact = -1, int index = -1) const;
    // Types into a row's "Yours" cell (as the editor does).
    bool setAnswerText(int row, const QString& text);
    RowState rowState(int row) const;
    // The first row with nothing written, or -1.
    int firstEmptyRow() const;
    // What went wrong with a row, as HTML: the verdict, the checker's explanation, the
    // matching mistakes (id, the wrong equation, findMistake's explanation) and the
    // workbook's number. Empty for an empty row.
    QString explanationHtml(int row) const;

    // The input slips the entries show, as `rbw check` names them (answers_input.h: one
    // code path): a row's quaternion written [x, y, z, w] (slipHint), and the whole
    // step's "steps count from 0: did you mean step k - 1?" (stepSlipHint, for steps up
    // to kStepHintLimit: it simulates the scene to step k - 1 once per step). Empty: none.
    QString rowHint(int row) const;
    QString stepHint() const { return stepHint_; }
    static constexpr long kStepHintLimit = 2000;

    // The filled, readable entries as an answers file (answers_file.h).
    QByteArray answersJson() const;
    // Reads an answers file into the store (for its step, this lesson) and shows it if it
    // is the current step. False with `error` for a file that cannot be read.
    bool loadAnswersJson(const QByteArray& json, const QString& label, QString* error, long* fileStep = nullptr);
    // Drops this step's entries.
    void clearEntries();

private:
    struct Row {
        Answer answer;              // without value: which quantity
        const TraceEntry* entry = nullptr;
        QString key;
        QString of;                 // "standard", "contact 0", "standard, probe 1"
        int count = 1;              // numbers expected
        ParsedAnswer parsed;
        RowState state = RowState::Empty;
        AnswerResult result;
        QString hint;               // slipHint of the checked entry
    };
    static QString rowKey(const Answer& a);
    void rebuildRows();
    void recheck();

    AnswersStore store_;
    QString lesson_;
    std::unique_ptr<World> before_;
    StepTrace trace_;
    SceneDef scene_;
    std::vector<Row> rows_;
    QString stepHint_;
    std::unique_ptr<StepStates> earlier_;   // step k - 1, simulated once for stepHint_
};

} // namespace rbw
