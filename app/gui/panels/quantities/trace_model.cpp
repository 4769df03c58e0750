#include "app/gui/panels/quantities/trace_model.h"

#include "app/core/step_numbering.h"
#include "app/output/value_format.h"
#include "physics/engine/quantities.h"
#include "physics/engine/world.h"

#include <QBrush>
#include <QColor>
#include <QFont>
#include <QFontMetrics>
#include <QRegularExpression>
#include <QStringList>

#include <algorithm>
#include <cmath>

namespace rbw {

namespace {

// The catalogue's display name (quantity_catalogue.h), with which force, torque or
// probe it is; inside a contact's group the index is the group itself.
QString humanName(const TraceEntry& e)
{
    QString name = QString::fromUtf8(e.info->name);
    if (e.info->stage == Stage::Collision || e.index < 0) return name;
    name += e.info->stage == Stage::Probes ? QStringLiteral(" (probe %1)").arg(e.index) : QStringLiteral(" #%1").arg(e.index);
    return name;
}

// The stages of the trace (trace.h's Stage, in its order).
constexpr int kStageCount = static_cast<int>(Stage::Probes) + 1;

QString stageTitle(Stage s)
{
    switch (s) {
    case Stage::Forces: return QObject::tr("Forces");
    case Stage::Integration: return QObject::tr("Integration");
    case Stage::Collision: return QObject::tr("Collisions");
    case Stage::Correction: return QObject::tr("Position correction");
    case Stage::Probes: return QObject::tr("Probe points");
    }
    return {};
}

bool sameValue(const TraceValue& a, const TraceValue& b)
{
    if (a.index() != b.index()) return false;
    return std::visit(
        [&](const auto& x) {
            using T = std::decay_t<decltype(x)>;
            const T& y = std::get<T>(b);
            if constexpr (std::is_same_v<T, double>) return x == y;
            else if constexpr (std::is_same_v<T, Quat>) return x.coeffs() == y.coeffs();
            else return x == y;
        },
        a);
}

} // namespace

// A matrix as three lines with its columns aligned (in the proportional font: two
// matrices side by side in a monospace font need 600 px at 1366x768). The entries are
// rounded to the same decimals, `digits` significant ones for the largest entry (R:
// 0.9925, and 0.0048 not 0.004819), as a printed matrix does, then lose their trailing
// zeros (1, not 1.000000; issue 20); an entry that rounds to zero is "0". Each column is
// aligned on its decimal point. A matrix of very large or very small entries keeps 'g'
// with `digits` digits. The tooltip has every digit (formatValue).
QString matrixLines(const Mat3& m, int digits)
{
    const double scale = m.cwiseAbs().maxCoeff();
    const bool fixed = scale >= 1e-4 && scale < 1e6;
    const int decimals = fixed ? std::clamp(digits - 1 - static_cast<int>(std::floor(std::log10(scale))), 0, 9) : 0;
    QString whole[3][3];
    QString fraction[3][3];   // with its '.', or empty
    int wholeWidth[3] = {0, 0, 0};
    int fractionWidth[3] = {0, 0, 0};
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
            const double x = std::abs(m(r, c)) < 1e-12 * scale ? 0.0 : m(r, c);
            QString text = fixed ? QString::number(x, 'f', decimals) : formatNumber(x, digits);
            if (fixed && text.contains('.')) {
                while (text.endsWith('0')) text.chop(1);
                if (text.endsWith('.')) text.chop(1);
            }
            if (fixed && (text == QLatin1String("-0") || text.isEmpty())) text = QStringLiteral("0");
            const qsizetype dot = fixed ? text.indexOf('.') : -1;
            whole[r][c] = dot < 0 ? text : text.left(dot);
            fraction[r][c] = dot < 0 ? QString() : text.mid(dot);
            wholeWidth[c] = std::max(wholeWidth[c], static_cast<int>(whole[r][c].size()));
            fractionWidth[c] = std::max(fractionWidth[c], static_cast<int>(fraction[r][c].size()));
        }
    }
    QStringList rows;
    for (int r = 0; r < 3; ++r) {
        QStringList row;
        // Padded with figure spaces (U+2007, a digit's width in the proportional font
        // the cell uses) and a punctuation space (U+2008, a point's width) for a
        // missing point, so the points line up.
        for (int c = 0; c < 3; ++c) {
            QString cell = whole[r][c].rightJustified(wholeWidth[c], QChar(0x2007));
            if (fractionWidth[c] > 0) {
                const QString& f = fraction[r][c];
                cell += f.isEmpty() ? QString(QChar(0x2008)) + QString(fractionWidth[c] - 1, QChar(0x2007))
                                    : f + QString(fractionWidth[c] - f.size(), QChar(0x2007));
            }
            row << cell;
        }
        rows << row.join(QChar(0x2007));
    }
    // Trailing padding is not needed at the line's end.
    for (QString& line : rows) {
        while (line.endsWith(QChar(0x2007))) line.chop(1);
    }
    return rows.join('\n');
}

namespace {

bool anyImpulse(const StepTrace& trace)
{
    for (const ContactHeader& c : trace.contacts) {
        if (!c.separating) return true;
    }
    return false;
}

} // namespace

QString TraceModel::cellText(const TraceValue& value) const
{
    if (const Mat3* m = std::get_if<Mat3>(&value)) return matrixLines(*m, matrixDigits_);
    // Vectors and quaternions: all digits, unless the table is too narrow even for
    // matrices of 3 digits (then vectorDigits_; the tooltip has all of them).
    return formatValueLines(value, std::holds_alternative<double>(value) ? 7 : vectorDigits_);
}

void TraceModel::setNameWrap(int pixels, const QFont& font)
{
    nameWrapPx_ = std::max(0, pixels);
    nameFont_ = font;
}

QString TraceModel::wrappedName(const QString& name) const
{
    if (nameWrapPx_ <= 0) return name;
    const QFontMetrics fm(nameFont_);
    QStringList lines;
    QString line;
    for (const QString& word : name.split(QLatin1Char(' '))) {
        const QString longer = line.isEmpty() ? word : line + QLatin1Char(' ') + word;
        if (!line.isEmpty() && fm.horizontalAdvance(longer) > nameWrapPx_) {
            lines << line;
            line = word;
        } else {
            line = longer;
        }
    }
    if (!line.isEmpty()) lines << line;
    return lines.join(QLatin1Char('\n'));
}

void TraceModel::setMatrixDigits(int digits)
{
    digits = std::clamp(digits, 3, 7);
    if (digits == matrixDigits_) return;
    matrixDigits_ = digits;   // the same lines, only shorter: the view repaints (TraceView)
}

void TraceModel::setStart(const World& world)
{
    StepTrace start;
    start.step = world.stepIndex();
    start.time = world.time();
    start.start.bodies = world.states();
    const std::vector<BodyState>& states = world.states();
    for (int b = 0; b < static_cast<int>(states.size()); ++b) {
        const BodyState& s = states[static_cast<size_t>(b)];
        start.add(q::position, b, s.x_W);
        start.add(q::linear_velocity, b, s.v_W);
        start.add(q::orientation, b, s.q_WB);
        start.add(q::rotation_matrix, b, s.R_WB);
        start.add(q::angular_momentum, b, s.L_W);
        start.add(q::inverse_inertia_world, b, s.Iinv_W);
        start.add(q::angular_velocity, b, s.omega_W);
    }
    beginResetModel();
    trace_ = std::move(start);
    changed_.assign(trace_.entries.size(), 0);
    startOnly_ = true;
    impulseAfterIntegration_ = false;
    rebuild(world.scene());
    endResetModel();
}

TraceModel::TraceModel(QObject* parent)
    : QAbstractItemModel(parent)
{
    nodes_.push_back(Node{});
}

void TraceModel::clear()
{
    beginResetModel();
    startOnly_ = false;
    impulseAfterIntegration_ = false;
    trace_ = StepTrace{};
    changed_.clear();
    nodes_.assign(1, Node{});
    rowOfEntry_.clear();
    endResetModel();
}

bool TraceModel::sameShape(const StepTrace& next) const
{
    if (next.entries.size() != trace_.entries.size() || next.contacts.size() != trace_.contacts.size()) return false;
    for (size_t k = 0; k < next.contacts.size(); ++k) {
        const ContactHeader& a = next.contacts[k];
        const ContactHeader& b = trace_.contacts[k];
        if (a.bodyA != b.bodyA || a.bodyB != b.bodyB || a.plane != b.plane || a.separating != b.separating ||
            a.pointCount != b.pointCount || std::string_view(a.feature) != b.feature) {
            return false;
        }
    }
    for (size_t i = 0; i < next.entries.size(); ++i) {
        const TraceEntry& a = next.entries[i];
        const TraceEntry& b = trace_.entries[i];
        if (a.info != b.info || a.body != b.body || a.index != b.index) return false;
        // Another statement computed it (another integrator): the Source column changes.
        if (a.where.line() != b.where.line() || sourceFile(a) != sourceFile(b)) return false;
    }
    return true;
}

void TraceModel::setTrace(const StepTrace& trace, const SceneDef& scene)
{
    if (!startOnly_ && !trace_.entries.empty() && sameShape(trace)) {
        // Same rows: report only rows whose value or highlight changed.
        std::vector<char> touched(trace.entries.size(), 0);
        for (size_t i = 0; i < trace.entries.size(); ++i) {
            const char nowChanged = !sameValue(trace.entries[i].value, trace_.entries[i].value);
            touched[i] = nowChanged || changed_[i];
            changed_[i] = nowChanged;
        }
        const bool newStep = trace.step != trace_.step;
        trace_ = trace;
        if (newStep) emit headerDataChanged(Qt::Horizontal, BeforeColumn, ValueColumn);
        for (size_t i = 0; i < trace_.entries.size(); ++i) {
            if (!touched[i]) continue;
            const Node& n = nodes_[rowOfEntry_[i]];
            emit dataChanged(createIndex(n.row, 0, quintptr(rowOfEntry_[i])),
                             createIndex(n.row, ColumnCount - 1, quintptr(rowOfEntry_[i])));
        }
        return;
    }
    beginResetModel();
    // A new shape: a row is "changed" when the previous step had no row with the same
    // quantity, body and index, or had a different value there.
    changed_.assign(trace.entries.size(), 0);
    if (!trace_.entries.empty() && !startOnly_) {
        for (size_t i = 0; i < trace.entries.size(); ++i) {
            const TraceEntry& e = trace.entries[i];
            const TraceEntry* before = trace_.find(e.info->id, e.body, e.index);
            changed_[i] = before == nullptr || before->info->stage != e.info->stage || !sameValue(before->value, e.value);
        }
    }
    trace_ = trace;
    startOnly_ = false;
    impulseAfterIntegration_ = anyImpulse(trace_);
    rebuild(scene);
    endResetModel();
}

void TraceModel::rebuild(const SceneDef& scene)
{
    nodes_.assign(1, Node{});
    rowOfEntry_.assign(trace_.entries.size(), -1);
    auto addChild = [&](int parent, const QString& label, int entry) {
        Node n;
        n.parent = parent;
        n.row = static_cast<int>(nodes_[parent].children.size());
        n.label = label;
        n.entry = entry;
        nodes_.push_back(n);
        const int id = static_cast<int>(nodes_.size()) - 1;
        nodes_[parent].children.push_back(id);
        return id;
    };
    // Stages in pipeline order, then bodies in scene order, then entries in trace order.
    // The collision stage groups by contact instead: its world-level counts first, then
    // one group per contact ("contact 0: A ↔ B · vertex-face").
    auto bodyOrPlane = [&](int body, int plane) {
        if (plane >= 0) return QString::fromStdString(scene.planes[plane].name);
        return body >= 0 ? QString::fromStdString(scene.bodies[body].name) : QString();
    };
    // A step with a collision impulse: the collision first, it is what the step is about.
    const std::vector<Stage> order =
        impulseAfterIntegration_
            ? std::vector<Stage>{Stage::Collision, Stage::Forces, Stage::Integration, Stage::Correction, Stage::Probes}
            : std::vector<Stage>{Stage::Forces, Stage::Integration, Stage::Collision, Stage::Correction, Stage::Probes};
    auto title = [&](Stage stage) {
        if (startOnly_) {
            return tr("Start: the state at %1 = %2 s, %3")
                .arg(steps::timeName(trace_.step))
                .arg(trace_.time, 0, 'g', 6)
                .arg(steps::beforeStep(trace_.step));
        }
        if (stage == Stage::Integration && impulseAfterIntegration_) {
            return tr("Integration (After: before the collision impulse above)");
        }
        return stageTitle(stage);
    };
    // The entries bucketed once, in trace order: by contact for the collision stage, by
    // stage and body for the others (a pile's step has tens of thousands of entries and
    // hundreds of contacts and bodies; a scan per contact and per body froze the app).
    const int bodies = static_cast<int>(scene.bodies.size());
    std::vector<std::vector<int>> ofContact(trace_.contacts.size());
    std::vector<std::vector<int>> ofStageBody(static_cast<size_t>(kStageCount) * static_cast<size_t>(bodies + 1));
    auto stageBody = [&](Stage stage, int body) -> std::vector<int>& {
        return ofStageBody[static_cast<size_t>(stage) * static_cast<size_t>(bodies + 1) + static_cast<size_t>(body + 1)];
    };
    for (size_t i = 0; i < trace_.entries.size(); ++i) {
        const TraceEntry& e = trace_.entries[i];
        if (e.info->stage == Stage::Collision) {
            if (e.index >= 0 && e.index < static_cast<int>(ofContact.size())) ofContact[e.index].push_back(static_cast<int>(i));
        } else if (e.body >= -1 && e.body < bodies) {
            stageBody(e.info->stage, e.body).push_back(static_cast<int>(i));
        }
    }
    for (Stage stage : order) {
        int stageNode = -1;
        if (stage == Stage::Collision) {
            for (size_t i = 0; i < trace_.entries.size(); ++i) {
                const TraceEntry& e = trace_.entries[i];
                if (e.info->stage != Stage::Collision || e.index >= 0) continue;
                if (stageNode < 0) stageNode = addChild(0, title(stage), -1);
                rowOfEntry_[i] = addChild(stageNode, QString(), static_cast<int>(i));
            }
            // Contacts grouped by pair: a pair with several contacts (the corners of a
            // box on a plane, the points of a manifold) gets a node of its own, with
            // one node per point under it.
            auto samePair = [](const ContactHeader& a, const ContactHeader& b) {
                return a.bodyA == b.bodyA && a.bodyB == b.bodyB && a.plane == b.plane;
            };
            int pairNode = -1;
            for (int k = 0; k < static_cast<int>(trace_.contacts.size()); ++k) {
                const ContactHeader& c = trace_.contacts[k];
                if (stageNode < 0) stageNode = addChild(0, title(stage), -1);
                const bool newPair = k == 0 || !samePair(c, trace_.contacts[k - 1]);
                int points = 1;
                while (k + points < static_cast<int>(trace_.contacts.size()) &&
                       samePair(c, trace_.contacts[k + points])) {
                    ++points;
                }
                const QString pair = QStringLiteral("%1 ↔ %2").arg(bodyOrPlane(c.bodyA, -1), bodyOrPlane(c.bodyB, c.plane));
                if (newPair) {
                    pairNode = points > 1 ? addChild(stageNode, tr("%1 · %2 contacts").arg(pair).arg(points), -1) : -1;
                }
                QString label = pairNode >= 0 ? tr("contact %1 · %2").arg(k).arg(QString::fromLatin1(c.feature))
                                              : tr("contact %1: %2 · %3").arg(k).arg(pair, QString::fromLatin1(c.feature));
                if (c.pointCount > 1) label += tr(" · average of %1 corners").arg(c.pointCount);
                if (c.separating) label += tr(" · separating: no impulse");
                const int contactNode = addChild(pairNode >= 0 ? pairNode : stageNode, label, -1);
                for (const int i : ofContact[static_cast<size_t>(k)]) rowOfEntry_[i] = addChild(contactNode, QString(), i);
            }
            continue;
        }
        for (int body = -1; body < bodies; ++body) {
            int bodyNode = -1;
            for (const int i : stageBody(stage, body)) {
                if (stageNode < 0) stageNode = addChild(0, title(stage), -1);
                if (bodyNode < 0) {
                    bodyNode = body < 0 ? stageNode
                                        : addChild(stageNode, QString::fromStdString(scene.bodies[body].name), -1);
                }
                rowOfEntry_[i] = addChild(bodyNode, QString(), i);
            }
        }
    }
}

QModelIndex TraceModel::index(int row, int column, const QModelIndex& parent) const
{
    const int p = parent.isValid() ? static_cast<int>(parent.internalId()) : 0;
    if (row < 0 || column < 0 || column >= ColumnCount || row >= static_cast<int>(nodes_[p].children.size())) {
        return {};
    }
    return createIndex(row, column, quintptr(nodes_[p].children[row]));
}

QModelIndex TraceModel::parent(const QModelIndex& child) const
{
    if (!child.isValid()) return {};
    const int p = nodes_[child.internalId()].parent;
    if (p <= 0) return {};
    return createIndex(nodes_[p].row, 0, quintptr(p));
}

int TraceModel::rowCount(const QModelIndex& parent) const
{
    if (parent.isValid() && parent.column() != 0) return 0;
    const int p = parent.isValid() ? static_cast<int>(parent.internalId()) : 0;
    return static_cast<int>(nodes_[p].children.size());
}

int TraceModel::columnCount(const QModelIndex&) const
{
    return ColumnCount;
}

const TraceEntry* TraceModel::entryAt(const QModelIndex& index) const
{
    if (!index.isValid()) return nullptr;
    const int e = nodes_[index.internalId()].entry;
    return e < 0 ? nullptr : &trace_.entries[e];
}

QString TraceModel::rowText(const QModelIndex& index) const
{
    const TraceEntry* e = entryAt(index);
    if (e == nullptr) return {};
    QString text = QString::fromUtf8(e->info->text) + QStringLiteral(" = ") + formatValue(e->value);
    if (*e->info->unit) text += ' ' + QString::fromUtf8(e->info->unit);
    if (e->info->frame != Frame::None) text += QStringLiteral(" [%1]").arg(frameName(e->info->frame));
    return text;
}

QVariant TraceModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid()) return {};
    const Node& n = nodes_[index.internalId()];
    if (n.entry < 0) {
        // The whole label also as a tooltip: a long one (a contact's pair, feature and
        // point) is elided where the Quantity column is capped (MainWindow).
        if ((role == Qt::DisplayRole || role == Qt::ToolTipRole) && index.column() == QuantityColumn) return n.label;
        if (role == Qt::FontRole) {
            QFont f;
            f.setBold(true);
            return f;
        }
        return {};
    }
    const TraceEntry& e = trace_.entries[n.entry];
    if (index.column() == YoursColumn) return studentData(n.entry, role);
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case QuantityColumn: return wrappedName(humanName(e));
        case SymbolColumn: return QString::fromUtf8(e.info->text);
        case BeforeColumn: {
            TraceValue before;
            if (!startValue(trace_, e.info->id, e.body, e.index, &before)) return {};
            return cellText(before);
        }
        case ValueColumn:
            if (startOnly_) return {};
            return cellText(e.value);
        case FrameColumn: return QString::fromLatin1(frameName(e.info->frame));
        case UnitColumn: return QString::fromUtf8(e.info->unit);
        case SourceColumn: {
            if (startOnly_) return {};
            // The file's name and the line; the tooltip has the path in the tree.
            const std::string_view file = sourceFile(e);
            const size_t slash = file.rfind('/');
            const std::string_view name = slash == std::string_view::npos ? file : file.substr(slash + 1);
            return QStringLiteral("%1:%2")
                .arg(QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size())))
                .arg(sourceLine(e));
        }
        case FormulaColumn: return QString::fromUtf8(e.info->formula);
        }
        return {};
    case Qt::TextAlignmentRole:
        return QVariant(Qt::AlignLeft | Qt::AlignTop);
    case Qt::ToolTipRole:
        if (startOnly_) {
            return tr("%1 at t = %2 s, the state step k = %3 starts from:\n%4")
                .arg(QString::fromUtf8(e.info->text))
                .arg(trace_.time, 0, 'g', 6)
                .arg(trace_.step)
                .arg(formatValue(e.value));
        }
        if (index.column() == SourceColumn) {
            return QString::fromStdString(sourceText(e));
        }
        if (index.column() == BeforeColumn) {
            TraceValue before;
            const QString full = startValue(trace_, e.info->id, e.body, e.index, &before) ? formatValue(before) : QString();
            return tr("%1 at the start of step %2, the value this step starts from:\n%3")
                .arg(QString::fromUtf8(e.info->text))
                .arg(trace_.step)
                .arg(full);
        }
        if (index.column() == ValueColumn) {
            QString tip = QStringLiteral("%1 = %2").arg(QString::fromUtf8(e.info->text), formatValue(e.value));
            if (e.info->stage == Stage::Integration && impulseAfterIntegration_) {
                tip += tr("\nAfter the integration, before the collision impulse of this step changes it");
            }
            return tip + tr("\n%1\nComputed in %2").arg(QString::fromUtf8(e.info->formula), QString::fromStdString(sourceText(e)));
        }
        return tr("%1\nComputed in %2").arg(QString::fromUtf8(e.info->formula), QString::fromStdString(sourceText(e)));
    case Qt::BackgroundRole:
        if (changed_[n.entry]) return QBrush(QColor(255, 244, 196));
        return {};
    case Qt::FontRole:
        if (index.column() == ValueColumn || index.column() == BeforeColumn) {
            // Numbers line up in a monospace font; a matrix is narrower in the
            // proportional one (its figure spaces keep the columns).
            if (std::holds_alternative<Mat3>(e.value)) return {};
            return QFont(QStringLiteral("monospace"));
        }
        if (index.column() == SourceColumn) return QFont(QStringLiteral("monospace"));
        return {};
    case IdRole:
        return QString::fromLatin1(e.info->id);
    case FormulaLatexRole:
        return QString::fromUtf8(e.info->formula);
    case ValueLatexRole:
        return latexValue(e.value);
    case BeforeLatexRole: {
        TraceValue before;
        if (!startValue(trace_, e.info->id, e.body, e.index, &before)) return {};
        return latexValue(before);
    }
    case NameRole:
        return humanName(e);
    case LatexRole:
        return QString::fromUtf8(e.info->symbol) + QStringLiteral(" = ") + latexValue(e.value);
    case ChangedRole:
        return bool(changed_[n.entry]);
    case SourceFileRole: {
        if (startOnly_) return QString();
        const std::string_view file = sourceFile(e);
        return QString::fromUtf8(file.data(), static_cast<qsizetype>(file.size()));
    }
    case SourceLineRole:
        return static_cast<int>(sourceLine(e));
    }
    return {};
}

QVariant TraceModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
    case QuantityColumn: return tr("Quantity");
    case SymbolColumn: return tr("Symbol");
    // A step's columns are its times, t_k and t_{k+1} (app/core/step_numbering.h).
    case BeforeColumn: return hasStep() ? tr("Before, %1").arg(steps::timeName(trace_.step)) : tr("Before");
    case ValueColumn: return hasStep() ? tr("After, %1").arg(steps::timeName(trace_.step + 1)) : tr("After");
    case FrameColumn: return tr("Frame");
    case UnitColumn: return tr("Unit");
    case SourceColumn: return tr("Source");
    case FormulaColumn: return tr("Formula (LaTeX)");
    case YoursColumn: return tr("Yours");
    }
    return {};
}

} // namespace rbw
