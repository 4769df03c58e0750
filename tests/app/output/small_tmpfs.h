// A full disk for the write-error tests (issue 22): a small tmpfs mounted on a
// temporary folder, then filled to the last page. Mounting needs root (CI runs as
// root); elsewhere, or where the kernel refuses the mount (a container without
// CAP_SYS_ADMIN), available() is false and why() says so, for the test's QSKIP.
#pragma once

#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QString>
#include <QTemporaryDir>

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/mount.h>
#include <unistd.h>

namespace rbw::test {

class SmallTmpfs {
public:
    explicit SmallTmpfs(const char* size = "256k")
    {
        if (!dir_.isValid()) {
            why_ = QStringLiteral("cannot create a temporary folder");
            return;
        }
        if (::geteuid() != 0) {
            why_ = QStringLiteral("mounting a tmpfs to fill a disk needs root (CI runs as root); not root here");
            return;
        }
        const QByteArray options = QByteArray("size=") + size + ",mode=0755";
        if (::mount("tmpfs", QFile::encodeName(dir_.path()).constData(), "tmpfs", MS_NOSUID | MS_NODEV,
                    options.constData()) != 0) {
            why_ = QStringLiteral("mount -t tmpfs failed as root: %1 (a container without CAP_SYS_ADMIN?)")
                       .arg(QString::fromLocal8Bit(std::strerror(errno)));
            return;
        }
        mounted_ = true;
    }
    ~SmallTmpfs()
    {
        if (mounted_) ::umount2(QFile::encodeName(dir_.path()).constData(), MNT_DETACH);
    }
    SmallTmpfs(const SmallTmpfs&) = delete;
    SmallTmpfs& operator=(const SmallTmpfs&) = delete;

    bool available() const { return mounted_; }
    QString why() const { return why_; }
    QString filePath(const QString& name) const { return dir_.filePath(name); }
    QString path() const { return dir_.path(); }

    // Writes a filler file until the file system is full (ENOSPC on a single byte).
    // False if it never filled up (then the test would prove nothing).
    bool fill()
    {
        const int fd = ::open(QFile::encodeName(filePath(QStringLiteral("filler"))).constData(),
                              O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        if (fd < 0) return false;
        const QByteArray page(4096, 'x');
        bool full = false;
        for (int i = 0; i < 1 << 20 && !full; ++i) full = ::write(fd, page.constData(), page.size()) < 0 && errno == ENOSPC;
        for (int i = 0; i < 4096 && full; ++i) {
            if (::write(fd, "x", 1) < 0) break;   // the partial page's rest
        }
        const bool oneMore = ::write(fd, "x", 1) < 0 && errno == ENOSPC;
        ::close(fd);
        return full && oneMore;
    }
    void unfill() { QFile::remove(filePath(QStringLiteral("filler"))); }

    // The folder's entries other than the filler: what a failed write may have left.
    QStringList entries() const
    {
        QStringList e = QDir(dir_.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot);
        e.removeAll(QStringLiteral("filler"));
        return e;
    }

private:
    QTemporaryDir dir_;
    bool mounted_ = false;
    QString why_;
};

} // namespace rbw::test
