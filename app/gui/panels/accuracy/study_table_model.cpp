#include "app/gui/panels/accuracy/study_table_model.h"

#include <QLocale>

namespace rbw {

namespace {

QString shown(const std::optional<double>& x, int digits = 3)
{
    return x ? QString::number(*x, 'g', digits) : QStringLiteral("—");
}

} // namespace

StudyTableModel::StudyTableModel(QObject* parent) : QAbstractTableModel(parent) {}

void StudyTableModel::setResult(const lab::StudyResult& result)
{
    beginResetModel();
    result_ = result;
    endResetModel();
}

int StudyTableModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : int(result_.rows.size());
}

int StudyTableModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant StudyTableModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount() || index.column() >= ColumnCount) return {};
    const lab::StudyRow& row = result_.rows[std::size_t(index.row())];
    if (role == Qt::TextAlignmentRole) {
        return index.column() == Integrator || index.column() == Status
                   ? QVariant(int(Qt::AlignLeft | Qt::AlignVCenter))
                   : QVariant(int(Qt::AlignRight | Qt::AlignVCenter));
    }
    if (role == Qt::ToolTipRole && index.column() == Status && row.status == lab::RunStatus::BlownUp) {
        return QString::fromStdString(row.blowUpMessage);
    }
    if (role != Qt::DisplayRole) return {};
    switch (index.column()) {
    case Integrator: return QString::fromStdString(row.integrator);
    case Dt: return QString::number(row.dt, 'g', QLocale::FloatingPointShortest);
    case Steps: return QString::number(row.steps);
    case PositionError: return shown(row.positionError);
    case OrientationError: return shown(row.orientationError);
    case OmegaError: return shown(row.omegaError);
    case EnergyDrift: return shown(row.energyDrift);
    case MomentumDrift: return shown(row.momentumDrift);
    case NsPerStep: return shown(row.nsPerStep, 4);
    case CostMs: {
        const std::optional<double> ns = row.totalNs();
        return shown(ns ? std::optional<double>(*ns * 1e-6) : std::nullopt);
    }
    case Status: return QString::fromStdString(row.statusText());
    }
    return {};
}

QVariant StudyTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || section < 0 || section >= ColumnCount) return {};
    if (role == Qt::ToolTipRole) {
        static const char* const tips[ColumnCount] = {
            "integrator", "step size h [s]", "steps N = T/h",
            "|x − x_exact| at T [m]", "angle of q_exact⁻¹ q at T [rad]", "|ω − ω_exact| at T [rad/s]",
            "max |E − E₀|/|E₀| over the run", "max ||L| − |L₀||/|L₀| over the run",
            "wall time per step, trace off [ns]", "ns per step × N [ms]", "ok, or the step that blew up"};
        return QString::fromUtf8(tips[section]);
    }
    if (role != Qt::DisplayRole) return {};
    static const char* const titles[ColumnCount] = {"integrator", "h [s]", "N", "e_x [m]", "e_q [rad]",
                                                    "e_ω [rad/s]", "ΔE/E", "Δ|L|/|L|", "ns/step", "cost [ms]",
                                                    "status"};
    return QString::fromUtf8(titles[section]);
}

} // namespace rbw
