// The code view alone: it opens a file at a line, highlights that line and keeps a
// few lines of context above it on screen; a line out of range highlights nothing;
// a file outside the source tree or missing is refused with the reason in the view.
#include "app/gui/panels/quantities/code_view.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace rbw;

class TestCodeView : public QObject {
    Q_OBJECT
private slots:
    void opensAtTheLine_data();
    void opensAtTheLine();
    void missingFileIsRefused_data();
    void missingFileIsRefused();
};

void TestCodeView::opensAtTheLine_data()
{
    QTest::addColumn<int>("line");
    QTest::addColumn<int>("highlighted");   // 0: none
    QTest::addColumn<int>("firstVisible");
    // 200 lines "line 1" .. "line 200"; kContextLines = 4 above the line.
    QTest::newRow("line 100") << 100 << 100 << 96;
    QTest::newRow("line 3: from the top") << 3 << 3 << 1;
    QTest::newRow("line 0: none") << 0 << 0 << 1;
    QTest::newRow("past the end: none") << 250 << 0 << 1;
}

void TestCodeView::opensAtTheLine()
{
    QFETCH(int, line);
    QFETCH(int, highlighted);
    QFETCH(int, firstVisible);
    QTemporaryDir dir;
    QFile f(dir.filePath("listing.cpp"));
    QVERIFY(f.open(QIODevice::WriteOnly));
    for (int k = 1; k <= 200; ++k) f.write(QStringLiteral("line %1\n").arg(k).toUtf8());
    f.close();

    CodeView view;
    view.resize(600, 400);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QVERIFY(view.showFile(f.fileName(), "listing.cpp", line));
    QCOMPARE(view.highlightedLine(), highlighted);
    QCOMPARE(view.firstVisibleLine(), firstVisible);
    QCOMPARE(view.lineText(100), QString("line 100"));
    if (highlighted > 0) {
        QVERIFY(view.lineOnScreen(highlighted));
        QCOMPARE(view.headerText(), QStringLiteral("listing.cpp:%1").arg(highlighted));
    } else {
        QCOMPARE(view.headerText(), QString("listing.cpp"));
    }
    QVERIFY(!view.lineOnScreen(199));   // negative control: far below is not on screen
}

void TestCodeView::missingFileIsRefused_data()
{
    QTest::addColumn<QString>("relative");
    QTest::newRow("no such file") << "physics/no_such_file.cpp";
    QTest::newRow("outside the tree") << "../outside.cpp";
}

void TestCodeView::missingFileIsRefused()
{
    QFETCH(QString, relative);
    CodeView view;
    QVERIFY(!view.showSource(relative, 10));
    QCOMPARE(view.highlightedLine(), 0);
    QCOMPARE(view.file(), relative);
    QVERIFY(!view.lineText(1).isEmpty());   // the reason
}

QTEST_MAIN(TestCodeView)
#include "tst_code_view.moc"
