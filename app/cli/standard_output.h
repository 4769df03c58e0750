// Standard output with every write checked (issue 22). Every rbw command prints through
// out() (or writes bytes to standardOutput()); a write that fails (a full disk, /dev/full,
// a closed descriptor) is remembered with its reason, a long run stops early on it
// (failed()), and finishStandardOutput() turns it into exit status 2 with
// "rbw: cannot write to standard output: REASON" on standard error.
#pragma once

#include <QByteArray>
#include <QIODevice>
#include <QString>
#include <QTextStream>

namespace rbw::cli {

// File descriptor 1 as a QIODevice: writes are buffered (64 KiB), written with write(2)
// and checked; the first error sticks.
class StandardOutput : public QIODevice {
public:
    StandardOutput();

    bool failed() const { return errno_ != 0; }
    QString failure() const;            // the reason of the first failed write
    bool flushBuffer();                 // writes what is buffered; false once any write failed
    bool isSequential() const override { return true; }

protected:
    qint64 readData(char* data, qint64 maxSize) override;
    qint64 writeData(const char* data, qint64 size) override;

private:
    QByteArray buffer_;
    int errno_ = 0;
};

StandardOutput& standardOutput();
QTextStream& out();   // text over standardOutput()

// Flushes out() and standardOutput(). If a write to standard output failed, prints the
// message and returns 2; else returns `status`.
int finishStandardOutput(int status);

} // namespace rbw::cli
