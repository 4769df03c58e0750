// rbw probes --output DIR [--probes motion|collision|all]
// The offline half of "Check my simulator" (issue 23, docs/simulator-protocol.md,
// "Offline mode"): writes each probe of the group as the protocol's commands, one file
// per probe, DIR/<probe>.commands (from "reset" to "quit"), through the atomic writer.
// The student's program reads each file and writes its `state` answers to
// DIR/<probe>.states; `rbw diagnose DIR` reads them back (probe_answer_files.h).
// Exit status: 0 written; 2 bad input (no --output, an unknown group, a folder that
// cannot be made or a file that cannot be written).
#pragma once

#include <QCommandLineParser>
#include <QStringList>

namespace rbw {

int runProbesCommand(const QCommandLineParser& parser, const QStringList& arguments);

} // namespace rbw
