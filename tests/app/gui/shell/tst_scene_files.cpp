// The student's own scene files in the app, under Xvfb: open by File → Open (the Qt
// file dialog), by a drop on the window and on the command line (the real binary);
// a broken file or lesson leaves the running scene running under its own name; the
// open file is watched, so saving it in an editor (in place or by rename) reloads it;
// the scene editor's edits change the next step's numbers, are refused with the
// loader's own messages when they break a rule, and save through the scene writer.
//
// Expected numbers are derivations: lesson 1's box (M = 2 kg) is pushed by
// f = (1, 1, 0) N for one step of h = 2 s from rest, so v1 = f h / M = (1, 1, 0) m/s;
// with M = 4 kg, v1 = (0.5, 0.5, 0) m/s.
#include "app/scene/scene_loader.h"
#include "app/scene/scene_writer.h"
#include "app/gui/panels/editor/scene_editor.h"
#include "app/gui/panels/editor/scene_editor_model.h"
#include "app/gui/shell/main_window.h"
#include "app/gui/shell/scene_files.h"
#include "physics/engine/world.h"
#include "tests/test_support.h"

#include <QAbstractItemModelTester>
#include <QAction>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QDialog>
#include <QDir>
#include <QListWidget>
#include <QTimer>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMimeData>
#include <QProcess>
#include <QSaveFile>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTreeView>
#include <QUrl>
#include <QtTest>

#include <cstdio>

using namespace rbw;

namespace {

QByteArray lessonText(const QString& relative)
{
    QFile f(QStringLiteral(RBW_SOURCE_DIR "/lessons/") + relative);
    if (!f.open(QIODevice::ReadOnly)) qFatal("cannot read %s", qPrintable(relative));
    return f.readAll();
}

void writeFile(const QString& path, const QByteArray& text)
{
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(text) != text.size() || !f.commit()) qFatal("cannot write %s", qPrintable(path));
}

// Lesson 1 with another name and mass: a scene that is plainly not lesson 1.
QByteArray myScene(const char* name, const char* mass)
{
    QByteArray text = lessonText("01-one-step/scene.json");
    text.replace("\"name\": \"One Euler step (Table 2.1)\"", QByteArray("\"name\": \"") + name + '"');
    text.replace("\"mass\": 2", QByteArray("\"mass\": ") + mass);
    return text;
}

QList<double> velocityAfterOneStep(MainWindow& w)
{
    w.findChild<QAction*>("actionStep")->trigger();
    return test::flat(w.world()->states()[0].v_W);
}

QLabel* alert(MainWindow& w) { return w.findChild<QLabel*>("alertLabel"); }

} // namespace

class TestSceneFiles : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);   // QSettings go to a test location
        QSettings().clear();
        QVERIFY(dir_.isValid());
    }

    void openByTheMenu()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.openLesson("01-one-step"));
        const QString path = dir_.filePath("menu.json");
        writeFile(path, myScene("Opened by the menu", "4"));

        w.findChild<QAction*>("actionOpenScene")->trigger();
        QFileDialog* dialog = nullptr;
        QTRY_VERIFY((dialog = w.findChild<QFileDialog*>("openSceneDialog")) != nullptr && dialog->isVisible());
        QVERIFY(dialog->testOption(QFileDialog::DontUseNativeDialog));
        dialog->selectFile(path);
        static_cast<QDialog*>(dialog)->accept();   // QFileDialog::accept(), as the Open button

        QCOMPARE(w.currentScenePath(), QFileInfo(path).absoluteFilePath());
        QCOMPARE(w.currentSceneTitle(), QString("Opened by the menu"));
        QVERIFY(w.windowTitle().contains("Opened by the menu"));
        QCOMPARE(w.world()->scene().bodies[0].mass, 4.0);
        QCOMPARE(w.sceneFiles()->watchedPath(), QFileInfo(path).absoluteFilePath());
        // M = 4 kg: v1 = f h / M = (1, 1, 0) * 2 / 4.
        QCOMPARE(velocityAfterOneStep(w), (QList<double>{0.5, 0.5, 0.0}));
        // Recent files: the file is listed first, in the settings and in File → Open recent.
        QCOMPARE(w.sceneFiles()->recentFiles().value(0), QFileInfo(path).absoluteFilePath());
        auto* recent = w.findChild<QMenu*>("recentMenu");
        QVERIFY(recent != nullptr);
        QVERIFY(!recent->actions().isEmpty() && recent->actions().first()->text().contains("menu.json"));
        // ... and the recent entry opens it again, after a lesson.
        QVERIFY(w.openLesson("03-two-box-collision"));
        recent->actions().first()->trigger();
        QCOMPARE(w.currentSceneTitle(), QString("Opened by the menu"));
    }

    // The new File actions take keys no other action has (Ctrl+E was taken by the export).
    void shortcutsAreUnique()
    {
        MainWindow w;
        QHash<QString, QString> owner;
        for (const QAction* a : w.shortcutActions()) {
            for (const QKeySequence& k : a->shortcuts()) {
                const QString key = k.toString(QKeySequence::PortableText);
                QVERIFY2(!owner.contains(key), qPrintable(QStringLiteral("%1: %2 and %3").arg(key, owner.value(key), a->objectName())));
                owner.insert(key, a->objectName());
            }
        }
        for (const char* name : {"actionOpenScene", "actionSaveScene", "actionSaveSceneAs", "actionEditScene"}) {
            QVERIFY2(owner.values().contains(QLatin1String(name)), name);
        }
        QCOMPARE(owner.value("Ctrl+O"), QString("actionOpenScene"));
    }

    void openByDragAndDrop_data()
    {
        QTest::addColumn<QString>("target");
        QTest::newRow("the window") << "";
        QTest::newRow("the 3D view") << "sceneView";
        QTest::newRow("the derivation (a web view)") << "derivationView";
        QTest::newRow("the lesson list") << "lessonList";
    }
    void openByDragAndDrop()
    {
        QFETCH(QString, target);
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.openLesson("01-one-step"));
        QWidget* on = target.isEmpty() ? &w : w.findChild<QWidget*>(target);
        QVERIFY(on != nullptr);
        const QString path = dir_.filePath("dropped.json");
        writeFile(path, myScene("Dropped on the window", "8"));

        // Negative control: a file that is not .json is not taken by the window (a web
        // view takes any drop itself; that is why the window filters the drops of all
        // its widgets).
        QMimeData text;
        text.setUrls({QUrl::fromLocalFile(dir_.filePath("notes.txt"))});
        QDragEnterEvent refused(QPoint(40, 30), Qt::CopyAction, &text, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&w, &refused);
        QVERIFY(!refused.isAccepted());

        QMimeData mime;
        mime.setUrls({QUrl::fromLocalFile(path)});
        QDragEnterEvent enter(QPoint(40, 30), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(on, &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(QPointF(40, 30), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(on, &drop);
        QVERIFY(drop.isAccepted());
        QCOMPARE(w.currentSceneTitle(), QString("Dropped on the window"));
        QCOMPARE(w.currentLessonId(), QString());   // not a lesson
        QCOMPARE(velocityAfterOneStep(w), (QList<double>{0.25, 0.25, 0.0}));   // M = 8 kg
    }

    void droppingALessonFileOpensTheLesson()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.openLesson("01-one-step"));
        QVERIFY(w.openSceneFile(QStringLiteral(RBW_SOURCE_DIR "/lessons/03-two-box-collision/scene.json")));
        QCOMPARE(w.currentLessonId(), QString("03-two-box-collision"));
    }

    // A broken file never replaces the running scene; the message names the file, the
    // field and the reason, and the running scene keeps its own name and numbers.
    void brokenFileKeepsTheRunningScene_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QStringList>("words");
        QTest::newRow("a rule: mass -1") << myScene("Broken", "-1")
                                         << QStringList{"bodies[0].mass", "must be a finite number > 0, got -1"};
        QTest::newRow("malformed JSON") << QByteArray("{ \"dt\": 1,, }") << QStringList{"malformed JSON"};
        QTest::newRow("unknown key") << myScene("Broken", "2").replace("\"mass\"", "\"masss\"")
                                     << QStringList{"bodies[0].masss", "unknown key"};
        QTest::newRow("missing file") << QByteArray() << QStringList{"cannot open"};
    }
    void brokenFileKeepsTheRunningScene()
    {
        QFETCH(QByteArray, text);
        QFETCH(QStringList, words);
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.openLesson("01-one-step"));
        const QString title = w.windowTitle();
        QCOMPARE(velocityAfterOneStep(w), (QList<double>{1.0, 1.0, 0.0}));   // M = 2 kg: f h / M

        const QString path = dir_.filePath(QStringLiteral("broken-%1.json").arg(QTest::currentDataTag()).replace(' ', '-'));
        if (!text.isEmpty()) writeFile(path, text);
        QString error;
        QVERIFY(!w.openSceneFile(path, &error));
        for (const QString& word : words) QVERIFY2(error.contains(word), qPrintable(error));
        QVERIFY(alert(w)->isVisible());
        QVERIFY2(alert(w)->text().contains(path), qPrintable(alert(w)->text()));
        for (const QString& word : words) QVERIFY2(alert(w)->text().contains(word), qPrintable(alert(w)->text()));
        // Still lesson 1, by name and by numbers: step 2 continues lesson 1's run.
        QCOMPARE(w.currentLessonId(), QString("01-one-step"));
        QCOMPARE(w.windowTitle(), title);
        QVERIFY(w.findChild<QLabel*>("statusLabel")->text().startsWith("One Euler step (Table 2.1)"));
        w.findChild<QAction*>("actionStep")->trigger();
        World reference(test::lessonScene("01-one-step/scene.json"));
        reference.step();
        reference.step();
        QCOMPARE(w.world()->stepIndex(), 2L);
        QCOMPARE(test::flat(w.world()->states()[0].x_W), test::flat(reference.states()[0].x_W));
        QCOMPARE(test::flat(w.world()->states()[0].q_WB), test::flat(reference.states()[0].q_WB));
    }

    // The same for a lesson of the list whose scene is broken: the list goes back to
    // the running lesson's row, which keeps its name (it used to take the broken one's).
    void brokenLessonKeepsTheRunningLesson()
    {
        QTemporaryDir lessons;
        QVERIFY(QDir().mkpath(lessons.filePath("01-one-step")) && QDir().mkpath(lessons.filePath("02-broken")));
        writeFile(lessons.filePath("01-one-step/scene.json"), lessonText("01-one-step/scene.json"));
        writeFile(lessons.filePath("02-broken/scene.json"), myScene("A broken lesson", "0"));
        qputenv("RBW_LESSONS_DIR", lessons.path().toLocal8Bit());
        MainWindow w;
        qputenv("RBW_LESSONS_DIR", QByteArray(RBW_SOURCE_DIR "/lessons"));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QCOMPARE(w.lessons().size(), 2);
        QVERIFY(w.openLesson("01-one-step"));
        const QString title = w.windowTitle();
        QVERIFY(!w.openLesson("02-broken"));
        QCOMPARE(w.currentLessonId(), QString("01-one-step"));
        QCOMPARE(w.currentSceneTitle(), QString("One Euler step (Table 2.1)"));
        QCOMPARE(w.windowTitle(), title);
        QCOMPARE(w.findChild<QListWidget*>("lessonList")->currentRow(), 0);
        QVERIFY(alert(w)->text().contains("bodies[0].mass"));
        QVERIFY(alert(w)->text().contains("One Euler step (Table 2.1)"));   // "still running ..."
        QVERIFY(w.findChild<QLabel*>("statusLabel")->text().startsWith("One Euler step (Table 2.1)"));
        QCOMPARE(velocityAfterOneStep(w), (QList<double>{1.0, 1.0, 0.0}));
    }

    // Saving the open file in an editor reloads it: in place, and by writing a new file
    // and renaming it over the old one (after which the path must be watched again).
    void savingTheFileReloadsIt_data()
    {
        QTest::addColumn<bool>("byRename");
        QTest::newRow("in place") << false;
        QTest::newRow("by rename") << true;
    }
    void savingTheFileReloadsIt()
    {
        QFETCH(bool, byRename);
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        const QString path = dir_.filePath(byRename ? "watched-rename.json" : "watched-inplace.json");
        writeFile(path, myScene("Watched", "2"));
        QVERIFY(w.openSceneFile(path));
        auto save = [&](const QByteArray& text) {
            if (byRename) {
                const QString temp = path + ".tmp";
                QFile t(temp);
                QVERIFY(t.open(QIODevice::WriteOnly) && t.write(text) == text.size());
                t.close();
                QVERIFY(std::rename(QFile::encodeName(temp).constData(), QFile::encodeName(path).constData()) == 0);
            } else {
                QFile f(path);
                QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(text) == text.size());
            }
        };
        save(myScene("Watched", "4"));
        QTRY_COMPARE_WITH_TIMEOUT(w.world()->scene().bodies[0].mass, 4.0, 5000);
        QCOMPARE(velocityAfterOneStep(w), (QList<double>{0.5, 0.5, 0.0}));
        // A second save: after a rename, the new file is watched too.
        save(myScene("Watched again", "8"));
        QTRY_COMPARE_WITH_TIMEOUT(w.currentSceneTitle(), QString("Watched again"), 5000);
        QCOMPARE(w.world()->scene().bodies[0].mass, 8.0);
        // A broken save: the error is shown, the last good scene keeps running.
        save(myScene("Watched, broken", "-1"));
        QTRY_VERIFY_WITH_TIMEOUT(alert(w)->isVisible(), 5000);
        QVERIFY(alert(w)->text().contains("bodies[0].mass"));
        QCOMPARE(w.currentSceneTitle(), QString("Watched again"));
        QCOMPARE(w.world()->scene().bodies[0].mass, 8.0);
        // Fixed again: it reloads, and the message goes.
        save(myScene("Watched, fixed", "2"));
        QTRY_COMPARE_WITH_TIMEOUT(w.currentSceneTitle(), QString("Watched, fixed"), 5000);
        QVERIFY(!alert(w)->isVisible());
    }

    // Editing a mass in the editor (typed into the view, as a student does) changes
    // the next step's numbers.
    void editingAMassChangesTheNextStep()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.openLesson("01-one-step"));
        w.findChild<QAction*>("actionEditScene")->trigger();
        SceneEditor* editor = w.sceneEditor();
        QTreeView* view = editor->view();
        const QModelIndex mass = editor->model()->indexOfPath("bodies[0].mass");
        QVERIFY(mass.isValid());
        QCOMPARE(mass.data().toString(), QString("2"));
        view->scrollTo(mass);
        view->setCurrentIndex(mass);
        view->edit(mass);
        QLineEdit* field = nullptr;
        QTRY_VERIFY((field = view->findChild<QLineEdit*>()) != nullptr && field->isVisible());
        field->selectAll();
        QTest::keyClicks(field, "4");
        QTest::keyClick(field, Qt::Key_Return);
        QTRY_COMPARE(w.world()->scene().bodies[0].mass, 4.0);
        QCOMPARE(w.world()->stepIndex(), 0L);   // the edited scene starts at t = 0
        QCOMPARE(w.currentSceneTitle(), QString("One Euler step (Table 2.1)"));
        QCOMPARE(velocityAfterOneStep(w), (QList<double>{0.5, 0.5, 0.0}));   // f h / M with M = 4

        // A value that breaks a rule is not applied; the message is the loader's own.
        QVERIFY(editor->model()->setData(editor->model()->indexOfPath("bodies[0].mass"), "-1"));
        QCOMPARE(w.world()->scene().bodies[0].mass, 4.0);
        QCOMPARE(w.world()->stepIndex(), 1L);   // the running scene was not touched
        const SceneLoadResult loader = parseScene(myScene("x", "-1"), "f.json");
        QVERIFY(!loader.ok());
        QCOMPARE(editor->issues(), QStringList{loader.errors.first().mid(QString("f.json: ").size())});
        // A value that cannot be read is refused at once.
        QSignalSpy refused(editor->model(), &SceneEditorModel::editRefused);
        QVERIFY(!editor->model()->setData(editor->model()->indexOfPath("dt"), "two"));
        QCOMPARE(refused.size(), 1);
        QVERIFY(refused.first().first().toString().startsWith("dt: must be a finite number"));
        // Fixed, it applies again.
        QVERIFY(editor->model()->setData(editor->model()->indexOfPath("bodies[0].mass"), "8"));
        QCOMPARE(velocityAfterOneStep(w), (QList<double>{0.25, 0.25, 0.0}));
    }

    // Each kind of value typed into the editor lands in the scene, as the scene file
    // would say it (compared through the scene writer's JSON).
    void editorEditsLandInTheScene_data()
    {
        QTest::addColumn<QString>("lesson");
        QTest::addColumn<QString>("path");
        QTest::addColumn<QString>("typed");
        QTest::addColumn<QString>("jsonPath");
        QTest::addColumn<QByteArray>("expected");
        auto row = [](const char* name, const char* lesson, const char* path, const char* typed, const char* json,
                      const char* expected) {
            QTest::newRow(name) << QString(lesson) << QString(path) << QString(typed) << QString(json) << QByteArray(expected);
        };
        row("dt", "01-one-step/scene.json", "dt", "0.005", "dt", "0.005");
        row("steps", "01-one-step/scene.json", "steps", "12", "steps", "12");
        row("gravity", "01-one-step/scene.json", "gravity", "0, -9.81, 0", "gravity", "[0,-9.81,0]");
        row("size in brackets", "01-one-step/scene.json", "bodies[0].size", "[1 2 3]", "bodies[0].size", "[1,2,3]");
        row("orientation, normalised", "01-one-step/scene.json", "bodies[0].orientation", "2, 0, 0, 2",
            "bodies[0].orientation.quaternion", "[0.7071067811865475,0,0,0.7071067811865475]");   // 2 / fl(sqrt 8)
        row("angular velocity", "01-one-step/scene.json", "bodies[0].angular_velocity", "0, 0, 3",
            "bodies[0].angular_velocity", "[0,0,3]");
        row("a body's integrator", "01-one-step/scene.json", "bodies[0].integrator", "rk4", "bodies[0].integrator", "\"rk4\"");
        row("the scene's integrator", "01-one-step/scene.json", "integrator", "midpoint", "integrator", "\"midpoint\"");
        row("force lifetime", "01-one-step/scene.json", "forces[0].to_step", "5", "forces[0].to_step", "5");
        row("probe point", "01-one-step/scene.json", "probes[0].point", "1, 1, 1", "probes[0].point", "[1,1,1]");
        row("plane normal, normalised", "07-bounce/scene.json", "planes[0].normal", "0, 2, 0", "planes[0].normal", "[0,1,0]");
        row("pair friction", "07-bounce/scene.json", "pairs[2].friction", "0.25", "pairs[2].friction", "0.25");
        row("plane contacts", "07-bounce/scene.json", "plane_contacts", "per-point", "plane_contacts", "\"per-point\"");
        row("restitution", "07-bounce/scene.json", "restitution", "0.5", "restitution", "0.5");
    }
    void editorEditsLandInTheScene()
    {
        QFETCH(QString, lesson);
        QFETCH(QString, path);
        QFETCH(QString, typed);
        QFETCH(QString, jsonPath);
        QFETCH(QByteArray, expected);
        SceneEditorModel model;
        QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
        model.setScene(test::lessonScene(lesson));
        const QModelIndex index = model.indexOfPath(path);
        QVERIFY2(index.isValid(), qPrintable(path));
        QVERIFY(model.flags(index) & Qt::ItemIsEditable);
        QVERIFY(model.setData(index, typed));
        QJsonValue v = sceneToJson(model.scene());
        QString rest = jsonPath;
        rest.replace('[', QStringLiteral(".["));
        for (const QString& part : rest.split('.')) {
            v = part.startsWith('[') ? v.toArray().at(part.mid(1, part.size() - 2).toInt()) : v.toObject().value(part);
        }
        const QJsonValue want = QJsonDocument::fromJson("[" + expected + "]").array().at(0);
        QVERIFY2(v == want, qPrintable(QString::fromUtf8(QJsonDocument(QJsonArray{v}).toJson(QJsonDocument::Compact))));
        QVERIFY(validate(model.scene()).empty());
    }

    // A quaternion or normal typed into the editor becomes what the loader reads from
    // the same numbers in a file, bit for bit.
    void editorNormalisesAsTheLoader()
    {
        const QByteArray text = lessonText("07-bounce/scene.json")
                                    .replace("\"orientation\": { \"axis\": [0, 0, 1], \"degrees\": 25 }, \"angular_response\"",
                                             "\"orientation\": { \"quaternion\": [3, 1, -2, 0.5] }, \"angular_response\"")
                                    .replace("\"normal\": [0, 1, 0]", "\"normal\": [0.3, 2, -0.1]");
        const SceneLoadResult loaded = parseScene(text, "q.json");
        QVERIFY2(loaded.ok(), qPrintable(loaded.errors.join('\n')));
        SceneEditorModel model;
        model.setScene(test::lessonScene("07-bounce/scene.json"));
        QVERIFY(model.setData(model.indexOfPath("bodies[0].orientation"), "3, 1, -2, 0.5"));
        QVERIFY(model.setData(model.indexOfPath("planes[0].normal"), "0.3, 2, -0.1"));
        QCOMPARE(test::flat(model.scene().bodies[0].q0_WB), test::flat(loaded.scene->bodies[0].q0_WB));
        QCOMPARE(test::flat(model.scene().planes[0].n_W), test::flat(loaded.scene->planes[0].n_W));
        QVERIFY(sceneDifferences(model.scene(), *loaded.scene).isEmpty());
    }

    // Adding and removing elements keeps the model consistent (QAbstractItemModelTester)
    // and the references right: a force on a removed body keeps its name for the message.
    void editorAddsAndRemoves()
    {
        SceneEditorModel model;
        QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
        model.setScene(test::lessonScene("03-two-box-collision/scene.json"));
        for (int g = SceneEditorModel::Bodies; g < SceneEditorModel::GroupCount; ++g) {
            const QModelIndex added = model.addElement(static_cast<SceneEditorModel::Group>(g));
            QVERIFY(added.isValid());
        }
        QCOMPARE(model.scene().bodies.size(), std::size_t(3));
        QCOMPARE(model.scene().bodies[2].name, std::string("body2"));
        std::vector<SceneIssue> issues = validate(model.scene());
        QVERIFY2(issues.empty(), issues.empty() ? "" : issues.front().reason.c_str());
        // Remove body A (index 0): the new force, torque, probe and pair named it.
        QVERIFY(model.removeElement(model.index(0, 0, model.index(SceneEditorModel::Bodies, 0))));
        QCOMPARE(model.scene().bodies.size(), std::size_t(2));
        QCOMPARE(model.scene().bodies[0].name, std::string("B"));
        QCOMPARE(model.scene().forces[0].body, -1);
        issues = validate(model.scene());
        bool named = false;
        for (const SceneIssue& i : issues) named = named || (i.path == "forces[0].body" && i.reason.find("\"A\"") != std::string::npos);
        QVERIFY(named);
    }

    // Save As writes the edited scene through the scene writer; it reads back equal,
    // becomes the watched file, and the app's own write does not reload it.
    void saveWritesTheEditedScene()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.openLesson("03-two-box-collision"));
        w.findChild<QAction*>("actionNewSceneFromLesson")->trigger();
        SceneEditorModel* model = w.sceneEditor()->model();
        QVERIFY(model->setData(model->indexOfPath("bodies[1].linear_velocity"), "0, -2, 0"));
        QVERIFY(w.sceneEditor()->isModified());
        QVERIFY(w.currentSceneTitle().startsWith("My "));
        w.findChild<QAction*>("actionStep")->trigger();
        const QString path = dir_.filePath("saved.json");
        QString error;
        QVERIFY2(w.saveSceneTo(path, &error), qPrintable(error));
        QVERIFY(!w.sceneEditor()->isModified());
        const SceneLoadResult back = loadSceneFile(path);
        QVERIFY2(back.ok(), qPrintable(back.errors.join('\n')));
        QVERIFY(sceneDifferences(w.sceneEditor()->scene(), *back.scene).isEmpty());
        QCOMPARE(back.scene->bodies[1].v0_W, Vec3(0, -2, 0));
        QCOMPARE(w.sceneFiles()->watchedPath(), QFileInfo(path).absoluteFilePath());
        QCOMPARE(w.currentScenePath(), QFileInfo(path).absoluteFilePath());
        QTest::qWait(600);   // longer than the watcher settles
        QCOMPARE(w.world()->stepIndex(), 1L);   // not reloaded by its own write
        // Save again, with another edit: File → Save writes the same file.
        QVERIFY(model->setData(model->indexOfPath("restitution"), "0.5"));
        w.findChild<QAction*>("actionSaveScene")->trigger();
        QCOMPARE(loadSceneFile(path).scene->restitution, 0.5);
        // A scene with problems is never saved; the file keeps the last good one.
        QVERIFY(model->setData(model->indexOfPath("dt"), "0"));
        QTimer::singleShot(0, [] {
            if (auto* box = qobject_cast<QDialog*>(QApplication::activeModalWidget())) box->reject();
        });
        QVERIFY(!w.saveSceneTo(path, &error));
        QVERIFY2(error.contains("dt: must be a finite number > 0"), qPrintable(error));
        QCOMPARE(loadSceneFile(path).scene->restitution, 0.5);
    }

    // The real binary: what was asked for and cannot be opened is an error on stderr
    // with exit status 2, never a silent start on lesson 1.
    void commandLine_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QStringList>("words");
        const QString broken = dir_.filePath("cli-broken.json");
        writeFile(broken, myScene("Broken", "-1"));
        const QString good = dir_.filePath("cli-good.json");
        writeFile(good, myScene("Good", "3"));
        const QString missing = dir_.filePath("no-such.json");
        QTest::newRow("missing file") << QStringList{missing} << 2 << QStringList{missing, "cannot open"};
        QTest::newRow("broken file") << QStringList{broken} << 2
                                     << QStringList{broken, "bodies[0].mass", "must be a finite number > 0, got -1"};
        QTest::newRow("--lesson with a broken file") << QStringList{"--lesson", broken} << 2
                                                     << QStringList{broken, "bodies[0].mass"};
        QTest::newRow("--lesson unknown id") << QStringList{"--lesson", "99-nope"} << 2
                                             << QStringList{"unknown lesson \"99-nope\"", "01-one-step"};
        QTest::newRow("two files") << QStringList{good, broken} << 2 << QStringList{"at most one scene file"};
        // Positive controls: what opens, runs (--measure quits by itself).
        QTest::newRow("good file") << QStringList{good, "--measure", "0.2"} << 0 << QStringList{};
        QTest::newRow("--lesson id") << QStringList{"--lesson", "07-bounce/impulses", "--measure", "0.2"} << 0
                                     << QStringList{};
    }
    void commandLine()
    {
        QFETCH(QStringList, args);
        QFETCH(int, exitCode);
        QFETCH(QStringList, words);
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("QTWEBENGINE_DISABLE_SANDBOX", "1");
        env.insert("XDG_CONFIG_HOME", dir_.filePath("config"));   // the app's settings stay out of the user's
        p.setProcessEnvironment(env);
        p.start(QStringLiteral(RBW_APP_PATH), QStringList{"-platform", "xcb"} + args);
        QVERIFY(p.waitForFinished(60000));
        const QString err = QString::fromLocal8Bit(p.readAllStandardError());
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QVERIFY2(p.exitCode() == exitCode, qPrintable(QStringLiteral("exit %1\n%2").arg(p.exitCode()).arg(err)));
        for (const QString& word : words) QVERIFY2(err.contains("rigid-workbook: ") && err.contains(word), qPrintable(err));
        if (exitCode == 0) QVERIFY2(!err.contains("rigid-workbook: "), qPrintable(err));
    }

private:
    QTemporaryDir dir_;
};

QTEST_MAIN(TestSceneFiles)
#include "tst_scene_files.moc"
