#include "app/cli/standard_output.h"

#include <cerrno>
#include <cstring>

#include <unistd.h>

namespace rbw::cli {

namespace {

constexpr qsizetype kBufferSize = 64 * 1024;
constexpr int kExitBadInput = 2;

} // namespace

StandardOutput::StandardOutput()
{
    open(QIODevice::WriteOnly | QIODevice::Unbuffered);
}

QString StandardOutput::failure() const
{
    return QString::fromLocal8Bit(std::strerror(errno_));
}

qint64 StandardOutput::readData(char*, qint64)
{
    return -1;
}

qint64 StandardOutput::writeData(const char* data, qint64 size)
{
    if (failed()) return -1;
    buffer_.append(data, static_cast<qsizetype>(size));
    if (buffer_.size() >= kBufferSize && !flushBuffer()) return -1;
    return size;
}

bool StandardOutput::flushBuffer()
{
    const char* data = buffer_.constData();
    qsizetype left = failed() ? 0 : buffer_.size();
    while (left > 0) {
        const ssize_t n = ::write(STDOUT_FILENO, data, static_cast<size_t>(left));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            errno_ = n < 0 ? errno : EIO;
            break;
        }
        data += n;
        left -= n;
    }
    buffer_.clear();
    return !failed();
}

StandardOutput& standardOutput()
{
    static StandardOutput device;
    return device;
}

QTextStream& out()
{
    static QTextStream stream(&standardOutput());
    return stream;
}

int finishStandardOutput(int status)
{
    out().flush();
    if (standardOutput().flushBuffer()) return status;
    QTextStream err(stderr);
    err << "rbw: cannot write to standard output: " << standardOutput().failure() << '\n';
    err.flush();
    return kExitBadInput;
}

} // namespace rbw::cli
