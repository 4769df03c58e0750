// The Help menu in the whole window under Xvfb (issue 20): User guide shows
// docs/user-guide.md rendered (headings, not "##"; its screenshots found); About names
// the version, the Qt versions and the licence; Keys lists every key of the window,
// Ctrl+Shift+S (Save scene as) among them, also on a desktop whose key theme has no
// Save As key.
#include "app/core/source_root.h"
#include "app/gui/shell/help_dialogs.h"
#include "app/gui/shell/keys_dialog.h"
#include "app/gui/shell/main_window.h"
#include "tests/app/gui/shell/window_test_support.h"
#include "tests/test_support.h"

#include <QAction>
#include <QDialog>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextDocument>
#include <QtTest>

using namespace rbw;
using namespace rbw::test;

class TestHelpMenu : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void helpMenuHasGuideKeysAbout();
    void userGuideIsRendered();
    void aboutNamesVersionsAndLicence();
    void keysListEveryKeyOfTheWindow();
};

void TestHelpMenu::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
    Warnings::install();
}

void TestHelpMenu::helpMenuHasGuideKeysAbout()
{
    MainWindow w;
    QMenu* help = nullptr;
    for (QAction* a : w.menuBar()->actions()) {
        if (a->text() == QStringLiteral("&Help")) help = a->menu();
    }
    QVERIFY(help != nullptr);
    QStringList names;
    for (QAction* a : help->actions()) names << a->objectName();
    QVERIFY2(names.contains("actionUserGuide") && names.contains("actionKeys") && names.contains("actionAbout"),
             qPrintable(names.join(',')));
}

// The guide found (the source tree's, in a build tree) and shown as Markdown: its
// title is a heading, no line starts with '#', its first screenshot is loaded.
void TestHelpMenu::userGuideIsRendered()
{
    const QString path = userGuidePath();
    QVERIFY2(path.endsWith(QStringLiteral("docs/user-guide.md")), qPrintable(path));
    MainWindow w;
    w.show();
    w.findChild<QAction*>("actionUserGuide")->trigger();
    QDialog* window = nullptr;
    QTRY_VERIFY((window = w.findChild<QDialog*>("userGuideWindow")) != nullptr);
    auto* browser = window->findChild<QTextBrowser*>("userGuideBrowser");
    QVERIFY(browser != nullptr);
    QTextDocument* doc = browser->document();
    QCOMPARE(doc->firstBlock().text(), QStringLiteral("User guide"));
    QCOMPARE(doc->firstBlock().blockFormat().headingLevel(), 1);
    QVERIFY(!browser->toPlainText().contains(QStringLiteral("\n## ")));   // rendered, not the source
    QVERIFY(browser->toPlainText().contains(QStringLiteral("The window")));
    // Its screenshots resolve beside it (negative control: a missing one does not).
    const QVariant image = browser->loadResource(QTextDocument::ImageResource, QUrl("images/guide-lesson1-derivation.png"));
    QVERIFY(image.isValid() && !image.toByteArray().isEmpty());
    QVERIFY(!browser->loadResource(QTextDocument::ImageResource, QUrl("images/no-such-shot.png")).isValid());
    // A second trigger raises the same window.
    w.findChild<QAction*>("actionUserGuide")->trigger();
    QCOMPARE(w.findChildren<QDialog*>("userGuideWindow").size(), qsizetype(1));
    window->close();
}

void TestHelpMenu::aboutNamesVersionsAndLicence()
{
    MainWindow w;
    w.show();
    w.findChild<QAction*>("actionAbout")->trigger();
    QMessageBox* box = nullptr;
    QTRY_VERIFY((box = w.findChild<QMessageBox*>("aboutDialog")) != nullptr);
    const QString text = box->text();
    QVERIFY2(text.contains(QStringLiteral("Rigid Body Workbook")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("Qt %1").arg(QString::fromLatin1(qVersion()))), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("Licence")), qPrintable(text));
    // The version: the project's (CMakeLists.txt: project(... VERSION x.y.z)), a dotted number.
    QVERIFY2(QRegularExpression(QStringLiteral("Workbook \\d+\\.\\d+\\.\\d+")).match(text).hasMatch(), qPrintable(text));
    box->close();
}

// Every action under the window with a key is in Keys, Ctrl+Shift+S among them; and an
// action added later with a key appears without anyone listing it (negative control:
// it was not listed before it had the key).
void TestHelpMenu::keysListEveryKeyOfTheWindow()
{
    MainWindow w;
    w.show();
    QVERIFY(w.openLesson("01-one-step"));
    auto listed = [&w]() {
        w.findChild<QAction*>("actionKeys")->trigger();
        QDialog* dialog = nullptr;
        QTest::qWaitFor([&] { return (dialog = w.findChild<QDialog*>("keysDialog")) != nullptr; }, 2000);
        QStringList keys;
        if (dialog == nullptr) return QStringList{QStringLiteral("(no Keys dialog)")};
        auto* table = dialog->findChild<QTableWidget*>("keysTable");
        for (int r = 0; r < table->rowCount(); ++r) keys << table->item(r, 0)->text() + " = " + table->item(r, 1)->text();
        dialog->close();
        delete dialog;
        return keys;
    };
    QStringList rows = listed();
    const QString all = rows.join('\n');
    QVERIFY2(all.contains(QStringLiteral("Save scene as… = Ctrl+Shift+S")), qPrintable(all));
    int withKeys = 0;
    for (QAction* a : w.findChildren<QAction*>()) {
        for (const QKeySequence& k : a->shortcuts()) {
            QVERIFY2(all.contains(k.toString(QKeySequence::NativeText)), qPrintable(plainActionText(a)));
            ++withKeys;
        }
    }
    QVERIFY(withKeys >= 25);
    QVERIFY(w.findChild<QAction*>("actionSaveSceneAs")->shortcuts().contains(QKeySequence("Ctrl+Shift+S")));

    auto* late = new QAction(QStringLiteral("A late action"), &w);
    QVERIFY(!listed().join('\n').contains(QStringLiteral("A late action")));
    late->setShortcut(QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_J));
    QVERIFY(listed().join('\n').contains(QStringLiteral("A late action = Ctrl+Alt+J")));
}

RBW_WINDOW_TEST_MAIN(TestHelpMenu)

#include "tst_help_menu.moc"
