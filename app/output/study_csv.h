// CSV of an accuracy study (physics/workbook/lab/study.h): a header, then one row per
// integrator x dt:
//   integrator,dt,steps,t_end,position_error,orientation_error,omega_error,
//   energy_drift,momentum_drift,ns_per_step,status
// Numbers are written in the shortest form that reads back as the same double. A field the run
// has no number for (a blown-up run, or a drift without a reference value) is empty,
// never NaN; status is "ok" or "blown up at step k". Formatting only: the numbers
// come from the study.
#pragma once

#include "physics/workbook/lab/contact_study.h"
#include "physics/workbook/lab/study.h"

#include <QString>
#include <QStringList>

namespace rbw {

QStringList studyCsvHeader();
QString studyCsvRow(const lab::StudyRow& row);
QString studyToCsv(const lab::StudyResult& result);   // header + rows, '\n' line ends

// CSV of a contact study (physics/workbook/lab/contact_study.h), one row per model x iterations x dt:
//   problem,model,iterations,dt,steps,t_end,deepest_overlap,deepest_below,drift,
//   energy_gained,kinetic_energy_end,moving_end,ns_per_step,status
// iterations is empty for the course model, drift for the rain; a blown-up run has only
// its model, h, steps and status.
QStringList contactStudyCsvHeader();
QString contactStudyToCsv(const lab::ContactStudyResult& result);

} // namespace rbw
