// "Check my numbers" (app/gui/panels/check/): the table of a step's quantities with the
// student's entries, coloured by the checker's verdicts, "What's wrong?", "Next step",
// the entries kept per lesson and step, and saving / loading them as an answers file.
//
// The wrong numbers are made here from the step's own trace, the way the student who
// makes the mistake would: lesson 8's box "standard" at step 0, with R, I0^-1 and L
// read from the trace, gives
//   the wrong  I^-1 = R^T I0^-1 R           (the transposed-inertia mistake),
//   the wrong  omega = R^T I0^-1 R L        (the omega that mistake gives),
// while the workbook's omega = R I0^-1 R^T L is the trace's angular_velocity
// (tst_checker checks the same chain against the checker alone).
#include "app/core/session.h"
#include "app/gui/panels/check/check_model.h"
#include "app/gui/panels/check/check_panel.h"
#include "app/gui/shell/main_window.h"
#include "app/gui/panels/view/scene_view.h"
#include "tests/test_support.h"

#include <QAbstractItemModelTester>
#include <QDockWidget>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QAction>
#include <QApplication>
#include <QSignalSpy>
#include <QSettings>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTableView>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

using namespace rbw;
using rbw::test::lessonScene;
using State = CheckModel::RowState;

namespace {

QString vecText(const Vec3& v, int digits)
{
    return QStringLiteral("(%1, %2, %3)")
        .arg(QString::number(v.x(), 'g', digits), QString::number(v.y(), 'g', digits), QString::number(v.z(), 'g', digits));
}

QString matText(const Mat3& m)
{
    QStringList rows;
    for (int i = 0; i < 3; ++i) {
        rows << QStringLiteral("%1 %2 %3")
                    .arg(QString::number(m(i, 0), 'g', 10), QString::number(m(i, 1), 'g', 10), QString::number(m(i, 2), 'g', 10));
    }
    return rows.join(QStringLiteral("; "));
}

// Lesson 8 after one step, with the panel showing it.
struct Lesson8 {
    Session session;
    CheckPanel panel;
    Mat3 IinvT;     // R^T I0^-1 R: the transposed inverse inertia
    Vec3 omegaT;    // R^T I0^-1 R L: the omega it gives
    Vec3 omega;     // the workbook's omega (the trace's)
    int iinvRow = -1;
    int omegaRow = -1;

    Lesson8()
    {
        session.load(lessonScene("08-conventions/scene.json"));
        session.step();   // step 0
        const StepTrace& t = *session.currentTrace();
        const Mat3 R = std::get<Mat3>(t.find("rotation_matrix", 0)->value);
        const Mat3 I0inv = std::get<Mat3>(t.find("inverse_inertia_body", 0)->value);
        const Vec3 L = std::get<Vec3>(t.find("angular_momentum", 0)->value);
        IinvT = R.transpose() * I0inv * R;
        omegaT = IinvT * L;
        omega = std::get<Vec3>(t.find("angular_velocity", 0)->value);
        panel.setStep("08-conventions", session.worldBeforeCurrentStep(), &t, session.world()->scene());
        iinvRow = panel.model()->rowOf("inverse_inertia_world", 0);
        omegaRow = panel.model()->rowOf("angular_velocity", 0);
    }
    CheckModel* model() const { return panel.model(); }
    // Types into a "Yours" cell through the model's edit role, as the cell editor does.
    void type(int row, const QString& text) { QVERIFY(model()->setData(model()->index(row, CheckModel::YoursColumn), text)); }
    QString mark(int row) const { return model()->index(row, CheckModel::MarkColumn).data().toString(); }
    QColor colour(int row) const
    {
        return model()->index(row, CheckModel::YoursColumn).data(Qt::BackgroundRole).value<QBrush>().color();
    }
};

} // namespace

class TestCheckPanel : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void listsTheStepsQuantities();
    void verdicts_data();
    void verdicts();
    void typingIntoTheCell();
    void unreadableEntry();
    void nextStepSelectsFirstEmpty();
    void saveAndLoad();
    void keptPerLessonAndStep();
    void loadRefusesWhatCheckRefuses_data();
    void loadRefusesWhatCheckRefuses();
    void typingOwnsTheKeyboard();
    void slipHints_data();
    void slipHints();
    void stepsCountedFromOne();
};

void TestCheckPanel::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
}

void TestCheckPanel::listsTheStepsQuantities()
{
    Lesson8 l;
    QAbstractItemModelTester tester(l.model(), QAbstractItemModelTester::FailureReportingMode::QtTest);
    QVERIFY(l.model()->rowCount() > 10);
    QVERIFY(l.iinvRow >= 0);
    QVERIFY(l.omegaRow >= 0);
    // Table order is the trace's: I^-1 is computed (and listed) before omega = I^-1 L.
    QVERIFY(l.iinvRow < l.omegaRow);
    QCOMPARE(l.model()->index(l.omegaRow, CheckModel::OfColumn).data().toString(), QString("standard"));
    QVERIFY(l.model()->index(l.omegaRow, CheckModel::QuantityColumn).data().toString().contains("angular_velocity"));
    QCOMPARE(l.model()->firstEmptyRow(), 0);   // nothing typed yet

    // Before the first step there is nothing to check.
    Session s;
    s.load(lessonScene("08-conventions/scene.json"));
    CheckPanel empty;
    empty.setStep("08-conventions", s.worldBeforeCurrentStep(), s.currentTrace(), s.world()->scene());
    QCOMPARE(empty.model()->rowCount(), 0);
}

void TestCheckPanel::verdicts_data()
{
    QTest::addColumn<bool>("wrongIinvFirst");   // type R^T I0^-1 R into I^-1 (an earlier row) first
    QTest::addColumn<int>("omegaKind");         // 0: R^T I0^-1 R L, 1: the trace's omega to 4 figures
    QTest::addColumn<int>("state");
    QTest::addColumn<QString>("markSign");
    QTest::addColumn<QString>("mistake");       // named by What's wrong?, "" for none
    // omega = R^T I0^-1 R L alone: wrong, and it is the transposed-inertia mistake.
    QTest::newRow("transposed omega") << false << 0 << int(State::Wrong) << QString::fromUtf8("✗") << "transposed-inertia";
    // The same omega after the wrong I^-1 = R^T I0^-1 R: it is I^-1 L of the student's own
    // I^-1, so it follows from that earlier error (amber).
    QTest::newRow("omega after wrong I^-1") << true << 0 << int(State::FollowsFromEarlier) << QString::fromUtf8("↪") << "";
    // Negative control: the workbook's omega to 4 significant figures is right.
    QTest::newRow("right omega") << false << 1 << int(State::Correct) << QString::fromUtf8("✓") << "";
}

void TestCheckPanel::verdicts()
{
    QFETCH(bool, wrongIinvFirst);
    QFETCH(int, omegaKind);
    QFETCH(int, state);
    QFETCH(QString, markSign);
    QFETCH(QString, mistake);
    Lesson8 l;
    if (wrongIinvFirst) {
        l.type(l.iinvRow, matText(l.IinvT));
        QCOMPARE(l.model()->rowState(l.iinvRow), State::Wrong);
    }
    l.type(l.omegaRow, omegaKind == 0 ? vecText(l.omegaT, 10) : vecText(l.omega, 4));
    QCOMPARE(int(l.model()->rowState(l.omegaRow)), state);
    // Colour and, for colour-blind readers, a sign and a word in the Mark column.
    QVERIFY(l.mark(l.omegaRow).startsWith(markSign));
    const QColor c = l.colour(l.omegaRow);
    if (state == int(State::Wrong)) QVERIFY(c.red() > c.green() + 30);                      // red
    if (state == int(State::Correct)) QVERIFY(c.green() > c.red() + 30);                    // green
    if (state == int(State::FollowsFromEarlier)) QVERIFY(c.red() > c.blue() + 60 && c.green() > c.blue() + 60);   // amber

    // What's wrong? on the entry.
    l.panel.view()->setCurrentIndex(l.model()->index(l.omegaRow, CheckModel::YoursColumn));
    auto* button = l.panel.findChild<QPushButton*>("whatsWrongButton");
    QCOMPARE(button->isEnabled(), state != int(State::Correct));
    l.panel.showWhatsWrong();
    const QString html = l.panel.explanationHtml();
    const QStringList ids = l.model()->index(l.omegaRow, 0).data(CheckModel::MistakesRole).toStringList();
    if (mistake.isEmpty()) {
        QVERIFY2(!ids.contains("transposed-inertia"), qPrintable(ids.join(',')));
        QVERIFY(!html.contains("transposed-inertia"));
    } else {
        QVERIFY2(ids.contains(mistake), qPrintable(ids.join(',')));
        QVERIFY(html.contains(mistake));
        QVERIFY(html.contains(QString::fromUtf8(findMistake(mistake.toStdString())->equation).toHtmlEscaped()) ||
                html.contains("I⁻¹"));
        // The workbook's number is shown: its first component to 7 figures.
        QVERIFY2(html.contains(QString::number(l.omega.x(), 'g', 7)), qPrintable(html));
    }
}

// The cell editor path: select the cell, type, press Enter.
void TestCheckPanel::typingIntoTheCell()
{
    Lesson8 l;
    l.panel.resize(900, 600);
    l.panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&l.panel));
    QTableView* view = l.panel.view();
    const QModelIndex cell = l.model()->index(l.omegaRow, CheckModel::YoursColumn);
    view->scrollTo(cell);
    view->setCurrentIndex(cell);
    view->edit(cell);
    auto* editor = view->findChild<QLineEdit*>();
    QVERIFY(editor != nullptr);
    QTest::keyClicks(editor, vecText(l.omegaT, 10));
    QTest::keyClick(editor, Qt::Key_Return);   // the delegate commits in a queued call
    QTRY_COMPARE(l.model()->rowState(l.omegaRow), State::Wrong);
    QCOMPARE(cell.data().toString(), vecText(l.omegaT, 10));
}

void TestCheckPanel::unreadableEntry()
{
    Lesson8 l;
    l.type(l.omegaRow, "(-2.4, 4.9.1, 0)");
    QCOMPARE(l.model()->rowState(l.omegaRow), State::Unreadable);
    QVERIFY(l.mark(l.omegaRow).contains("cannot read '4.9.1'"));
    l.type(l.omegaRow, "(1, 2)");
    QVERIFY(l.mark(l.omegaRow).contains("3 numbers expected, got 2"));
    // An unreadable entry is not an earlier answer: the row after it is still checked.
    l.type(l.omegaRow, "");
    QCOMPARE(l.model()->rowState(l.omegaRow), State::Empty);
    QCOMPARE(l.mark(l.omegaRow), QString());
}

void TestCheckPanel::nextStepSelectsFirstEmpty()
{
    Lesson8 l;
    l.type(0, "0");
    l.type(1, "0");
    QCOMPARE(l.model()->firstEmptyRow(), 2);
    QVERIFY(l.panel.selectNextEmpty());
    QCOMPARE(l.panel.view()->currentIndex().row(), 2);
    QCOMPARE(l.panel.view()->currentIndex().column(), int(CheckModel::YoursColumn));
}

void TestCheckPanel::saveAndLoad()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("answers.json");
    {
        Lesson8 l;
        l.type(l.iinvRow, matText(l.IinvT));
        l.type(l.omegaRow, vecText(l.omegaT, 10));
        QString error;
        QVERIFY2(l.panel.saveAnswers(path, &error), qPrintable(error));
    }
    // The file is an answers file (answers_file.h): step 0, both entries, the body by name.
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QJsonObject o = QJsonDocument::fromJson(f.readAll()).object();
    QCOMPARE(o.value("step").toInt(), 0);
    const QJsonArray answers = o.value("answers").toArray();
    QCOMPARE(answers.size(), 2);
    QCOMPARE(answers[0].toObject().value("quantity").toString(), QString("inverse_inertia_world"));
    QCOMPARE(answers[1].toObject().value("body").toString(), QString("standard"));

    // Loaded into a fresh panel: the same entries and verdicts (wrong, then amber).
    Lesson8 l;
    QString error;
    QVERIFY2(l.panel.loadAnswers(path, &error), qPrintable(error));
    QCOMPARE(l.model()->rowState(l.iinvRow), State::Wrong);
    QCOMPARE(l.model()->rowState(l.omegaRow), State::FollowsFromEarlier);

    // A file that is not an answers file is refused with a message.
    const QString bad = dir.filePath("bad.json");
    QFile b(bad);
    QVERIFY(b.open(QIODevice::WriteOnly));
    b.write("{\"answers\": [{\"quantity\": \"angular_velocity\", \"body\": \"nobody\", \"value\": [1, 2, 3]}]}");
    b.close();
    QVERIFY(!l.panel.loadAnswers(bad, &error));
    QVERIFY2(error.contains("nobody"), qPrintable(error));
}

// In the app: the dock is there, and entries survive switching steps and lessons.
void TestCheckPanel::keptPerLessonAndStep()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.findChild<QDockWidget*>("checkDock") != nullptr);
    QVERIFY(w.openLesson("08-conventions"));
    CheckModel* m = w.checkPanel()->model();
    QCOMPARE(m->rowCount(), 0);   // step 0 not taken yet
    w.stepOnce();
    QVERIFY(m->rowCount() > 0);
    const int row = m->rowOf("angular_velocity", 0);
    QVERIFY(m->setData(m->index(row, CheckModel::YoursColumn), "(1, 2, 3)"));
    QCOMPARE(m->rowState(row), State::Wrong);

    w.stepOnce();   // step 1: its own, empty entries
    QCOMPARE(m->step(), 1L);
    QCOMPARE(m->index(m->rowOf("angular_velocity", 0), CheckModel::YoursColumn).data().toString(), QString());
    w.stepBack();   // back at step 0: the entry again
    QCOMPARE(m->step(), 0L);
    QCOMPARE(m->index(row, CheckModel::YoursColumn).data().toString(), QString("(1, 2, 3)"));

    QVERIFY(w.openLesson("01-one-step"));
    w.stepOnce();
    QCOMPARE(m->lesson(), QString("01-one-step"));
    QCOMPARE(m->index(m->rowOf("angular_velocity", 0), CheckModel::YoursColumn).data().toString(), QString());
    QVERIFY(w.openLesson("08-conventions"));
    w.stepOnce();
    QCOMPARE(m->index(row, CheckModel::YoursColumn).data().toString(), QString("(1, 2, 3)"));
    QCOMPARE(m->rowState(row), State::Wrong);
}

// The panel refuses exactly what rbw check refuses, with the same message (issue 22
// item 5; one code path, app/exercise/answers_input.h): each file is also given to the
// real rbw check on lesson 8's scene, which must refuse it (exit 2) with the panel's
// message, line for line (its "rbw: " prefix taken off). The words are the expected
// reason, so neither side can pass by printing nothing.
// Lesson 8 at step 0: two bodies, "standard" with probe 0, "template" with probe 1, no
// contact, 1000 steps.
void TestCheckPanel::loadRefusesWhatCheckRefuses_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QString>("words");
    QTest::newRow("unknown quantity") << QByteArray(R"({"answers": [{"quantity": "omega", "body": "standard", "value": 1}]})")
                                      << "a.json: answers[0].quantity: unknown quantity \"omega\"";
    QTest::newRow("contact 5, none in the step") << QByteArray(R"({"answers": [{"quantity": "impulse", "contact": 5, "value": 1}]})")
                                                 << "a.json: answers[0]: no contact 5 in step 0 (it has 0)";
    QTest::newRow("probe 7") << QByteArray(R"({"answers": [{"quantity": "point_velocity", "body": "standard", "index": 7, "value": [1, 2, 3]}]})")
                             << "the probes of standard are 0";
    QTest::newRow("no answers") << QByteArray(R"({"answers": []})") << "a.json: answers: there are no answers";
    QTest::newRow("duplicate key") << QByteArray(R"({"step": 0, "step": 1, "answers": [{"quantity": "torque", "body": "standard", "value": [1, 2, 3]}]})")
                                   << "a.json: step: duplicate key \"step\"";
    QTest::newRow("step beyond") << QByteArray(R"({"step": 1000, "answers": [{"quantity": "torque", "body": "standard", "value": [1, 2, 3]}]})")
                                 << "a.json: step: step 1000 is beyond the scene's 1000 steps (the last is step 999); steps count from 0: did you mean step 999?";
    QTest::newRow("empty") << QByteArray("") << "a.json: the file is empty";
    QTest::newRow("malformed JSON") << QByteArray(R"({"answers": [)") << "a.json: malformed JSON";
    QTest::newRow("unknown body") << QByteArray(R"({"answers": [{"quantity": "torque", "body": "ghost", "value": [1, 2, 3]}]})")
                                  << "a.json: answers[0].body: no body named \"ghost\"";
    QTest::newRow("a form error before a step's") << QByteArray(R"({"answers": [{"quantity": "impulse", "contact": 5, "value": 1}, {"quantity": "omega", "body": "standard", "value": 1}]})")
                                                  << "a.json: answers[1].quantity: unknown quantity \"omega\"";
}

void TestCheckPanel::loadRefusesWhatCheckRefuses()
{
    QFETCH(QByteArray, text);
    QFETCH(QString, words);
    QTemporaryDir dir;
    const QString path = dir.filePath("a.json");
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(text);
    f.close();
    Lesson8 l;
    QString error;
    QVERIFY(!l.panel.loadAnswers(path, &error));
    QVERIFY2(error.contains(words), qPrintable(error));
    QCOMPARE(l.model()->index(l.omegaRow, CheckModel::YoursColumn).data().toString(), QString());   // nothing loaded

    // rbw check on the same file, named as the panel names it (run in its folder).
    QProcess cli;
    cli.setWorkingDirectory(dir.path());
    cli.start(QStringLiteral(RBW_CLI_PATH),
              {"check", QStringLiteral(RBW_SOURCE_DIR "/lessons/08-conventions/scene.json"), "a.json"});
    QVERIFY(cli.waitForFinished(120000));
    QCOMPARE(cli.exitCode(), 2);
    QStringList cliLines = QString::fromUtf8(cli.readAllStandardError()).trimmed().split(QLatin1Char('\n'));
    for (QString& line : cliLines) {
        QVERIFY2(line.startsWith(QLatin1String("rbw: ")), qPrintable(line));
        line.remove(0, 5);
    }
    QCOMPARE(error, cliLines.join(QLatin1Char('\n')));
}

// The check table owns the keyboard while a cell is edited (issue 21 item 8): "[" (the
// app's "Play slower") and Space ("Play") typed into the Yours cell are text, and
// neither action fires nor the step changes. Negative control: on the quantity's name
// (not editable) "[" is the app's key again.
void TestCheckPanel::typingOwnsTheKeyboard()
{
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openLesson("08-conventions"));
    w.stepOnce();
    auto* dock = w.findChild<QDockWidget*>("checkDock");
    QVERIFY(dock != nullptr);
    dock->show();
    dock->raise();
    auto* play = w.findChild<QAction*>("actionPlay");
    auto* slower = w.findChild<QAction*>("actionSlower");
    QVERIFY(play != nullptr && slower != nullptr);
    QSignalSpy played(play, &QAction::triggered);
    QSignalSpy slowed(slower, &QAction::triggered);
    QTableView* view = w.checkPanel()->view();
    CheckModel* m = w.checkPanel()->model();
    const int row = m->rowOf("angular_velocity", 0);
    w.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&w));
    view->setFocus();
    QTRY_VERIFY(view->hasFocus());

    view->setCurrentIndex(m->index(row, CheckModel::QuantityColumn));
    QTest::keyClicks(view, "[");
    QCOMPARE(slowed.count(), 1);   // the control: the shortcut works here
    slowed.clear();

    view->setCurrentIndex(m->index(row, CheckModel::YoursColumn));
    QTest::keyClicks(view, "[");   // opens the editor with "["
    auto* editor = view->findChild<QLineEdit*>();
    QVERIFY(editor != nullptr);
    QTRY_VERIFY(editor->hasFocus());
    QTest::keyClicks(QApplication::focusWidget(), "1 2 3]");
    QCOMPARE(editor->text(), QString("[1 2 3]"));
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Return);
    QTRY_COMPARE(m->index(row, CheckModel::YoursColumn).data().toString(), QString("[1 2 3]"));
    QCOMPARE(played.count(), 0);
    QCOMPARE(slowed.count(), 0);
    QCOMPARE(m->step(), 0L);
    QCOMPARE(m->rowState(row), State::Wrong);   // read and checked as (1, 2, 3)
}

int main(int argc, char* argv[])
{
    // As in the app's main(): shared GL contexts for QtWebEngine and the 3D view.
    QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QSurfaceFormat::setDefaultFormat(SceneView::requestedFormat());
    QApplication app(argc, argv);
    QApplication::setOrganizationName("rigid-workbook-tests");
    TestCheckPanel test;
    return QTest::qExec(&test, argc, argv);
}

// The input slips rbw check names get the same hint in the panel (issue 21 item 6; one
// code path: app/exercise/answers_input.h's slipHint and the answer parser). Lesson 8's
// "standard" after step 0: its orientation r' = r (omega_0 = 0, so r + h/2 (0, omega) r
// = r) is 30 degrees about z, [w, x, y, z] = [cos 15°, 0, 0, sin 15°], read from the trace.
void TestCheckPanel::slipHints_data()
{
    QTest::addColumn<QString>("slip");      // which entry is typed
    QTest::addColumn<int>("state");
    QTest::addColumn<QString>("hint");      // in the Mark column's text or tooltip, or "" for none
    QTest::newRow("quaternion [x, y, z, w]") << "xyzw" << int(State::Wrong) << "quaternions are [w, x, y, z]";
    QTest::newRow("quaternion [w, x, y, z]: no hint") << "wxyz" << int(State::Correct) << "";
    QTest::newRow("another wrong quaternion: no hint") << "other" << int(State::Wrong) << "";
    QTest::newRow("decimal commas") << "comma" << int(State::Unreadable) << "use a decimal point: 3.11, not 3,11";
}

void TestCheckPanel::slipHints()
{
    QFETCH(QString, slip);
    QFETCH(int, state);
    QFETCH(QString, hint);
    Lesson8 l;
    const Quat r = std::get<Quat>(l.session.currentTrace()->find("orientation", 0)->value);
    const int row = l.model()->rowOf("orientation", 0);
    QVERIFY(row >= 0);
    const auto n = [](double x) { return QString::number(x, 'g', 10); };
    QString text;
    if (slip == "xyzw") text = QStringLiteral("[%1 %2 %3 %4]").arg(n(r.x()), n(r.y()), n(r.z()), n(r.w()));
    if (slip == "wxyz") text = QStringLiteral("[%1 %2 %3 %4]").arg(n(r.w()), n(r.x()), n(r.y()), n(r.z()));
    if (slip == "other") text = QStringLiteral("[%1 %2 %3 %4]").arg(n(r.z()), n(r.w()), n(r.x()), n(r.y()));
    if (slip == "comma") text = QStringLiteral("[%1 %2 %3 %4]").arg(n(r.w()), n(r.x()), n(r.y()), n(r.z())).replace('.', ',');
    l.type(row, text);
    QCOMPARE(int(l.model()->rowState(row)), state);
    const QString mark = l.mark(row);
    const QString tip = l.model()->index(row, CheckModel::MarkColumn).data(Qt::ToolTipRole).toString();
    l.panel.view()->setCurrentIndex(l.model()->index(row, CheckModel::YoursColumn));
    l.panel.showWhatsWrong();
    const QString explained = l.panel.explanationHtml();
    if (hint.isEmpty()) {
        QCOMPARE(l.model()->rowHint(row), QString());
        QVERIFY2(!tip.contains("hint") && !mark.contains("hint"), qPrintable(mark + " / " + tip));
        QVERIFY(!explained.contains("Hint:"));
    } else if (slip == "comma") {
        QVERIFY2(mark.contains(hint), qPrintable(mark));   // the parser's message, as answers files get it
    } else {
        QVERIFY2(l.model()->rowHint(row).contains(hint), qPrintable(l.model()->rowHint(row)));
        QVERIFY2(mark.contains("hint") && tip.contains(hint), qPrintable(mark + " / " + tip));
        QVERIFY2(explained.contains(hint), qPrintable(explained));
        // the same text rbw check prints (answers_input.h)
        Answer a;
        a.quantity = "orientation";
        a.body = 0;
        a.value = {r.x(), r.y(), r.z(), r.w()};
        AnswerResult wrong;
        wrong.verdict = Verdict::Wrong;
        wrong.expected = {r.w(), r.x(), r.y(), r.z()};
        QCOMPARE(l.model()->rowHint(row), slipHint(a, wrong, 1e-3));
    }
}

// Steps counted from 1: at step 1, the numbers of step 0 (read from a step-0 trace: x' and
// omega' of "standard") are not all right (omega is wrong), but every one is right for step 0: the panel
// says "did you mean step 0?", as rbw check does for a file. Negative controls: step 1's
// own numbers, and step 0's position beside a wrong omega, get no hint.
void TestCheckPanel::stepsCountedFromOne()
{
    Session session;
    session.load(lessonScene("08-conventions/scene.json"));
    session.step();   // step 0
    const StepTrace step0 = *session.currentTrace();
    session.step();   // step 1
    const StepTrace& step1 = *session.currentTrace();
    CheckPanel panel;
    panel.setStep("08-conventions", session.worldBeforeCurrentStep(), &step1, session.world()->scene());
    QCOMPARE(panel.model()->step(), 1L);
    const int xRow = panel.model()->rowOf("position", 0);
    const int omegaRow = panel.model()->rowOf("angular_velocity", 0);
    QVERIFY(xRow >= 0 && omegaRow >= 0);
    const auto vec = [](const StepTrace& t, const char* id) { return std::get<Vec3>(t.find(id, 0)->value); };
    const auto type = [&](int row, const QString& text) {
        QVERIFY(panel.model()->setData(panel.model()->index(row, CheckModel::YoursColumn), text));
    };

    type(xRow, vecText(vec(step0, "position"), 10));
    type(omegaRow, vecText(vec(step0, "angular_velocity"), 10));
    // omega turns with the body in step 1 (by |omega| h, about 0.06 rad): not step 1's number
    // (x moves by h v = 0.005 m only, right to 3 figures in both steps)
    QCOMPARE(panel.model()->rowState(omegaRow), State::Wrong);
    QVERIFY2(panel.stepHintText().contains("steps count from 0: did you mean step 0?"), qPrintable(panel.stepHintText()));
    QVERIFY(panel.findChild<QLabel*>("checkStepHint") != nullptr);
    panel.view()->setCurrentIndex(panel.model()->index(omegaRow, CheckModel::YoursColumn));
    panel.showWhatsWrong();
    QVERIFY2(panel.explanationHtml().contains("did you mean step 0?"), qPrintable(panel.explanationHtml()));

    type(omegaRow, vecText(2 * vec(step0, "angular_velocity"), 10));   // wrong in both steps
    QCOMPARE(panel.stepHintText(), QString());

    type(xRow, vecText(vec(step1, "position"), 10));
    type(omegaRow, vecText(vec(step1, "angular_velocity"), 10));
    QCOMPARE(panel.model()->rowState(omegaRow), State::Correct);
    QCOMPARE(panel.stepHintText(), QString());
}

#include "tst_check_panel.moc"
