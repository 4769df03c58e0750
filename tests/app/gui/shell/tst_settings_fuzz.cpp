// Settings can never crash the app (issue 22, item 3). One corrupted value in the
// settings file was a SIGSEGV at every start: QMainWindow::restoreState indexes its
// dock areas with the saved dock position, and 0x7fffffff there reads far outside
// them. The window layout is now sealed (AppSettings: magic, layout version, SHA-256)
// and every value is read as its type or dropped with a note on standard error.
//
// The fuzz loop: deterministic, seeded mutations of a real saved settings file
// (flipped bytes, truncations, huge and negative 32-bit ints written into the state
// and geometry blobs, the blobs without their seal, wrong types for every key, broken
// @Variant/@ByteArray texts). For each, the window is built, opens the remembered
// lesson as main() does, and closes; afterwards the file holds a layout this app
// restores. Controls: the unmutated file restores its layout (a hidden dock stays
// hidden), and the exact file still holds the value that crashed Qt. Two
// starts of the real binary close the loop with the process as a student runs it.
#include "app/gui/shell/app_settings.h"
#include "app/gui/shell/main_window.h"
#include "tests/app/gui/shell/window_test_support.h"

#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QDockWidget>
#include <QFile>
#include <QPoint>
#include <QProcess>
#include <QRandomGenerator>
#include <QRect>
#include <QSettings>
#include <QSize>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace rbw;

namespace {

QString settingsPath() { return QSettings().fileName(); }

QByteArray readFile(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// Writes the settings file and gives it a modification time of its own: QSettings
// re-reads a file only when its size or time changed.
void writeSettings(const QByteArray& bytes)
{
    static qint64 tick = 0;
    QSettings().sync();
    QFile f(settingsPath());
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(bytes);
    f.close();
    QFile touched(settingsPath());
    QVERIFY(touched.open(QIODevice::ReadWrite));
    QVERIFY(touched.setFileTime(QDateTime::fromSecsSinceEpoch(1600000000 + ++tick), QFileDevice::FileModificationTime));
}

void putInt(QByteArray* blob, qsizetype at, quint32 v)
{
    for (int i = 0; i < 4 && at + i < blob->size(); ++i) (*blob)[at + i] = static_cast<char>((v >> (8 * (3 - i))) & 0xffu);
}

// The offset of the first dock area's position in a Qt state blob (Qt 6.4
// QDockAreaLayout::saveState: marker 0xfd, int count, then int position per area).
qsizetype dockPositionOffset(const QByteArray& state)
{
    for (qsizetype i = 8; i + 9 <= state.size(); ++i) {
        if (static_cast<uchar>(state[i]) == 0xfd && state.mid(i + 1, 3) == QByteArray(3, '\0')) return i + 5;
    }
    return -1;
}

const quint32 kHugeInts[] = {0x7fffffffu, 0x80000000u, 0xffffffffu, 0x7ffffffeu, 0x00010000u, 0xfffffffbu};

// One corrupted settings file for `seed`, from `original` (a real saved file);
// *what says which mutation.
QByteArray mutate(const QByteArray& original, quint32 seed, QString* what)
{
    QRandomGenerator rng(seed);
    writeSettings(original);
    const QStringList keys = AppSettings::keys();
    switch (seed % 7) {
    case 0: {   // flipped bytes
        QByteArray b = original;
        const int n = 1 + int(rng.bounded(8));
        for (int k = 0; k < n; ++k) b[qsizetype(rng.bounded(quint32(b.size())))] ^= char(1 + rng.bounded(255));
        *what = QStringLiteral("%1 flipped bytes").arg(n);
        return b;
    }
    case 1: {   // truncated
        const qsizetype at = qsizetype(rng.bounded(quint32(original.size())));
        *what = QStringLiteral("truncated at %1").arg(at);
        return original.left(at);
    }
    case 2:
    case 3: {   // huge or negative ints inside a sealed blob (state, geometry)
        const QString key = seed % 7 == 2 ? QStringLiteral("window/state") : QStringLiteral("window/geometry");
        QByteArray sealed = QSettings().value(key).toByteArray();
        const qsizetype at = 40 + qsizetype(rng.bounded(quint32(std::max<qsizetype>(1, sealed.size() - 44))));
        const QByteArray was = sealed;
        for (quint32 k = rng.bounded(6); sealed == was; ++k) putInt(&sealed, at, kHugeInts[k % 6]);   // one that differs
        QSettings().setValue(key, sealed);
        *what = QStringLiteral("%1: an int at byte %2 of the sealed blob").arg(key).arg(at);
        break;
    }
    case 4: {   // the Qt blob without its seal (an older app's file), with a huge int in it
        const QString key = rng.bounded(2) == 0 ? QStringLiteral("window/state") : QStringLiteral("window/geometry");
        QByteArray raw = AppSettings::unseal(QSettings().value(key).toByteArray(), nullptr).value_or(QByteArray());
        const qsizetype at = qsizetype(rng.bounded(quint32(std::max<qsizetype>(1, raw.size() - 4))));
        const QByteArray was = raw;
        for (quint32 k = rng.bounded(6); raw == was && !raw.isEmpty(); ++k) putInt(&raw, at, kHugeInts[k % 6]);
        QSettings().setValue(key, raw);
        *what = QStringLiteral("%1: unsealed, with a huge int").arg(key);
        break;
    }
    case 5: {   // a value of the wrong type for a key
        const QString key = keys[int(rng.bounded(quint32(keys.size())))];
        QByteArray junk(int(rng.bounded(64)), '\0');
        for (char& c : junk) c = char(rng.bounded(256));
        const QVariant values[] = {QVariant(0x7fffffff), QVariant(-1), QVariant(true), QVariant(3.5),
                                   QVariant(QStringList{"a", "b"}), QVariant(junk), QVariant(QString("garbage")),
                                   QVariant(QPoint(-1, 1 << 30)), QVariant(QSize(-5, 99999999)),
                                   QVariant(QRect(0, 0, -1, -1)), QVariant(QVariantMap{{"a", 1}}),
                                   QVariant(QDateTime::fromSecsSinceEpoch(0))};
        const int v = int(rng.bounded(12));
        QSettings().setValue(key, values[v]);
        *what = QStringLiteral("%1 = a %2").arg(key, QString::fromLatin1(values[v].typeName()));
        break;
    }
    default: {   // a broken serialised value in the file's text
        const char* texts[] = {"@Variant(\\0\\0\\0\\x7f\\xff\\xff\\xff\\xff)", "@ByteArray(\\0\\0\\0\\xff", "@Rect(1 2)",
                               "@Size(99999999999 -5)", "@Point(", "@Invalid()", "@Variant(\\0\\0\\0\\n\\xff\\xff\\xff\\xff\\0)",
                               "\\xff\\xfe\\0\\0"};
        const QString key = keys[int(rng.bounded(quint32(keys.size())))];
        const QByteArray name = key.section('/', 1).toLatin1() + '=';
        QByteArray b = original;
        const qsizetype line = b.indexOf('\n' + name);
        const QByteArray text = texts[rng.bounded(8)];
        if (line >= 0) {
            const qsizetype end = b.indexOf('\n', line + 1);
            b.replace(line + 1 + name.size(), (end < 0 ? b.size() : end) - (line + 1 + name.size()), text);
        }
        *what = QStringLiteral("%1 = %2").arg(key, QString::fromLatin1(text));
        return b;
    }
    }
    QSettings().sync();
    return readFile(settingsPath());
}

} // namespace

class TestSettingsFuzz : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void theSavedLayoutComesBack();
    void theCrashingValueIsRefused();
    void corruptedSettingsNeverCrash();
    void theRealAppStartsWithCorruptedSettings_data();
    void theRealAppStartsWithCorruptedSettings();

private:
    QByteArray original_;   // a real saved settings file: lesson 6, the plot dock hidden, a recent file
    QTemporaryDir dir_;
};

void TestSettingsFuzz::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
    QVERIFY(dir_.isValid());
    QFile scene(dir_.filePath("recent.json"));
    QVERIFY(scene.open(QIODevice::WriteOnly));
    scene.write("{}");
    scene.close();
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("06-box-on-plane"));
    w.findChild<QDockWidget*>("plotDock")->hide();
    AppSettings::setRecentFiles({scene.fileName()});
    w.close();
    QSettings().sync();
    original_ = readFile(settingsPath());
    for (const QString& key : AppSettings::keys()) QVERIFY2(original_.contains(key.section('/', 1).toLatin1() + '='), qPrintable(key));
}

void TestSettingsFuzz::theSavedLayoutComesBack()
{
    writeSettings(original_);
    QCOMPARE(AppSettings::lastLesson(), QString("06-box-on-plane"));
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(!w.findChild<QDockWidget*>("plotDock")->isVisible());
    QVERIFY(w.findChild<QDockWidget*>("lessonsDock")->isVisible());
}

void TestSettingsFuzz::theCrashingValueIsRefused()
{
    writeSettings(original_);
    const QByteArray sealed = QSettings().value("window/state").toByteArray();
    const std::optional<QByteArray> state = AppSettings::unseal(sealed, nullptr);
    QVERIFY(state.has_value());
    const qsizetype at = dockPositionOffset(*state);
    QVERIFY(at > 0);
    QVERIFY(static_cast<uchar>(state->at(at + 3)) < 4);   // a dock position: 0..3 (QInternal::DockPosition)
    // The file: the Qt blob as an older app saved it, with the position 0x7fffffff.
    QByteArray crashing = *state;
    putInt(&crashing, at, 0x7fffffffu);
    // Within the seal the checksum fails; without it the seal is missing. Both refused.
    QByteArray resealedPart = sealed;
    putInt(&resealedPart, 40 + at, 0x7fffffffu);
    QString reason;
    QVERIFY(!AppSettings::unseal(resealedPart, &reason).has_value());
    QVERIFY2(reason.contains("checksum"), qPrintable(reason));
    QVERIFY(!AppSettings::unseal(crashing, &reason).has_value());
    QSettings().setValue("window/state", crashing);
    {
        MainWindow w;   // was SIGSEGV in restoreState
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.findChild<QDockWidget*>("plotDock")->isVisible());   // the default layout
        QVERIFY(!QSettings().contains("window/state"));                 // dropped
    }
    // Negative control: the seal of an unchanged blob opens.
    QCOMPARE(AppSettings::unseal(AppSettings::seal(crashing), nullptr).value_or(QByteArray()), crashing);
}

void TestSettingsFuzz::corruptedSettingsNeverCrash()
{
    const int files = 210;
    QElapsedTimer clock;
    clock.start();
    for (int i = 0; i < files; ++i) {
        QString what;
        const QByteArray corrupted = mutate(original_, quint32(1000 + i), &what);
        QVERIFY2(corrupted != original_ || what.contains("truncated"), qPrintable(what));   // each file is changed
        writeSettings(corrupted);
        {
            MainWindow w;
            if (i % 15 == 0) {   // a few are shown, as main() does
                w.show();
                QVERIFY2(QTest::qWaitForWindowExposed(&w), qPrintable(what));
            }
            if (!w.openLesson(AppSettings::lastLesson())) QVERIFY2(w.openLesson("01-one-step"), qPrintable(what));
            QVERIFY2(w.session()->isLoaded(), qPrintable(what));
            QVERIFY2(w.close(), qPrintable(what));
        }
        // Quit wrote a layout this app restores again.
        QVERIFY2(!AppSettings::windowState().isEmpty(), qPrintable(what));
    }
    qInfo("%d corrupted settings files in %lld ms", files, clock.elapsed());
}

void TestSettingsFuzz::theRealAppStartsWithCorruptedSettings_data()
{
    QTest::addColumn<QString>("kind");
    QTest::newRow("the issue's file: dock position 0x7fffffff") << "dock";
    QTest::newRow("wrong types") << "types";
}

void TestSettingsFuzz::theRealAppStartsWithCorruptedSettings()
{
    QFETCH(QString, kind);
    writeSettings(original_);
    if (kind == "dock") {
        QByteArray state = AppSettings::unseal(QSettings().value("window/state").toByteArray(), nullptr).value_or(QByteArray());
        QVERIFY(dockPositionOffset(state) > 0);
        putInt(&state, dockPositionOffset(state), 0x7fffffffu);
        QSettings().setValue("window/state", state);
    } else {
        QSettings().setValue("lesson/last", 42);
        QSettings().setValue("window/geometry", QStringList{"x"});
        QSettings().setValue("files/recent", QPoint(1, 2));
    }
    QSettings().sync();
    QTemporaryDir config;
    QVERIFY(QDir().mkpath(config.filePath("rigid-workbook")));
    QVERIFY(QFile::copy(settingsPath(), config.filePath("rigid-workbook/Rigid Body Workbook.conf")));
    QProcess app;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("XDG_CONFIG_HOME", config.path());
    app.setProcessEnvironment(env);
    app.start(QStringLiteral(RBW_APP_PATH), {"--measure", "0.2"});
    QVERIFY(app.waitForFinished(60000));
    const QString err = QString::fromLocal8Bit(app.readAllStandardError());
    QCOMPARE(app.exitStatus(), QProcess::NormalExit);
    QVERIFY2(app.exitCode() == 0, qPrintable(err.right(2000)));
    QVERIFY2(err.contains("settings: ") && err.contains("dropped"), qPrintable(err.right(2000)));
    // --measure printed its numbers: the window ran, then quit on its own.
    QVERIFY(app.readAllStandardOutput().contains("\"fps\""));
}

RBW_WINDOW_TEST_MAIN(TestSettingsFuzz)

#include "tst_settings_fuzz.moc"
