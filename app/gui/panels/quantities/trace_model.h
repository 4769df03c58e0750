// A tree model over one step's trace: stage -> body -> quantity rows, with columns
// quantity, symbol, before (the value at the start of the step, for the state
// quantities x, v, r, L, R, I^-1, omega and the probe points: StepTrace::start),
// after (the value the step computed), frame, unit, source (the physics statement that computed
// the value: "explicit_euler.cpp:27", with sourceText's "physics/engine/integrators/
// explicit_euler.cpp:27" as its tooltip) and formula. It only presents the trace; it
// never computes a number. When the next step has the same rows, only the values
// that changed are reported (dataChanged), and they are highlighted.
//
// Before the first step it shows the start: every body's state (x, v, q, R, L, I^-1,
// omega) in the Before column (setStart). In a step with a collision, the collision
// group comes first and the integration group says that its After is the value before
// the impulse. A matrix is three lines; matrixDigits() sets its significant digits in
// the cells (the view lowers them when the table would not fit), the tooltip always
// has all seven.
#pragma once

#include "app/gui/panels/quantities/student_column.h"
#include "physics/engine/scene.h"
#include "physics/engine/trace.h"

namespace rbw { class World; }

#include <QAbstractItemModel>
#include <QFont>

#include <algorithm>
#include <vector>

namespace rbw {

// A matrix as the cells show it: three lines, `digits` significant digits for its
// largest entry, no trailing zeros, each column aligned on its point.
QString matrixLines(const Mat3& m, int digits);

class TraceModel : public QAbstractItemModel {
    Q_OBJECT
public:
    enum Column {
        QuantityColumn,
        SymbolColumn,
        BeforeColumn,
        ValueColumn,   // "After": the value the step computed
        FrameColumn,
        UnitColumn,
        SourceColumn,
        FormulaColumn,
        YoursColumn,   // the student's own simulator's value (StudentColumn); the view hides it without one
        ColumnCount
    };
    enum Role {
        IdRole = Qt::UserRole + 1,   // the quantity's stable id, on every column of a row
        LatexRole,                   // "symbol = value" in LaTeX
        ChangedRole,                 // true when the value differs from the previous step's
        SourceFileRole,              // the computing statement's file, relative to the source tree
        SourceLineRole,              // and its line (1-based)
        FormulaLatexRole,            // the catalogue's formula, LaTeX (for the typeset formula pane)
        ValueLatexRole,              // the value the step computed, LaTeX
        BeforeLatexRole,             // the value at the start of the step, LaTeX; invalid if none
        NameRole,                    // the quantity's full name ("angular velocity of box")
    };

    explicit TraceModel(QObject* parent = nullptr);

    // Shows this trace; bodies are named from the scene. Passing an empty trace clears.
    void setTrace(const StepTrace& trace, const SceneDef& scene);
    void clear();
    // The state before the first step (or any state without a trace): each body's x, v,
    // q, R, L, I^-1 and omega as the world holds them, in the Before column.
    void setStart(const World& world);
    bool showsStart() const { return startOnly_; }
    // A step's trace is shown (not the start state, not empty): its columns are t_k, t_{k+1}.
    bool hasStep() const { return !startOnly_ && !trace_.entries.empty(); }
    const StepTrace& trace() const { return trace_; }
    // Significant digits of a matrix in the Before and After cells (3..7, default 7).
    // Emits nothing: the same three lines, only shorter; the caller (TraceView) repaints.
    void setMatrixDigits(int digits);
    int matrixDigits() const { return matrixDigits_; }
    // The same for vectors and quaternions (the view's last resort); numbers keep 7.
    void setVectorDigits(int digits) { vectorDigits_ = std::clamp(digits, 4, 7); }
    int vectorDigits() const { return vectorDigits_; }
    // The Quantity column's names broken at spaces into lines no wider than `pixels` in
    // `font` (the view sets it where whole names would push the values off screen);
    // 0: one line. A name is never elided. The view lays its rows out again.
    void setNameWrap(int pixels, const QFont& font);
    int nameWrap() const { return nameWrapPx_; }
    // The student's own numbers (Compare with my simulator → Open in the main window):
    // the Yours column shows them for the state rows of the step shown; empty: no column.
    void setStudentValues(std::vector<StudentValue> values, const QString& source);
    void clearStudentValues();
    bool hasStudentValues() const { return !student_.isEmpty(); }
    const StudentColumn& studentColumn() const { return student_; }
    // Whether this step's integration rows come before a collision impulse.
    bool integrationBeforeImpulse() const { return impulseAfterIntegration_; }

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    // The entry a row shows, or nullptr for a group row.
    const TraceEntry* entryAt(const QModelIndex& index) const;
    // "ω = (-2.4, 4.918033, -1.764706) rad/s [world]"
    QString rowText(const QModelIndex& index) const;

private:
    struct Node {
        int parent = -1;          // node index, -1 for the invisible root
        int row = 0;              // row within the parent
        QString label;            // group label
        int entry = -1;           // index into trace_.entries for a quantity row
        std::vector<int> children;
    };
    void rebuild(const SceneDef& scene);
    bool sameShape(const StepTrace& next) const;

    StepTrace trace_;
    std::vector<char> changed_;   // per entry
    std::vector<Node> nodes_;     // nodes_[0] is the root
    std::vector<int> rowOfEntry_; // node index of each entry
    bool startOnly_ = false;      // setStart: the rows are a state, not a step
    StudentColumn student_;       // the Yours column's numbers
    bool impulseAfterIntegration_ = false;
    int matrixDigits_ = 7;
    int vectorDigits_ = 7;
    int nameWrapPx_ = 0;
    QFont nameFont_;
    QString wrappedName(const QString& name) const;
    QString cellText(const TraceValue& value) const;
    QVariant studentData(int entry, int role) const;
};

} // namespace rbw
