// The one "start a scene" sequence (LessonController, issue 18): a lesson from the
// list, a scene file, new numbers for a seed and the editor's scene all start the
// same way. Before, the sequence was written four times and the copies disagreed:
// two gave the accuracy panel the lesson's id ("01-one-step"), two its title. Each
// row starts a scene from a running, stepped lesson and checks every part the
// sequence touches. Also: a scene that fails to load leaves the running one, and
// New numbers and the worksheet ask for the seed in the one seed dialog.
#include "app/gui/panels/accuracy/accuracy_panel.h"
#include "app/gui/panels/editor/scene_editor.h"
#include "app/gui/shell/exercise_actions.h"
#include "app/gui/shell/main_window.h"
#include "tests/app/gui/shell/window_test_support.h"

#include <QAction>
#include <QFile>
#include <QInputDialog>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QListWidget>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

#include <limits>

using namespace rbw;

namespace {

// The accuracy panel's "Scene: …" line (the panel shows what it studies there).
QString accuracySceneLine(MainWindow& w)
{
    for (QLabel* label : w.accuracyPanel()->findChildren<QLabel*>()) {
        if (label->text().startsWith(QLatin1String("Scene: "))) return label->text();
    }
    return {};
}

// Lesson 1's scene under another name, as the student's own file.
QString writeOwnScene(const QTemporaryDir& dir, const QString& name)
{
    QFile lesson(QStringLiteral(RBW_SOURCE_DIR "/lessons/01-one-step/scene.json"));
    if (!lesson.open(QIODevice::ReadOnly)) return {};
    QJsonObject scene = QJsonDocument::fromJson(lesson.readAll()).object();
    scene.insert("name", name);
    const QString path = dir.filePath("own.json");
    QFile out(path);
    if (!out.open(QIODevice::WriteOnly)) return {};
    out.write(QJsonDocument(scene).toJson());
    return path;
}

// Accepts (or cancels) the next seed dialog with `text` once it is open.
void answerSeedDialog(const QString& text, bool accept, QString* titleSeen)
{
    QTimer::singleShot(0, [=] {
        auto* dialog = qobject_cast<QInputDialog*>(QApplication::activeModalWidget());
        if (dialog == nullptr || dialog->objectName() != QLatin1String("seedDialog")) {
            answerSeedDialog(text, accept, titleSeen);   // not open yet: look again
            return;
        }
        *titleSeen = dialog->windowTitle();
        dialog->setTextValue(text);
        if (accept) dialog->accept();
        else dialog->reject();
    });
}

} // namespace

class TestLessonController : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void everyOriginStartsTheSameWay_data()
    {
        QTest::addColumn<QString>("origin");
        QTest::addColumn<QString>("title");     // what the window, status line and accuracy panel show
        QTest::addColumn<bool>("lessonRow");    // the list shows a lesson's row (else none, or unchanged)
        QTest::newRow("lesson") << "lesson" << "Two-box collision (corner to face)" << true;
        QTest::newRow("file") << "file" << "My own scene" << false;
        // "Lesson 1, new numbers (seed 7)": LessonController::openNewNumbers.
        QTest::newRow("new numbers") << "numbers" << "Lesson 1, new numbers (seed 7)" << true;
        // New scene from this lesson: "My " and the lesson's title.
        QTest::newRow("editor") << "editor" << "My One Euler step (Table 2.1)" << true;
    }

    void everyOriginStartsTheSameWay()
    {
        QFETCH(QString, origin);
        QFETCH(QString, title);
        QFETCH(bool, lessonRow);
        QTemporaryDir dir;
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.openLesson("01-one-step"));
        for (int k = 0; k < 3; ++k) w.stepOnce();
        w.setPlaying(true);
        QVERIFY(w.findChild<QAction*>("actionPlay")->isChecked());

        if (origin == "lesson") {
            QVERIFY(w.openLesson("03-two-box-collision"));
        } else if (origin == "file") {
            const QString path = writeOwnScene(dir, title);
            QVERIFY(!path.isEmpty());
            QVERIFY(w.openSceneFile(path));
            QCOMPARE(w.sceneEditor()->filePath(), QFileInfo(path).absoluteFilePath());
        } else if (origin == "numbers") {
            QString error;
            QVERIFY2(w.openNewNumbers(7, &error), qPrintable(error));
        } else {
            w.newSceneFromLesson();
        }
        // Every part of the sequence, the same for each origin.
        QCOMPARE(w.currentSceneTitle(), title);
        QCOMPARE(accuracySceneLine(w), QStringLiteral("Scene: %1").arg(title));
        QVERIFY2(w.windowTitle().startsWith(title), qPrintable(w.windowTitle()));
        QVERIFY(w.findChild<QLabel*>("statusLabel")->text().startsWith(title));
        QCOMPARE(w.world()->stepIndex(), 0L);                                // a new run
        QVERIFY(!w.findChild<QAction*>("actionPlay")->isChecked());          // playing stopped
        QCOMPARE(QString::fromStdString(w.sceneEditor()->scene().name), QString::fromStdString(w.world()->scene().name));
        auto* list = w.findChild<QListWidget*>("lessonList");
        if (lessonRow) QCOMPARE(list->currentItem()->data(Qt::UserRole).toString(), w.currentLessonId());
        else QCOMPARE(list->currentRow(), -1);
        // The old copies' bug: two of them named the lesson's id here, not its title.
        if (!w.currentLessonId().isEmpty()) QVERIFY(!accuracySceneLine(w).contains(w.currentLessonId()));
    }

    // A scene that does not load never replaces the running one.
    void aFailedLoadKeepsTheRunningScene()
    {
        QTemporaryDir dir;
        const QString broken = dir.filePath("broken.json");
        QFile f(broken);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("{\"name\": \"broken\", \"bodies\": [");
        f.close();
        MainWindow w;
        QVERIFY(w.openLesson("03-two-box-collision"));
        w.stepOnce();
        const QString line = accuracySceneLine(w);
        QString error;
        QVERIFY(!w.openSceneFile(broken, &error));
        QVERIFY(!error.isEmpty());
        QCOMPARE(w.currentLessonId(), QString("03-two-box-collision"));
        QCOMPARE(w.world()->stepIndex(), 1L);
        QCOMPARE(accuracySceneLine(w), line);
        QVERIFY(w.findChild<QLabel*>("alertLabel")->text().contains("broken.json"));
        QCOMPARE(w.findChild<QListWidget*>("lessonList")->currentItem()->data(Qt::UserRole).toString(),
                 QString("03-two-box-collision"));
    }

    void seedsParse_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("ok");
        QTest::addColumn<quint64>("seed");
        QTest::newRow("plain") << "42" << true << quint64(42);
        QTest::newRow("spaces") << "  7 " << true << quint64(7);
        QTest::newRow("largest") << "18446744073709551615" << true << std::numeric_limits<quint64>::max();
        QTest::newRow("one past") << "18446744073709551616" << false << quint64(0);
        QTest::newRow("negative") << "-1" << false << quint64(0);
        QTest::newRow("words") << "seven" << false << quint64(0);
        QTest::newRow("empty") << "" << false << quint64(0);
    }

    void seedsParse()
    {
        QFETCH(QString, text);
        QFETCH(bool, ok);
        QFETCH(quint64, seed);
        QString error;
        const std::optional<quint64> parsed = ExerciseActions::parseSeed(text, &error);
        QCOMPARE(parsed.has_value(), ok);
        if (ok) QCOMPARE(*parsed, seed);
        else QVERIFY2(error.contains(QStringLiteral("\"%1\"").arg(text)), qPrintable(error));
    }

    // New numbers and the worksheet ask in the same dialog.
    void oneSeedDialogForBoth()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.openLesson("01-one-step"));
        QString title;
        answerSeedDialog("42", true, &title);
        w.findChild<QAction*>("actionNewNumbers")->trigger();
        QCOMPARE(title, QString("New numbers"));
        QCOMPARE(w.currentSceneTitle(), QString("Lesson 1, new numbers (seed 42)"));
        title.clear();
        answerSeedDialog("43", false, &title);   // cancelled: no file dialog follows
        w.findChild<QAction*>("actionExportWorksheet")->trigger();
        QCOMPARE(title, QString("Worksheet"));
        QCOMPARE(w.currentSceneTitle(), QString("Lesson 1, new numbers (seed 42)"));
    }
};

RBW_WINDOW_TEST_MAIN(TestLessonController)

#include "tst_lesson_controller.moc"
