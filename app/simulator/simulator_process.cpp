#include "app/simulator/simulator_process.h"

#include "app/core/step_numbering.h"

#include <QByteArray>
#include <QDeadlineTimer>
#include <QProcess>

#include <cerrno>
#include <cmath>
#include <cstdlib>

#ifdef Q_OS_UNIX
#include <csignal>
#include <sys/types.h>
#include <unistd.h>
#endif
#ifdef Q_OS_LINUX
#include <sys/prctl.h>
#endif

namespace rbw {

SimulatorCommand parseSimulatorCommand(const QString& text)
{
    QStringList parts = QProcess::splitCommand(text);
    SimulatorCommand c;
    if (parts.isEmpty()) return c;
    c.program = parts.takeFirst();
    c.arguments = parts;
    return c;
}

AnswerParse parseAnswerLine(const QByteArray& line)
{
    AnswerParse r;
    QByteArray text = line;
    while (text.endsWith('\n') || text.endsWith('\r')) text.chop(1);
    const QList<QByteArray> tokens = text.simplified().split(' ');
    if (text.simplified().isEmpty() || (tokens.size() != 9 && tokens.size() != 13)) {
        r.error = QStringLiteral("expected 9 or 13 numbers");
        return r;
    }
    for (const QByteArray& t : tokens) {
        const std::string s = t.toStdString();
        char* end = nullptr;
        errno = 0;
        const double v = std::strtod(s.c_str(), &end);
        if (end == s.c_str() || *end != '\0') {
            r.error = QStringLiteral("\"%1\" is not a number; expected 9 or 13 numbers").arg(QString::fromUtf8(t));
            return r;
        }
        if (!std::isfinite(v)) {
            r.nonFinite = QString::fromUtf8(t);
            r.error = QStringLiteral("%1 is not a finite number").arg(r.nonFinite);
            return r;
        }
        r.values.push_back(v);
    }
    return r;
}

namespace {

// Ends the program and everything it started (its process group).
void stop(QProcess& p)
{
#ifdef Q_OS_UNIX
    const qint64 pid = p.processId();
    if (pid > 0) ::kill(-static_cast<pid_t>(pid), SIGKILL);
#endif
    if (p.state() != QProcess::NotRunning) {
        p.kill();
        p.waitForFinished(5000);
    }
}

constexpr int kCancelPollMs = 50;   // how often a wait looks at `cancel`

bool isCancelled(const std::atomic<bool>* cancel)
{
    return cancel != nullptr && cancel->load();
}

// At most until the deadline, in slices that look at `cancel`.
int waitSlice(const QDeadlineTimer& deadline, const std::atomic<bool>* cancel)
{
    const qint64 left = std::max<qint64>(0, deadline.remainingTime());
    return static_cast<int>(cancel != nullptr ? std::min<qint64>(left, kCancelPollMs) : left);
}

// One line of standard output, without its line end; false when the program exited,
// the deadline passed or the run was cancelled first.
bool readAnswer(QProcess& p, const QDeadlineTimer& deadline, const std::atomic<bool>* cancel, QByteArray& line)
{
    while (!p.canReadLine()) {
        if (p.state() == QProcess::NotRunning || deadline.hasExpired() || isCancelled(cancel)) return false;
        p.waitForReadyRead(waitSlice(deadline, cancel));
    }
    line = p.readLine();
    while (line.endsWith('\n') || line.endsWith('\r')) line.chop(1);
    return true;
}

QString howItEnded(const QProcess& p)
{
    if (p.exitStatus() == QProcess::CrashExit) {
        return QStringLiteral("was killed by signal %1").arg(p.exitCode());
    }
    return QStringLiteral("exited with status %1").arg(p.exitCode());
}

QString shown(QByteArray text)
{
    if (text.size() > 200) text = text.left(200) + "...";
    return QString::fromUtf8(text);
}

QStringList lastLines(const QByteArray& text, int n)
{
    QStringList lines = QString::fromUtf8(text).split('\n', Qt::SkipEmptyParts);
    for (QString& l : lines) {
        if (l.endsWith('\r')) l.chop(1);
    }
    return lines.mid(std::max<qsizetype>(0, lines.size() - n));
}

} // namespace

SimulatorRun runSimulatorProbe(const SimulatorCommand& command, const std::vector<std::string>& lines,
                               int probeNumber, const QString& probeName, int timeoutMs,
                               const std::atomic<bool>* cancel)
{
    SimulatorRun run;
    QProcess proc;
    proc.setProcessChannelMode(QProcess::SeparateChannels);
#ifdef Q_OS_UNIX
    proc.setChildProcessModifier([] {
        ::setpgid(0, 0);   // its own group: stop() ends the program's children too
#ifdef Q_OS_LINUX
        ::prctl(PR_SET_PDEATHSIG, SIGKILL);   // and it dies with rbw
#endif
    });
#endif
    const QString seconds = QString::number(timeoutMs / 1000.0, 'g', 6) + QStringLiteral(" s");
    const QString where = QStringLiteral("probe %1").arg(probeNumber);
    const QDeadlineTimer deadline(timeoutMs);
    auto fail = [&](const QString& message) {
        stop(proc);
        run.failure = message;
        run.stderrTail = lastLines(proc.readAllStandardError(), 5);
        return run;
    };
    auto cancelled = [&] {
        run.cancelled = true;
        return fail(QStringLiteral("cancelled at %1 (%2); your simulator was stopped").arg(where, probeName));
    };

    proc.start(command.program, command.arguments, QIODevice::ReadWrite);
    if (!proc.waitForStarted(static_cast<int>(std::max<qint64>(1, deadline.remainingTime())))) {
        return fail(QStringLiteral("cannot start the simulator \"%1\": %2").arg(command.program, proc.errorString()));
    }

    int steps = 0;
    for (const std::string& text : lines) {
        proc.write(QByteArray::fromStdString(text) + '\n');
        const QString line = QString::fromStdString(text);
        if (line == QLatin1String("quit")) break;
        if (line.startsWith(QLatin1String("step "))) ++steps;
        if (!line.startsWith(QLatin1String("state "))) continue;

        // the answer after `steps` steps, worded as every screen words it (step_numbering.h)
        const QString at = QStringLiteral("at %1, %2").arg(where, steps::stateName(steps));
        QByteArray answer;
        if (!readAnswer(proc, deadline, cancel, answer)) {
            if (isCancelled(cancel)) return cancelled();
            if (proc.state() == QProcess::NotRunning) {
                return fail(QStringLiteral("your simulator %1 %2, before it answered \"%3\" (%4)")
                                .arg(howItEnded(proc), at, line, probeName));
            }
            return fail(QStringLiteral("your simulator did not answer \"%1\" %2 within %3 (%4); it was stopped")
                            .arg(line, at, seconds, probeName));
        }
        const AnswerParse parsed = parseAnswerLine(answer);
        if (!parsed.nonFinite.isEmpty()) {
            return fail(QStringLiteral("your simulator printed %1 %2 (%3: its answer to \"%4\" was \"%5\")")
                            .arg(parsed.nonFinite, at, probeName, line, shown(answer)));
        }
        if (!parsed.error.isEmpty()) {
            return fail(QStringLiteral("your simulator answered \"%1\" to \"%2\" %3 (%4); %5")
                            .arg(shown(answer), line, at, probeName, parsed.error));
        }
        run.answers.push_back(parsed.values);
    }

    // After quit: exit 0, nothing more on standard output.
    proc.closeWriteChannel();
    do {   // at least one wait, however little time is left
        proc.waitForFinished(std::max(1, waitSlice(deadline, cancel)));
    } while (proc.state() != QProcess::NotRunning && !deadline.hasExpired() && !isCancelled(cancel));
    if (proc.state() != QProcess::NotRunning) {
        if (isCancelled(cancel)) return cancelled();
        return fail(QStringLiteral("your simulator did not exit within %1 after \"quit\" at %2 (%3); it was stopped")
                        .arg(seconds, where, probeName));
    }
    const QByteArray rest = proc.readAllStandardOutput();
    if (!rest.trimmed().isEmpty()) {
        return fail(QStringLiteral("your simulator printed \"%1\" at %2 (%3) where no answer was asked for "
                                   "(after its last answer)")
                        .arg(shown(rest.trimmed()), where, probeName));
    }
    if (proc.exitStatus() != QProcess::NormalExit || proc.exitCode() != 0) {
        return fail(QStringLiteral("your simulator %1 after \"quit\" at %2 (%3); expected status 0")
                        .arg(howItEnded(proc), where, probeName));
    }
    stop(proc);   // anything the program left running in its group
    run.ok = true;
    run.stderrTail = lastLines(proc.readAllStandardError(), 5);
    return run;
}

} // namespace rbw
