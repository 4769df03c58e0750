// The numbers of an accuracy study as a table (Qt model/view), one row per run:
// integrator, h, N, e_x, e_q, e_omega, dE, dL, ns per step, cost, status. A blown-up
// run shows "—" for every number and its status names the step. Display only: the
// numbers come from the study.
#pragma once

#include "physics/workbook/lab/study.h"

#include <QAbstractTableModel>

namespace rbw {

class StudyTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Integrator, Dt, Steps, PositionError, OrientationError, OmegaError, EnergyDrift,
                  MomentumDrift, NsPerStep, CostMs, Status, ColumnCount };

    explicit StudyTableModel(QObject* parent = nullptr);

    void setResult(const lab::StudyResult& result);   // resets the model
    const lab::StudyResult& result() const { return result_; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    lab::StudyResult result_;
};

} // namespace rbw
