// Replays, in the normal build (and under the sanitizers in build-asan/), every input
// the scene fuzzer ever crashed on (tests/fuzz_regressions/), and the fuzzer's seeds
// (lessons/*/*.json), through the very function the fuzzer calls: fuzzOneScene().
// A crash here kills the test process, so CTest reports it. docs/reliability.md.
#include "fuzz/fuzz_scene.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QtTest>

class TestFuzzRegressions : public QObject {
    Q_OBJECT
private slots:
    void replay_data();
    void replay();
};

void TestFuzzRegressions::replay_data()
{
    QTest::addColumn<QString>("path");
    const QDir source(QStringLiteral(RBW_SOURCE_DIR));
    int count = 0;
    // Every file of tests/fuzz_regressions/ except its README.
    const QDir regressions(source.filePath(QStringLiteral("tests/fuzz_regressions")));
    for (const QFileInfo& f : regressions.entryInfoList(QDir::Files, QDir::Name)) {
        if (f.fileName() == QLatin1String("README.md")) continue;
        QTest::newRow(qPrintable(QStringLiteral("regression/") + f.fileName())) << f.filePath();
        ++count;
    }
    // The seeds: every lesson scene.
    QDirIterator it(source.filePath(QStringLiteral("lessons")), {QStringLiteral("*.json")}, QDir::Files,
                    QDirIterator::Subdirectories);
    QStringList seeds;
    while (it.hasNext()) seeds << it.next();
    seeds.sort();
    for (const QString& s : seeds) {
        QTest::newRow(qPrintable(QStringLiteral("seed/") + source.relativeFilePath(s))) << s;
        ++count;
    }
    if (count == 0) qFatal("no inputs found under %s", RBW_SOURCE_DIR);
}

void TestFuzzRegressions::replay()
{
    QFETCH(QString, path);
    QFile file(path);
    QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(path + ": " + file.errorString()));
    const QByteArray bytes = file.readAll();
    QCOMPARE(rbw::fuzz::fuzzOneScene(reinterpret_cast<const std::uint8_t*>(bytes.constData()),
                                     static_cast<std::size_t>(bytes.size())),
             0);
}

QTEST_GUILESS_MAIN(TestFuzzRegressions)
#include "tst_fuzz_regressions.moc"
