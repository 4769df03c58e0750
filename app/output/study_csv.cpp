#include "app/output/study_csv.h"

#include <QLocale>

namespace rbw {

namespace {

// The shortest text that reads back as the same double ("0.1", not "0.10000000000000001")
QString number(double x) { return QString::number(x, 'g', QLocale::FloatingPointShortest); }

QString field(const std::optional<double>& x) { return x ? number(*x) : QString(); }

QString quoted(const QString& text)
{
    // RFC 4180: a field with a comma or a quote is quoted, quotes doubled
    if (!text.contains(',') && !text.contains('"')) return text;
    QString q = text;
    q.replace('"', "\"\"");
    return '"' + q + '"';
}

} // namespace

QStringList studyCsvHeader()
{
    return {"integrator", "dt", "steps", "t_end", "position_error", "orientation_error", "omega_error",
            "energy_drift", "momentum_drift", "ns_per_step", "status"};
}

QString studyCsvRow(const lab::StudyRow& row)
{
    const QStringList fields{
        quoted(QString::fromStdString(row.integrator)),
        number(row.dt),
        QString::number(row.steps),
        number(row.tEnd),
        field(row.positionError),
        field(row.orientationError),
        field(row.omegaError),
        field(row.energyDrift),
        field(row.momentumDrift),
        field(row.nsPerStep),
        quoted(QString::fromStdString(row.statusText())),
    };
    return fields.join(',');
}

QString studyToCsv(const lab::StudyResult& result)
{
    QString text = studyCsvHeader().join(',') + '\n';
    for (const lab::StudyRow& row : result.rows) text += studyCsvRow(row) + '\n';
    return text;
}

QStringList contactStudyCsvHeader()
{
    return {"problem", "model", "iterations", "dt", "steps", "t_end", "deepest_overlap", "deepest_below", "drift",
            "energy_gained", "kinetic_energy_end", "moving_end", "ns_per_step", "status"};
}

QString contactStudyToCsv(const lab::ContactStudyResult& result)
{
    QString text = contactStudyCsvHeader().join(',') + '\n';
    for (const lab::ContactStudyRow& row : result.rows) {
        const bool ok = row.status == lab::RunStatus::Ok;
        auto measured = [ok](double x) { return ok ? number(x) : QString(); };
        const QStringList fields{
            quoted(QString::fromStdString(result.problem)),
            QString::fromStdString(row.model),
            row.iterations > 0 ? QString::number(row.iterations) : QString(),
            number(row.dt),
            QString::number(row.steps),
            number(row.tEnd),
            measured(row.deepestOverlap),
            measured(row.deepestBelow),
            ok ? field(row.drift) : QString(),
            measured(row.energyGained),
            measured(row.kineticEnergyEnd),
            ok ? QString::number(row.movingEnd) : QString(),
            measured(row.nsPerStep),
            quoted(QString::fromStdString(row.statusText())),
        };
        text += fields.join(',') + '\n';
    }
    return text;
}

} // namespace rbw
