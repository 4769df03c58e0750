#include "app/output/output_target.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace rbw {

namespace {

constexpr int kMaxSymlinkHops = 40;   // as the kernel's ELOOP limit

QString identityOf(const struct stat& st)
{
    return QStringLiteral("inode:%1:%2").arg(static_cast<qulonglong>(st.st_dev)).arg(static_cast<qulonglong>(st.st_ino));
}

// /proc/PID/fd/N or /proc/PID/task/TID/fd/N: a "magic" link to an open descriptor. Not
// followed like a symbolic link: its target may be a pipe, a socket or a file that the
// descriptor opened with O_APPEND, none of which a path can reproduce.
bool isDescriptorLink(const QString& path, qint64* pid, int* fd)
{
    static const QRegularExpression re(QStringLiteral("^/proc/(\\d+)(?:/task/\\d+)?/fd/(\\d+)$"));
    const QRegularExpressionMatch m = re.match(path);
    if (!m.hasMatch()) return false;
    bool okPid = false;
    bool okFd = false;
    *pid = m.captured(1).toLongLong(&okPid);
    *fd = m.captured(2).toInt(&okFd);
    return okPid && okFd;
}

OutputTarget refused(const QString& resolved, const QString& reason)
{
    OutputTarget t;
    t.kind = OutputTarget::Kind::Refused;
    t.resolved = resolved;
    t.reason = reason;
    t.identity = resolved;
    return t;
}

} // namespace

OutputTarget resolveOutputTarget(const QString& path)
{
    if (path.isEmpty()) return refused(path, QStringLiteral("the file name is empty"));
    QString p = QDir::cleanPath(QFileInfo(path).absoluteFilePath());
    for (int hop = 0;; ++hop) {
        if (hop == kMaxSymlinkHops) return refused(p, QStringLiteral("too many levels of symbolic links"));
        // The folder's own links (/dev/fd -> /proc/self/fd, /proc/self -> /proc/PID).
        const QFileInfo info(p);
        const QString folder = QFileInfo(info.absolutePath()).canonicalFilePath();
        if (folder.isEmpty()) break;   // no such folder: the write reports it
        p = folder == QLatin1String("/") ? QLatin1Char('/') + info.fileName() : folder + QLatin1Char('/') + info.fileName();

        qint64 pid = 0;
        int fd = -1;
        if (isDescriptorLink(p, &pid, &fd)) {
            OutputTarget t;
            t.resolved = p;
            struct stat st {};
            if (pid == static_cast<qint64>(::getpid())) {
                if (::fstat(fd, &st) != 0) return refused(p, QString::fromLocal8Bit(std::strerror(errno)));
                t.kind = OutputTarget::Kind::OwnDescriptor;
                t.descriptor = fd;
            } else {
                if (::stat(QFile::encodeName(p).constData(), &st) != 0) {
                    return refused(p, QString::fromLocal8Bit(std::strerror(errno)));
                }
                t.kind = OutputTarget::Kind::InPlace;
            }
            if (S_ISDIR(st.st_mode)) return refused(p, QStringLiteral("it is a directory"));
            t.identity = identityOf(st);
            return t;
        }

        struct stat lst {};
        if (::lstat(QFile::encodeName(p).constData(), &lst) != 0 || !S_ISLNK(lst.st_mode)) break;
        char buffer[4096];
        const ssize_t n = ::readlink(QFile::encodeName(p).constData(), buffer, sizeof buffer - 1);
        if (n < 0) break;
        const QString target = QFile::decodeName(QByteArray(buffer, static_cast<qsizetype>(n)));
        p = QDir::cleanPath(QDir::isAbsolutePath(target) ? target : folder + QLatin1Char('/') + target);
    }

    OutputTarget t;
    t.resolved = p;
    t.identity = p;
    struct stat st {};
    if (::stat(QFile::encodeName(p).constData(), &st) != 0) {
        t.kind = OutputTarget::Kind::Replace;   // a new file (or an error the write will name)
        return t;
    }
    if (S_ISREG(st.st_mode)) t.kind = OutputTarget::Kind::Replace;
    else if (S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode)) t.kind = OutputTarget::Kind::InPlace;
    else if (S_ISDIR(st.st_mode)) return refused(p, QStringLiteral("it is a directory"));
    else if (S_ISBLK(st.st_mode)) return refused(p, QStringLiteral("it is a block device (only regular files, FIFOs and character devices are written)"));
    else if (S_ISSOCK(st.st_mode)) return refused(p, QStringLiteral("it is a socket (only regular files, FIFOs and character devices are written)"));
    else return refused(p, QStringLiteral("it is not a regular file, FIFO or character device"));
    t.identity = identityOf(st);
    return t;
}

} // namespace rbw
