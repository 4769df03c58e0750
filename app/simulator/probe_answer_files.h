// The offline answers of "Check my simulator" (issue 23, docs/simulator-protocol.md,
// "Offline mode"), read strictly: a bad line ends the reading with a sentence that
// names the file, the line and the reason (rbw diagnose exits 2 with it).
//
// A folder (rbw diagnose DIR): DIR/<probe>.commands as `rbw probes` wrote them (each
// must be the workbook's probe, line for line) and DIR/<probe>.states, the program's
// answers: one line per `state` command, in order, 9 or 13 numbers
// (simulator_process.h's parseAnswerLine), nothing else. Without a group, the probes
// are those whose .commands file is in DIR.
//
// A trajectory (rbw diagnose --trajectory FILE.csv): the header
//   probe,step,body,x,y,z,vx,vy,vz,wx,wy,wz,qw,qx,qy,qz
// then one row per `state` answer: the probe's name, the steps before the answer, the
// body, and the 13 numbers (the four of the quaternion may all be empty: a program
// without an orientation getter). Each probe's rows come in the order of its `state`
// commands; every probe of the group (or, without one, every probe the file names) has
// all its rows.
#pragma once

#include "physics/workbook/probes/probes.h"
#include "physics/workbook/probes/replay.h"

#include <QString>

#include <optional>
#include <vector>

namespace rbw {

struct OfflineAnswers {
    bool ok = false;
    QString failure;                        // when !ok: "FILE:LINE: reason"
    std::vector<probes::Probe> probes;      // the probes answered, in their run order
    std::vector<probes::Answers> given;     // their answers
};

// `group`: the probes asked for (--probes), or nullopt: those found.
OfflineAnswers readAnswersFolder(const QString& dir, std::optional<probes::ProbeGroup> group);
OfflineAnswers readTrajectoryCsv(const QString& file, std::optional<probes::ProbeGroup> group);

} // namespace rbw
