// Where the app finds the source tree for its code view: RBW_SOURCE_ROOT first, then
// the tree it was built from; and a relative path from a trace entry never leaves
// the tree.
#include "app/core/source_root.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

using namespace rbw;

class TestSourceRoot : public QObject {
    Q_OBJECT
private slots:
    void init() { qunsetenv("RBW_SOURCE_ROOT"); }
    void cleanup() { qunsetenv("RBW_SOURCE_ROOT"); }
    void builtTreeByDefault();
    void environmentFirst();
    void missingEnvironmentDirectoryIsIgnored();
    void filePaths_data();
    void filePaths();
};

void TestSourceRoot::builtTreeByDefault()
{
    QCOMPARE(sourceRoot(), QDir::cleanPath(QStringLiteral(RBW_SOURCE_DIR)));
}

void TestSourceRoot::environmentFirst()
{
    QTemporaryDir tree;
    QVERIFY(tree.isValid());
    QVERIFY(QDir(tree.path()).mkpath("physics"));
    QFile f(tree.path() + "/physics/x.cpp");
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("// x <- x + h v\n");
    f.close();
    qputenv("RBW_SOURCE_ROOT", tree.path().toLocal8Bit());
    QCOMPARE(sourceRoot(), QDir::cleanPath(tree.path()));
    QCOMPARE(sourceFilePath("physics/x.cpp"), QDir::cleanPath(tree.path()) + "/physics/x.cpp");
    // The built tree's files are not found through the other root.
    QVERIFY(sourceFilePath("physics/engine/world.cpp").isEmpty());
}

void TestSourceRoot::missingEnvironmentDirectoryIsIgnored()
{
    qputenv("RBW_SOURCE_ROOT", "/no/such/directory/anywhere");
    QCOMPARE(sourceRoot(), QDir::cleanPath(QStringLiteral(RBW_SOURCE_DIR)));
}

void TestSourceRoot::filePaths_data()
{
    QTest::addColumn<QString>("relative");
    QTest::addColumn<bool>("found");
    QTest::newRow("a physics file") << "physics/engine/world.cpp" << true;
    QTest::newRow("an integrator") << "physics/engine/integrators/explicit_euler.cpp" << true;
    QTest::newRow("no such file") << "physics/no_such_file.cpp" << false;
    QTest::newRow("a directory") << "physics" << false;
    QTest::newRow("out of the tree") << "../../../etc/passwd" << false;
    QTest::newRow("absolute") << "/etc/passwd" << false;
    QTest::newRow("empty") << "" << false;
}

void TestSourceRoot::filePaths()
{
    QFETCH(QString, relative);
    QFETCH(bool, found);
    const QString path = sourceFilePath(relative);
    QCOMPARE(!path.isEmpty(), found);
    if (found) QCOMPARE(path, QDir::cleanPath(QStringLiteral(RBW_SOURCE_DIR "/") + relative));
}

QTEST_GUILESS_MAIN(TestSourceRoot)
#include "tst_source_root.moc"
