// What `rigid-workbook --lesson ARG` and `rigid-workbook FILE` name
// (resolveLessonArgument, app/core/lesson_catalogue.h): a lesson by id, a lesson by its
// own file, a scene file, or an error that says why, never a silent lesson 1.
#include "app/core/lesson_catalogue.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

using namespace rbw;

class TestLessonArgument : public QObject {
    Q_OBJECT
private slots:
    void resolves_data()
    {
        QTest::addColumn<QString>("argument");
        QTest::addColumn<QString>("lessonId");
        QTest::addColumn<bool>("isFile");
        QTest::addColumn<QString>("errorWords");
        QVERIFY(dir_.isValid());
        QFile own(dir_.filePath("own.json"));
        QVERIFY(own.open(QIODevice::WriteOnly));
        own.write("{}");   // not loaded here: resolving only finds the file
        own.close();
        const QString lessons = QStringLiteral(RBW_SOURCE_DIR "/lessons");
        QTest::newRow("lesson id") << "01-one-step" << "01-one-step" << false << "";
        QTest::newRow("variant id") << "07-bounce/impulses" << "07-bounce/impulses" << false << "";
        QTest::newRow("a lesson's own file") << lessons + "/03-two-box-collision/scene.json" << "03-two-box-collision"
                                             << false << "";
        QTest::newRow("a variant's own file") << lessons + "/04-many-boxes/fifty-boxes.json" << "04-many-boxes/fifty-boxes"
                                              << false << "";
        QTest::newRow("the student's file") << dir_.filePath("own.json") << "" << true << "";
        QTest::newRow("unknown id") << "99-nope" << "" << false << "unknown lesson \"99-nope\"; give a lesson id (01-one-step";
        QTest::newRow("missing file") << dir_.filePath("none.json") << "" << false << "none.json: cannot open: no such file";
        QTest::newRow("a folder") << dir_.path() + "/" << "" << false << "cannot open: not a file";
    }
    void resolves()
    {
        QFETCH(QString, argument);
        QFETCH(QString, lessonId);
        QFETCH(bool, isFile);
        QFETCH(QString, errorWords);
        const QList<Lesson> lessons = lessonCatalogue(QStringLiteral(RBW_SOURCE_DIR "/lessons"));
        const LessonArgument r = resolveLessonArgument(argument, lessons);
        QCOMPARE(r.lessonId, lessonId);
        QCOMPARE(r.file.isEmpty(), !isFile);
        if (isFile) QCOMPARE(r.file, QFileInfo(argument).absoluteFilePath());
        QCOMPARE(r.ok(), errorWords.isEmpty());
        QVERIFY2(r.error.contains(errorWords), qPrintable(r.error));
        // Variants are not offered as ids in the message; lessons are.
        if (!r.ok() && r.error.contains("unknown lesson")) QVERIFY(!r.error.contains("fifty-boxes"));
    }

private:
    QTemporaryDir dir_;
};

QTEST_GUILESS_MAIN(TestLessonArgument)
#include "tst_lesson_argument.moc"
