// rbw diagnose --simulator "CMD" [--timeout S] [--format text|json]
// Check my simulator (issue 23, docs/simulator-protocol.md): runs the student's own
// program (CMD, started as a child process, one run per probe) through the motion
// probes (physics/workbook/probes/), reads its `state` answers strictly
// (app/simulator/simulator_process.h) and says what they are: the course algorithm's
// (matches), a mistake model's (explained, with its id), partly a model's, or nothing
// the workbook knows (unexplained), with the first number that leaves the right
// algorithm.
// Exit status: 0 matches; 1 explained, partly-explained or unexplained; 2 bad input
// (an unknown option value, a program that cannot be started, exits early, breaks the
// protocol, prints a non-finite number or does not answer within the timeout).
#pragma once

#include <QCommandLineParser>
#include <QStringList>

namespace rbw {

int runDiagnoseCommand(const QCommandLineParser& parser, const QStringList& arguments);

} // namespace rbw
