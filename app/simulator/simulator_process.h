// The student's simulator as a child process (issue 23, docs/simulator-protocol.md):
// one probe = one run of the program. It sends the probe's protocol lines one by one,
// waits for one line after each `state`, parses it strictly, and after `quit` expects
// the program to exit with status 0 having printed nothing else. Anything else (the
// program cannot be started, exits early, breaks the protocol, prints a non-finite
// number or does not answer within the probe's time) ends the run with a sentence that
// names the probe, the step, the command and what the program printed.
//
// The program never runs inside the workbook, and never outlives a run: on Unix it
// starts in its own process group, which is killed as a whole (a shell script's own
// children too), and on Linux it is also killed if rbw itself dies.
#pragma once

#include <QString>
#include <QStringList>

#include <atomic>
#include <string>
#include <vector>

namespace rbw {

struct SimulatorRun {
    bool ok = false;
    std::vector<std::vector<double>> answers;   // one per `state`, 9 or 13 finite numbers
    QString failure;                            // when !ok: what went wrong
    QStringList stderrTail;                     // the program's last lines on standard error
    bool cancelled = false;                     // stopped by `cancel` (failure says so)
};

struct SimulatorCommand {
    QString program;
    QStringList arguments;
};

// "python3 my_sim.py" -> program and arguments (QProcess::splitCommand's quoting);
// empty program when the text holds none.
SimulatorCommand parseSimulatorCommand(const QString& text);

// Runs one probe: `lines` from "reset" to "quit"; `probeNumber` (from 1) and `probeName`
// only for the messages; `timeoutMs` from the start to the program's exit. `cancel`, when
// set (from another thread), stops the program within about 50 ms.
SimulatorRun runSimulatorProbe(const SimulatorCommand& command, const std::vector<std::string>& lines,
                               int probeNumber, const QString& probeName, int timeoutMs,
                               const std::atomic<bool>* cancel = nullptr);

// Parses one answer line: 9 or 13 numbers in any format strtod reads, separated by
// spaces or tabs (a trailing \r is allowed). Empty `error` when it parses; otherwise
// `error` says what is wrong and `nonFinite` holds the first nan/inf token, if that
// was the reason.
struct AnswerParse {
    std::vector<double> values;
    QString error;
    QString nonFinite;
};
AnswerParse parseAnswerLine(const QByteArray& line);

} // namespace rbw
