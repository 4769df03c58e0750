// Every file and every byte of standard output the real rbw writes is checked (issue 22):
// - `> /dev/full` for every command: exit 2, "cannot write to standard output: ...";
// - --output to a FIFO: its reader gets the whole content, the FIFO stays;
// - --output /dev/stdout (and /dev/fd/1, /proc/self/fd/1) with standard output
//   redirected into a file with >>: the file keeps what it held, the content follows;
// - --output to a character device (a twin of /dev/full or /dev/null made with mknod,
//   root only): written in place, the node stays;
// - two outputs naming one file, an output naming a lesson's own file or the input
//   scene: exit 2, nothing written;
// - a full disk (a small tmpfs, root only) for every writer: exit 2 naming the file and
//   the reason, the old file untouched, no temporary file left.
#include "tests/app/output/small_tmpfs.h"
#include "tests/test_support.h"

#include <QCryptographicHash>
#include <QDirIterator>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <thread>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

namespace {

const QString kLessons = QStringLiteral(RBW_SOURCE_DIR "/lessons");
const QString kLesson1 = kLessons + QStringLiteral("/01-one-step/scene.json");
const QString kSpin = kLessons + QStringLiteral("/10-accuracy-lab/constant-spin.json");

struct Proc {
    int exit = -1;
    QByteArray out;
    QString err;
};

// rbw with ARGS; standard output to `stdoutFile` (appended to if `append`) when given.
Proc runCli(const QStringList& args, const QString& stdoutFile = {}, bool append = false)
{
    QProcess p;
    if (!stdoutFile.isEmpty()) p.setStandardOutputFile(stdoutFile, append ? QIODevice::Append : QIODevice::Truncate);
    p.start(QStringLiteral(RBW_CLI_PATH), args);
    if (!p.waitForFinished(120000)) p.kill();
    return Proc{p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAllStandardOutput(),
                QString::fromUtf8(p.readAllStandardError())};
}

QStringList withOut(QStringList args, const QString& out)
{
    for (QString& a : args) a.replace(QStringLiteral("{out}"), out);
    return args;
}

QByteArray readAll(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("<unreadable>");
}

bool writePlain(const QString& path, const QByteArray& bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size();
}

mode_t typeOf(const QString& path)
{
    struct stat st {};
    return ::lstat(QFile::encodeName(path).constData(), &st) == 0 ? (st.st_mode & S_IFMT) : 0;
}

// Every file under `dir` with its SHA-256: what must not change.
QMap<QString, QByteArray> snapshot(const QString& dir)
{
    QMap<QString, QByteArray> files;
    QDirIterator it(dir, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString f = it.next();
        files.insert(f, QCryptographicHash::hash(readAll(f), QCryptographicHash::Sha256));
    }
    return files;
}

// The writers and what they write: {out} is the file. The study CSVs hold timings
// (ns_per_step), so only their shape is compared.
void writerRows()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<bool>("exact");
    const QString seed = QStringLiteral("--seed");
    QTest::newRow("exercise --output") << QStringList{"exercise", "01-one-step", seed, "3", "--output", "{out}"} << true;
    QTest::newRow("exercise --worksheet") << QStringList{"exercise", "01-one-step", seed, "3", "--worksheet", "{out}"} << true;
    QTest::newRow("exercise --answer-key") << QStringList{"exercise", "01-one-step", seed, "3", "--answer-key", "{out}"} << true;
    QTest::newRow("exercise --answers-key") << QStringList{"exercise", "01-one-step", seed, "3", "--answers-key", "{out}"} << true;
    QTest::newRow("study --output") << QStringList{"study", kSpin, "--integrators", "explicit-euler", "--dt", "0.1",
                                                   "--t-end", "1", "--output", "{out}"} << false;
    QTest::newRow("contact-study --output") << QStringList{"contact-study", "resting-box", "--iterations", "1", "--dt",
                                                           "0.01", "--t-end", "0.05", "--output", "{out}"} << false;
}

void compareContent(const QByteArray& got, const QByteArray& expected, bool exact)
{
    if (exact) {
        QCOMPARE(got, expected);
        return;
    }
    QCOMPARE(got.count('\n'), expected.count('\n'));
    QCOMPARE(got.left(got.indexOf('\n')), expected.left(expected.indexOf('\n')));
}

} // namespace

class TestCliWrites : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        // A scene and its answers file for `check`.
        scene_ = dir_.filePath(QStringLiteral("ex.json"));
        answers_ = dir_.filePath(QStringLiteral("ex-answers.json"));
        const Proc p = runCli({"exercise", "01-one-step", "--seed", "3", "--output", scene_, "--answers-key", answers_});
        QVERIFY2(p.exit == 0, qPrintable(p.err));
    }

    void stdoutFull_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<int>("okExit");   // the exit status with a working standard output
        QTest::newRow("run json") << QStringList{"run", kLesson1} << 0;
        QTest::newRow("run csv") << QStringList{"run", kLesson1, "--format", "csv", "--steps", "50"} << 0;
        QTest::newRow("run --trace all") << QStringList{"run", kLesson1, "--trace", "all", "--steps", "50"} << 0;
        QTest::newRow("study") << QStringList{"study", kSpin, "--integrators", "explicit-euler", "--dt", "0.1", "--t-end", "1"} << 0;
        QTest::newRow("contact-study") << QStringList{"contact-study", "resting-box", "--iterations", "1", "--dt", "0.01",
                                                      "--t-end", "0.05"} << 0;
        QTest::newRow("check text") << QStringList{"check", "{scene}", "{answers}"} << 0;
        QTest::newRow("check json") << QStringList{"check", "{scene}", "{answers}", "--format", "json"} << 0;
        QTest::newRow("check csv") << QStringList{"check", "{scene}", "{answers}", "--format", "csv"} << 0;
        QTest::newRow("exercise") << QStringList{"exercise", "01-one-step", "--seed", "3"} << 0;
        QTest::newRow("lessons") << QStringList{"lessons"} << 0;
        QTest::newRow("integrators") << QStringList{"integrators"} << 0;
        QTest::newRow("quantities") << QStringList{"quantities"} << 0;
        QTest::newRow("quantities json") << QStringList{"quantities", "--format", "json"} << 0;
        QTest::newRow("quantities csv") << QStringList{"quantities", "--format", "csv"} << 0;
        QTest::newRow("--help") << QStringList{"--help"} << 0;
        QTest::newRow("--version") << QStringList{"--version"} << 0;
    }
    void stdoutFull()
    {
        QFETCH(QStringList, args);
        QFETCH(int, okExit);
        for (QString& a : args) {
            a.replace(QStringLiteral("{scene}"), scene_);
            a.replace(QStringLiteral("{answers}"), answers_);
        }
        const Proc full = runCli(args, QStringLiteral("/dev/full"));
        QVERIFY2(full.exit == 2, qPrintable(QStringLiteral("exit %1: %2").arg(full.exit).arg(full.err)));
        QVERIFY2(full.err.contains(QStringLiteral("rbw: cannot write to standard output: No space left on device")),
                 qPrintable(full.err));
        // Control: the same command prints something and succeeds on a working output.
        const Proc ok = runCli(args);
        QVERIFY2(ok.exit == okExit, qPrintable(ok.err));
        QVERIFY(!ok.out.isEmpty());
    }

    // A long streamed run stops at its first failed write instead of simulating on:
    // 10^6 traced steps of lesson 1 take minutes; the write fails within the first 64 KiB.
    void streamingStopsEarly()
    {
        QElapsedTimer t;
        t.start();
        const Proc full = runCli({"run", kLesson1, "--trace", "all", "--steps", "1000000"}, QStringLiteral("/dev/full"));
        QCOMPARE(full.exit, 2);
        QVERIFY2(t.elapsed() < 20000, qPrintable(QString::number(t.elapsed())));
    }

    void fifo_data() { writerRows(); }
    void fifo()
    {
        QFETCH(QStringList, args);
        QFETCH(bool, exact);
        QTemporaryDir dir;
        const QString reference = dir.filePath(QStringLiteral("reference"));
        QCOMPARE(runCli(withOut(args, reference)).exit, 0);
        const QString fifo = dir.filePath(QStringLiteral("pipe"));
        QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        QByteArray got;
        std::thread reader([&] {
            QFile f(fifo);
            if (f.open(QIODevice::ReadOnly)) got = f.readAll();
        });
        const Proc p = runCli(withOut(args, fifo));
        // Should rbw not have opened the FIFO, open it here so that the reader returns.
        if (const int fd = ::open(QFile::encodeName(fifo).constData(), O_WRONLY | O_NONBLOCK | O_CLOEXEC); fd >= 0) ::close(fd);
        reader.join();
        QVERIFY2(p.exit == 0, qPrintable(p.err));
        QCOMPARE(typeOf(fifo), mode_t(S_IFIFO));
        compareContent(got, readAll(reference), exact);
    }

    // --output /dev/stdout with standard output appended to a log: the log keeps its
    // line (QSaveFile used to rename a temporary over it) and gets the content after it.
    void stdoutAppended_data()
    {
        writerRows();
    }
    void stdoutAppended()
    {
        QFETCH(QStringList, args);
        QFETCH(bool, exact);
        QTemporaryDir dir;
        // Without --output, exercise also prints the scene, after writing its files.
        const QString reference = dir.filePath(QStringLiteral("reference"));
        const Proc ref = runCli(withOut(args, reference));
        QCOMPARE(ref.exit, 0);
        for (const QString& name : {QStringLiteral("/dev/stdout"), QStringLiteral("/dev/fd/1"), QStringLiteral("/proc/self/fd/1")}) {
            const QString log = dir.filePath(QStringLiteral("log.txt"));
            QVERIFY(writePlain(log, "kept line\n"));
            const Proc p = runCli(withOut(args, name), log, true);
            QVERIFY2(p.exit == 0, qPrintable(name + QStringLiteral(": ") + p.err));
            const QByteArray got = readAll(log);
            QVERIFY2(got.startsWith("kept line\n"), qPrintable(name));
            compareContent(got.mid(10), readAll(reference) + ref.out, exact);
        }
    }

    // A character device is written in place: a twin of /dev/full reports ENOSPC (exit 2)
    // and a twin of /dev/null takes the bytes (exit 0); both stay device nodes.
    void characterDevice_data() { writerRows(); }
    void characterDevice()
    {
        QFETCH(QStringList, args);
        if (::geteuid() != 0) QSKIP("mknod of a device twin needs root (CI runs as root); not root here");
        QTemporaryDir dir;
        const QString full = dir.filePath(QStringLiteral("full"));
        const QString null = dir.filePath(QStringLiteral("null"));
        QCOMPARE(::mknod(QFile::encodeName(full).constData(), S_IFCHR | 0666, makedev(1, 7)), 0);
        QCOMPARE(::mknod(QFile::encodeName(null).constData(), S_IFCHR | 0666, makedev(1, 3)), 0);
        const Proc pf = runCli(withOut(args, full));
        QVERIFY2(pf.exit == 2, qPrintable(pf.err));
        QVERIFY2(pf.err.contains(full + QStringLiteral(": --")) && pf.err.contains(QStringLiteral("cannot write: No space left on device")),
                 qPrintable(pf.err));
        const Proc pn = runCli(withOut(args, null));
        QVERIFY2(pn.exit == 0, qPrintable(pn.err));
        QCOMPARE(typeOf(full), mode_t(S_IFCHR));
        QCOMPARE(typeOf(null), mode_t(S_IFCHR));
    }

    // Refused before anything is written; every file in the folder (a copy of lesson 1)
    // stays as it was, and no output appears.
    void conflictingOutputs_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("words");
        const QStringList ex{"exercise", "{lesson}", "--seed", "3"};
        QTest::newRow("--output and --answers-key the same file")
            << ex + QStringList{"--output", "{dir}/a.json", "--answers-key", "{dir}/a.json"} << "name the same file";
        QTest::newRow("--worksheet and --answer-key through a link")
            << ex + QStringList{"--worksheet", "{dir}/w.html", "--answer-key", "{dir}/link.html"} << "name the same file";
        QTest::newRow("--output the lesson's exercise.json")
            << ex + QStringList{"--output", "{lesson}/exercise.json"} << "the lesson's exercise.json, which is never overwritten";
        QTest::newRow("--answers-key the lesson's scene")
            << ex + QStringList{"--answers-key", "{lesson}/scene.json"} << "never overwritten";
        QTest::newRow("--worksheet the lesson's text")
            << ex + QStringList{"--worksheet", "{lesson}/lesson.md"} << "the lesson's lesson.md";
        QTest::newRow("study --output its own scene")
            << QStringList{"study", "{lesson}/scene.json", "--output", "{lesson}/scene.json"} << "the scene file (the input)";
        QTest::newRow("study --output its scene through a link")
            << QStringList{"study", "{lesson}/scene.json", "--output", "{dir}/scene-link.json"} << "never overwritten";
        QTest::newRow("--output a directory")
            << ex + QStringList{"--output", "{dir}", "--worksheet", "{dir}/w.html"} << "it is a directory";
    }
    void conflictingOutputs()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, words);
        QTemporaryDir dir;
        const QString lesson = dir.filePath(QStringLiteral("lesson"));
        QVERIFY(QDir().mkpath(lesson));
        for (const QString& f : QDir(kLessons + QStringLiteral("/01-one-step")).entryList(QDir::Files)) {
            QVERIFY(QFile::copy(kLessons + QStringLiteral("/01-one-step/") + f, lesson + QLatin1Char('/') + f));
        }
        QVERIFY(QFile::link(dir.filePath(QStringLiteral("w.html")), dir.filePath(QStringLiteral("link.html"))));
        QVERIFY(QFile::link(lesson + QStringLiteral("/scene.json"), dir.filePath(QStringLiteral("scene-link.json"))));
        for (QString& a : args) {
            a.replace(QStringLiteral("{lesson}"), lesson);
            a.replace(QStringLiteral("{dir}"), dir.path());
        }
        const QMap<QString, QByteArray> before = snapshot(dir.path());
        const Proc p = runCli(args);
        QVERIFY2(p.exit == 2, qPrintable(QStringLiteral("exit %1: %2").arg(p.exit).arg(p.err)));
        QVERIFY2(p.err.contains(words), qPrintable(p.err));
        QCOMPARE(snapshot(dir.path()), before);
        // Control: the lesson copy itself is a working exercise.
        QCOMPARE(runCli({"exercise", lesson, "--seed", "3"}).exit, 0);
    }

    // A full disk for every writer: exit 2, the message names the file and the reason,
    // the old file is untouched and nothing else is left. Then, with room, it writes.
    void fullDisk_data() { writerRows(); }
    void fullDisk()
    {
        QFETCH(QStringList, args);
        rbw::test::SmallTmpfs fs;
        if (!fs.available()) QSKIP(qPrintable(fs.why()));
        const QString out = fs.filePath(QStringLiteral("old.out"));
        QVERIFY(writePlain(out, "OLD CONTENT\n"));
        QVERIFY(fs.fill());
        const Proc p = runCli(withOut(args, out));
        QVERIFY2(p.exit == 2, qPrintable(QStringLiteral("exit %1: %2").arg(p.exit).arg(p.err)));
        QVERIFY2(p.err.contains(out) && p.err.contains(QStringLiteral("No space left on device")), qPrintable(p.err));
        QCOMPARE(readAll(out), QByteArray("OLD CONTENT\n"));
        QCOMPARE(fs.entries(), QStringList{QStringLiteral("old.out")});
        fs.unfill();
        const Proc ok = runCli(withOut(args, out));
        QVERIFY2(ok.exit == 0, qPrintable(ok.err));
        QVERIFY(readAll(out) != QByteArray("OLD CONTENT\n"));
    }

private:
    QTemporaryDir dir_;
    QString scene_;
    QString answers_;
};

QTEST_GUILESS_MAIN(TestCliWrites)
#include "tst_cli_writes.moc"
