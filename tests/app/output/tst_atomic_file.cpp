// The atomic writer (app/output/atomic_file.h, issue 22) on the cases that used to lose
// a file: a full disk (a small tmpfs, root only), a FIFO, an open descriptor named by
// path, a symbolic link, a directory. The real rbw's use of it: tst_cli_writes.
#include "app/output/atomic_file.h"
#include "app/output/output_target.h"
#include "tests/app/output/small_tmpfs.h"

#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>

#include <thread>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace {

QByteArray readAll(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("<unreadable>");
}

void writePlain(const QString& path, const QByteArray& bytes)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    QCOMPARE(f.write(bytes), bytes.size());
}

mode_t typeOf(const QString& path)
{
    struct stat st {};
    return ::lstat(QFile::encodeName(path).constData(), &st) == 0 ? (st.st_mode & S_IFMT) : 0;
}

} // namespace

class TestAtomicFile : public QObject {
    Q_OBJECT
private slots:
    // A full disk: the write fails with the reason and the old file is untouched, for
    // content below QSaveFile's 16 KiB buffer (the error surfaced only in commit(),
    // which renamed an empty file over the old one) and above it.
    void fullDiskKeepsTheOldFile_data()
    {
        QTest::addColumn<int>("size");
        QTest::newRow("100 bytes (inside QSaveFile's buffer)") << 100;
        QTest::newRow("40 KiB (beyond the buffer)") << 40 * 1024;
    }
    void fullDiskKeepsTheOldFile()
    {
        QFETCH(int, size);
        rbw::test::SmallTmpfs fs;
        if (!fs.available()) QSKIP(qPrintable(fs.why()));
        const QString path = fs.filePath(QStringLiteral("scene.json"));
        writePlain(path, "OLD CONTENT\n");
        QVERIFY(fs.fill());
        const QByteArray bytes(size, 'n');
        QString error;
        QVERIFY(!rbw::writeFileAtomically(path, bytes, &error));
        QVERIFY2(error.startsWith(path + QStringLiteral(": cannot write: ")), qPrintable(error));
        QVERIFY2(error.contains(QStringLiteral("No space left on device")), qPrintable(error));
        QCOMPARE(readAll(path), QByteArray("OLD CONTENT\n"));
        QCOMPARE(fs.entries(), QStringList{QStringLiteral("scene.json")});   // no temporary left
        // Control: with room again the same call writes the file.
        fs.unfill();
        QVERIFY2(rbw::writeFileAtomically(path, bytes, &error), qPrintable(error));
        QCOMPARE(readAll(path), bytes);
    }

    void fullDiskLeavesNoNewFile()
    {
        rbw::test::SmallTmpfs fs;
        if (!fs.available()) QSKIP(qPrintable(fs.why()));
        QVERIFY(fs.fill());
        QVERIFY(!rbw::writeFileAtomically(fs.filePath(QStringLiteral("new.csv")), "a,b\n", nullptr));
        QCOMPARE(fs.entries(), QStringList{});
    }

    // A FIFO is written in place: its reader gets every byte and it stays a FIFO.
    void fifoIsWrittenInPlace()
    {
        QTemporaryDir dir;
        const QString fifo = dir.filePath(QStringLiteral("pipe"));
        QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        const QByteArray bytes = QByteArray("line\n").repeated(20000);   // 100 kB: more than a pipe holds
        QByteArray got;
        std::thread reader([&] {
            QFile f(fifo);
            if (f.open(QIODevice::ReadOnly)) got = f.readAll();
        });
        QString error;
        const bool ok = rbw::writeFileAtomically(fifo, bytes, &error);
        reader.join();
        QVERIFY2(ok, qPrintable(error));
        QCOMPARE(got.size(), bytes.size());
        QCOMPARE(got, bytes);
        QCOMPARE(typeOf(fifo), mode_t(S_IFIFO));
    }

    // A path naming one of this process's descriptors writes through it: a file opened
    // for appending keeps its content (what `--output /dev/stdout >> log` needs).
    void ownDescriptorAppends_data()
    {
        QTest::addColumn<QString>("pattern");
        QTest::newRow("/proc/self/fd/N") << QStringLiteral("/proc/self/fd/%1");
        QTest::newRow("/dev/fd/N") << QStringLiteral("/dev/fd/%1");
        QTest::newRow("/proc/PID/fd/N") << QStringLiteral("/proc/%1/fd/").arg(::getpid()) + QStringLiteral("%1");
    }
    void ownDescriptorAppends()
    {
        QFETCH(QString, pattern);
        QTemporaryDir dir;
        const QString log = dir.filePath(QStringLiteral("log.txt"));
        writePlain(log, "kept\n");
        const int fd = ::open(QFile::encodeName(log).constData(), O_WRONLY | O_APPEND | O_CLOEXEC);
        QVERIFY(fd >= 0);
        const QString path = pattern.arg(fd);
        QCOMPARE(rbw::resolveOutputTarget(path).kind, rbw::OutputTarget::Kind::OwnDescriptor);
        QString error;
        const bool ok = rbw::writeFileAtomically(path, "new\n", &error);
        ::close(fd);
        QVERIFY2(ok, qPrintable(error));
        QCOMPARE(readAll(log), QByteArray("kept\nnew\n"));
        QCOMPARE(typeOf(log), mode_t(S_IFREG));
    }

    // A closed descriptor is an error, not a new file.
    void closedDescriptorIsRefused()
    {
        const int fd = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
        QVERIFY(fd >= 0);
        ::close(fd);
        QString error;
        QVERIFY(!rbw::writeFileAtomically(QStringLiteral("/proc/self/fd/%1").arg(fd), "x", &error));
        QVERIFY2(error.contains(QStringLiteral("Bad file descriptor")), qPrintable(error));
    }

    // Through a symbolic link the target is replaced and the link stays a link.
    void symlinkKeepsTheLink()
    {
        QTemporaryDir dir;
        const QString target = dir.filePath(QStringLiteral("real.json"));
        const QString link = dir.filePath(QStringLiteral("link.json"));
        writePlain(target, "old");
        QVERIFY(QFile::link(target, link));
        QString error;
        QVERIFY2(rbw::writeFileAtomically(link, "new", &error), qPrintable(error));
        QCOMPARE(typeOf(link), mode_t(S_IFLNK));
        QCOMPARE(readAll(target), QByteArray("new"));
        QCOMPARE(rbw::resolveOutputTarget(link).identity, rbw::resolveOutputTarget(target).identity);
    }

    void refused_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("reason");
        QTest::newRow("a directory") << QStringLiteral(".") << QStringLiteral("it is a directory");
        QTest::newRow("a missing folder") << QStringLiteral("no/such/file.json") << QStringLiteral("No such file or directory");
        QTest::newRow("an empty name") << QString() << QStringLiteral("the file name is empty");
    }
    void refused()
    {
        QFETCH(QString, name);
        QFETCH(QString, reason);
        QTemporaryDir dir;
        const QString path = name.isEmpty() ? name : dir.filePath(name);
        QString error;
        QVERIFY(!rbw::writeFileAtomically(path, "x", &error));
        QVERIFY2(error.startsWith(path + QStringLiteral(": cannot write: ")), qPrintable(error));
        QVERIFY2(error.contains(reason), qPrintable(error));
        QVERIFY(QFileInfo(dir.path()).isDir());
    }

    // A character device is written in place, never replaced: /dev/null takes the bytes.
    void characterDeviceInPlace()
    {
        QCOMPARE(rbw::resolveOutputTarget(QStringLiteral("/dev/null")).kind, rbw::OutputTarget::Kind::InPlace);
        QString error;
        QVERIFY2(rbw::writeFileAtomically(QStringLiteral("/dev/null"), "x", &error), qPrintable(error));
        QCOMPARE(typeOf(QStringLiteral("/dev/null")), mode_t(S_IFCHR));
        // /dev/full in place: the write reports ENOSPC (no rename over the node: the
        // target is never renamed over unless it is a regular file, see the kind).
        QCOMPARE(rbw::resolveOutputTarget(QStringLiteral("/dev/full")).kind, rbw::OutputTarget::Kind::InPlace);
    }
};

QTEST_GUILESS_MAIN(TestAtomicFile)
#include "tst_atomic_file.moc"
