#include "app/output/atomic_file.h"

#include "app/output/output_target.h"

#include <QFile>
#include <QSaveFile>

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <unistd.h>

namespace rbw {

namespace {

QString systemError(int code)
{
    return QString::fromLocal8Bit(std::strerror(code));
}

// Every byte to descriptor fd, through short writes and signals; the errno on failure.
int writeAll(int fd, const QByteArray& bytes)
{
    const char* data = bytes.constData();
    qsizetype left = bytes.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, data, static_cast<size_t>(left));
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        if (n == 0) return EIO;
        data += n;
        left -= n;
    }
    return 0;
}

// A FIFO, a character device or another process's descriptor: opened for writing
// without O_CREAT or O_TRUNC (O_APPEND, so a regular file behind a descriptor link
// keeps what it holds), written, closed; every step checked.
int writeInPlace(const QString& resolved, const QByteArray& bytes)
{
    int fd = -1;
    do {
        fd = ::open(QFile::encodeName(resolved).constData(), O_WRONLY | O_APPEND | O_NOCTTY | O_CLOEXEC);
    } while (fd < 0 && errno == EINTR);
    if (fd < 0) return errno;
    const int writeError = writeAll(fd, bytes);
    const int closeError = ::close(fd) == 0 || errno == EINTR ? 0 : errno;
    return writeError != 0 ? writeError : closeError;
}

// The atomic replacement. QSaveFile buffers up to 16 KiB and writes it in commit(),
// which then renames even if that write failed (ENOSPC on a full disk): flush and
// check first, and sync to disk before the rename, so that commit() has nothing left
// that could fail unnoticed.
bool replaceFile(const QString& resolved, const QByteArray& bytes, QString* reason)
{
    QSaveFile file(resolved);
    if (!file.open(QIODevice::WriteOnly)) {
        *reason = file.errorString();
        return false;
    }
    if (file.write(bytes) != bytes.size() || !file.flush() || file.error() != QFileDevice::NoError) {
        *reason = file.errorString();
        file.cancelWriting();
        return false;   // the destructor removes the temporary file
    }
    const int fd = file.handle();
    if (fd >= 0 && ::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) {
        *reason = systemError(errno);
        file.cancelWriting();
        return false;
    }
    if (!file.commit()) {
        *reason = file.errorString();
        return false;
    }
    return true;
}

} // namespace

bool writeFileAtomically(const QString& path, const QByteArray& bytes, QString* error)
{
    const OutputTarget target = resolveOutputTarget(path);
    QString reason;
    bool ok = false;
    switch (target.kind) {
    case OutputTarget::Kind::Replace:
        ok = replaceFile(target.resolved, bytes, &reason);
        break;
    case OutputTarget::Kind::InPlace:
        if (const int e = writeInPlace(target.resolved, bytes); e != 0) reason = systemError(e);
        else ok = true;
        break;
    case OutputTarget::Kind::OwnDescriptor:
        if (const int e = writeAll(target.descriptor, bytes); e != 0) reason = systemError(e);
        else ok = true;
        break;
    case OutputTarget::Kind::Refused:
        reason = target.reason;
        break;
    }
    if (!ok && error != nullptr) *error = QStringLiteral("%1: cannot write: %2").arg(path, reason);
    return ok;
}

} // namespace rbw
