#include "app/gui/panels/quantities/student_column.h"

#include "app/core/step_numbering.h"
#include "app/gui/panels/quantities/trace_model.h"
#include "physics/engine/quantities.h"

#include <QBrush>
#include <QFont>

#include <QObject>
#include <QStringList>

#include <string_view>

namespace rbw {

namespace {

// The quantities a `state` line answers, by their catalogue entries (x, v, ω, r).
bool isStateQuantity(std::string_view id)
{
    for (const QuantityInfo* info : {&q::position, &q::linear_velocity, &q::angular_velocity, &q::orientation}) {
        if (id == info->id) return true;
    }
    return false;
}

QString numbers(const std::vector<double>& values)
{
    QStringList parts;
    for (double v : values) parts << QString::number(v, 'g', 9);
    return QLatin1Char('(') + parts.join(QStringLiteral(", ")) + QLatin1Char(')');
}

} // namespace

const StudentValue* StudentColumn::find(const StepTrace& trace, bool startOnly, int entry) const
{
    if (values_.empty() || entry < 0 || entry >= static_cast<int>(trace.entries.size())) return nullptr;
    const TraceEntry& e = trace.entries[static_cast<size_t>(entry)];
    const std::string_view id = e.info->id;
    if (e.body < 0 || !isStateQuantity(id)) return nullptr;
    // Only the row with the state after the step: the last entry of its id and body.
    for (size_t k = static_cast<size_t>(entry) + 1; k < trace.entries.size(); ++k) {
        if (trace.entries[k].body == e.body && std::string_view(trace.entries[k].info->id) == id) return nullptr;
    }
    const long n = startOnly ? trace.step : trace.step + 1;
    for (const StudentValue& v : values_) {
        if (v.step == n && v.body == e.body && v.quantityId == id) return &v;
    }
    return nullptr;
}

TraceValue StudentColumn::valueOf(const StudentValue& v)
{
    const std::vector<double>& g = v.given;
    if (g.size() == 4) return Quat(g[0], g[1], g[2], g[3]);   // w, x, y, z
    if (g.size() == 3) return Vec3(g[0], g[1], g[2]);
    return 0.0;
}

QString StudentColumn::toolTip(const StudentValue& v, const QString& symbol)
{
    QString tip = QObject::tr("Yours (%1, body %2, %3): %4\nThe workbook's: %5\n")
                      .arg(symbol)
                      .arg(v.body)
                      .arg(steps::stateName(v.step), numbers(v.given), numbers(v.expected));
    if (v.differs) {
        tip += QObject::tr("Differs: the largest difference is %1, more than the %2 allowed")
                   .arg(v.largest, 0, 'g', 4)
                   .arg(v.tolerance, 0, 'g', 3);
    } else {
        tip += QObject::tr("Agrees: the largest difference is %1 (at most %2 allowed)")
                   .arg(v.largest, 0, 'g', 4)
                   .arg(v.tolerance, 0, 'g', 3);
    }
    return tip;
}

// The TraceModel's side of the column.

void TraceModel::setStudentValues(std::vector<StudentValue> values, const QString& source)
{
    beginResetModel();   // the view shows the column and fits it
    student_.set(std::move(values), source);
    endResetModel();
}

void TraceModel::clearStudentValues()
{
    if (student_.isEmpty()) return;
    beginResetModel();
    student_.clear();
    endResetModel();
}

QVariant TraceModel::studentData(int entry, int role) const
{
    const StudentValue* v = student_.find(trace_, startOnly_, entry);
    if (v == nullptr) return {};
    switch (role) {
    case Qt::DisplayRole: return cellText(StudentColumn::valueOf(*v));
    case Qt::ToolTipRole: return StudentColumn::toolTip(*v, QString::fromUtf8(trace_.entries[entry].info->text));
    case Qt::BackgroundRole: return QBrush(v->differs ? StudentColumn::differColour() : StudentColumn::agreeColour());
    case Qt::ForegroundRole: return QBrush(Qt::black);
    case Qt::FontRole: return QFont(QStringLiteral("monospace"));
    case Qt::TextAlignmentRole: return QVariant(Qt::AlignLeft | Qt::AlignTop);
    case IdRole: return QString::fromLatin1(trace_.entries[entry].info->id);
    }
    return {};
}

} // namespace rbw
