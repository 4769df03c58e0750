// Every file the app and rbw write is replaced atomically (QSaveFile): it appears
// complete or not at all. Under Xvfb, each export is pointed at a folder in which no
// file may be created: it must fail with a message naming the path, create nothing
// there (no partial file, no leftover temporary file) and leave a file already there
// untouched, even though that file itself is writable (a writer that fell back to
// writing in place would change it). And the derivation's PDF export writes a whole
// PDF, %PDF- to %%EOF, with nothing else beside it.
//
// Root ignores permission bits, so when the test runs as root, each write into the
// locked folder runs with the effective user and group "nobody" (seteuid; restored
// right after). A precondition checks the folder really is unwritable then.
#include "app/scene/scene_loader.h"
#include "app/gui/panels/accuracy/accuracy_panel.h"
#include "app/derivation/derivation_builder.h"
#include "app/gui/panels/derivation/derivation_view.h"
#include "app/gui/panels/plots/body_plot_panel.h"
#include "app/gui/panels/plots/plot_panel.h"
#include "app/gui/shell/worksheet_export.h"
#include "app/exercise/exercise.h"
#include "physics/engine/world.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <memory>

#include <grp.h>
#include <unistd.h>

using namespace rbw;

namespace {

constexpr uid_t kNobody = 65534;
const QByteArray kOldContents("the file that was here before the export\n");

QString lessonPath(const QString& relative)
{
    return QStringLiteral(RBW_SOURCE_DIR "/lessons/") + relative;
}

SceneDef loadLesson(const QString& relative)
{
    const SceneLoadResult r = loadSceneFile(lessonPath(relative));
    if (!r.ok()) qFatal("%s", qPrintable(r.errors.join('\n')));
    return *r.scene;
}

// While it lives, the process writes files as the user nobody if it is root (root may
// write anywhere); otherwise it changes nothing.
class Unprivileged {
public:
    Unprivileged()
    {
        if (geteuid() != 0) return;
        if (setegid(kNobody) != 0) {
            failed_ = true;
            return;
        }
        if (seteuid(kNobody) != 0) {
            if (setegid(0) != 0) qFatal("cannot return to the effective group root");
            failed_ = true;
            return;
        }
        dropped_ = true;
    }
    ~Unprivileged()
    {
        if (!dropped_) return;
        if (seteuid(0) != 0 || setegid(0) != 0) qFatal("cannot return to the effective user root");
    }
    Unprivileged(const Unprivileged&) = delete;
    Unprivileged& operator=(const Unprivileged&) = delete;
    bool failed() const { return failed_; }

private:
    bool dropped_ = false;
    bool failed_ = false;
};

// <tmp>/locked: mode 0555, holding one writable file (mode 0666) with kOldContents.
class LockedFolder {
public:
    explicit LockedFolder(const QString& existingName) : existingName_(existingName)
    {
        if (!base_.isValid()) return;
        // nobody must be able to reach the folder: the temporary folder is 0700.
        QFile::setPermissions(base_.path(), QFileDevice::ReadOwner | QFileDevice::WriteOwner |
                                                QFileDevice::ExeOwner | QFileDevice::ReadGroup |
                                                QFileDevice::ExeGroup | QFileDevice::ReadOther |
                                                QFileDevice::ExeOther);
        if (!QDir(base_.path()).mkdir(QStringLiteral("locked"))) return;
        QFile f(existingPath());
        if (!f.open(QIODevice::WriteOnly) || f.write(kOldContents) != kOldContents.size()) return;
        f.close();
        const auto rw = QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ReadGroup |
                        QFileDevice::WriteGroup | QFileDevice::ReadOther | QFileDevice::WriteOther;
        const auto rx = QFileDevice::ReadOwner | QFileDevice::ExeOwner | QFileDevice::ReadGroup |
                        QFileDevice::ExeGroup | QFileDevice::ReadOther | QFileDevice::ExeOther;
        ok_ = QFile::setPermissions(existingPath(), rw) && QFile::setPermissions(path(), rx);
    }
    ~LockedFolder()
    {
        // Writable again, so QTemporaryDir can remove it.
        QFile::setPermissions(path(), QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
    }
    bool ok() const { return ok_; }
    QString path() const { return base_.filePath(QStringLiteral("locked")); }
    QString filePath(const QString& name) const { return path() + QLatin1Char('/') + name; }
    QString existingPath() const { return filePath(existingName_); }
    // Everything in the folder, hidden files (QSaveFile's temporary names) included.
    QStringList entries() const
    {
        return QDir(path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden | QDir::System);
    }
    QByteArray existingContents() const
    {
        QFile f(existingPath());
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("(unreadable)");
    }
    // True if the current effective user may create files in the folder.
    bool writableNow() const { return euidaccess(QFile::encodeName(path()).constData(), W_OK) == 0; }

private:
    QTemporaryDir base_;
    QString existingName_;
    bool ok_ = false;
};

// Empty if the locked-folder checks can run: not root, or root that can become nobody.
QString whyNoLockedFolder()
{
    Unprivileged unprivileged;
    return unprivileged.failed() ? QStringLiteral("running as root, and cannot switch to the user nobody") : QString();
}

// Runs `write(path)` on a new file and on the existing one of a locked folder as an
// unprivileged user; each must fail with a message naming the path and leave the
// folder as it was.
template <typename Write>
void checkRefusedAndNothingLeft(const QString& extension, Write write)
{
    const QString existing = QStringLiteral("existing.") + extension;
    LockedFolder folder(existing);
    QVERIFY2(folder.ok(), "cannot set up the locked folder");
    const QString fresh = folder.filePath(QStringLiteral("new.") + extension);
    for (const QString& path : {fresh, folder.existingPath()}) {
        QString error;
        bool written = true;
        {
            Unprivileged unprivileged;
            QVERIFY(!unprivileged.failed());
            QVERIFY2(!folder.writableNow(), "precondition: the locked folder must not be writable");
            written = write(path, &error);
        }
        QVERIFY2(!written, qPrintable(path + QStringLiteral(" was written; the writer said: ") + error));
        QVERIFY2(error.contains(path), qPrintable(QStringLiteral("the message \"%1\" does not name %2").arg(error, path)));
        QCOMPARE(folder.entries(), QStringList{existing});
        QCOMPARE(folder.existingContents(), kOldContents);
    }
}

void verifyWholePdf(const QString& path)
{
    QFile f(path);
    QVERIFY2(f.open(QIODevice::ReadOnly), qPrintable(path));
    const QByteArray pdf = f.readAll();
    QVERIFY2(pdf.size() > 1000, qPrintable(QString::number(pdf.size())));
    QVERIFY(pdf.startsWith("%PDF-"));
    QVERIFY2(pdf.trimmed().endsWith("%%EOF"), "the PDF is cut short");
}

} // namespace

class TestExports : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void cleanupTestCase();
    void derivationPdfIsWhole();
    void derivationPdfRefused();
    void derivationHtmlRefused();
    void plotPngAndCsvRefused();
    void bodyPlotPng();
    void accuracyPngAndCsvRefused();
    void rbwStudyOutputRefused();
    void worksheetPdfAndHtml();
    void worksheetRefused();

private:
    std::unique_ptr<DerivationView> view_;
    bool rendered_ = false;
};

void TestExports::initTestCase()
{
    // One derivation page, rendered once: lesson 1's step.
    view_ = std::make_unique<DerivationView>();
    view_->resize(500, 900);
    view_->show();
    QVERIFY(QTest::qWaitForWindowExposed(view_.get()));
    const SceneDef scene = loadLesson(QStringLiteral("01-one-step/scene.json"));
    World world(scene);
    StepTrace trace;
    QVERIFY(world.step(&trace).ok);
    QSignalSpy spy(view_.get(), &DerivationView::rendered);
    view_->showStep(buildLessonDerivation(trace, scene, lessonPath(QStringLiteral("01-one-step"))).html);
    QVERIFY(spy.wait(30000));
    QVERIFY2(spy.first().at(0).toInt() > 0, "KaTeX did not render the page");
    rendered_ = true;
}

void TestExports::cleanupTestCase()
{
    view_.reset();
}

void TestExports::derivationPdfIsWhole()
{
    QVERIFY(rendered_);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("derivation.pdf"));
    // An old file there is replaced by the whole new one.
    QFile old(path);
    QVERIFY(old.open(QIODevice::WriteOnly));
    old.write(kOldContents);
    old.close();
    QSignalSpy spy(view_.get(), &DerivationView::pdfExported);
    view_->exportPdf(path);
    QVERIFY(spy.wait(30000));
    QCOMPARE(spy.first().at(0).toString(), path);
    QVERIFY2(spy.first().at(1).toBool(), qPrintable(spy.first().at(2).toString()));
    QVERIFY(spy.first().at(2).toString().isEmpty());
    verifyWholePdf(path);
    // Nothing else: no temporary file left beside it.
    QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden),
             QStringList{QStringLiteral("derivation.pdf")});
}

void TestExports::derivationPdfRefused()
{
    const QString why = whyNoLockedFolder();
    if (!why.isEmpty()) QSKIP(qPrintable(why));
    QVERIFY(rendered_);
    checkRefusedAndNothingLeft(QStringLiteral("pdf"), [this](const QString& path, QString* error) {
        QSignalSpy spy(view_.get(), &DerivationView::pdfExported);
        view_->exportPdf(path);
        if (!spy.wait(30000)) {
            *error = QStringLiteral("no pdfExported signal");
            return true;   // fails the check, with this message
        }
        *error = spy.first().at(2).toString();
        if (spy.first().at(0).toString() != path) *error += QStringLiteral(" (signal for another path)");
        return spy.first().at(1).toBool();
    });
    if (QTest::currentTestFailed()) return;
    // Printing that produced nothing is an error too, and writes nothing.
    QTemporaryDir dir;
    QString error;
    QVERIFY(!DerivationView::writePdf(dir.filePath(QStringLiteral("empty.pdf")), QByteArray(), &error));
    QVERIFY(error.contains(QLatin1String("printing the page failed")));
    QVERIFY(QDir(dir.path()).isEmpty(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden));
}

void TestExports::derivationHtmlRefused()
{
    const QString why = whyNoLockedFolder();
    if (!why.isEmpty()) QSKIP(qPrintable(why));
    QVERIFY(rendered_);
    checkRefusedAndNothingLeft(QStringLiteral("html"), [this](const QString& path, QString* error) {
        return view_->exportHtml(path, error);
    });
}

void TestExports::plotPngAndCsvRefused()
{
    const QString why = whyNoLockedFolder();
    if (!why.isEmpty()) QSKIP(qPrintable(why));
    PlotPanel panel;
    panel.resize(600, 400);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    Diagnostics d;
    d.kineticTranslational = 1.0;
    d.kineticRotational = 2.0;
    d.kinetic = 3.0;
    d.total = 3.0;
    QVERIFY2(panel.appendStep(0.1, d), qPrintable(panel.lastError()));
    QVERIFY2(panel.appendStep(0.2, d), qPrintable(panel.lastError()));
    checkRefusedAndNothingLeft(QStringLiteral("png"), [&](const QString& path, QString* error) {
        return panel.exportPng(path, error);
    });
    if (QTest::currentTestFailed()) return;
    checkRefusedAndNothingLeft(QStringLiteral("csv"), [&](const QString& path, QString* error) {
        return panel.exportCsv(path, error);
    });
}

void TestExports::bodyPlotPng()
{
    BodyPlotPanel panel;
    panel.resize(600, 400);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.setBodies({QStringLiteral("box")});
    Diagnostics d;
    d.bodies.resize(1);
    for (int k = 1; k <= 3; ++k) {
        d.bodies[0].kinetic = k;
        d.bodies[0].L_norm = 2.0 * k;
        QVERIFY(panel.appendStep(0.1 * k, d));
    }
    // Written: a whole PNG of the chart, alone in its folder.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bodies.png"));
    QString error;
    QVERIFY2(panel.exportPng(path, &error), qPrintable(error));
    const QImage image(path);
    QVERIFY(!image.isNull());
    QVERIFY(image.width() >= 960 && image.height() >= 640);   // twice at least 480 x 320
    QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden),
             QStringList{QStringLiteral("bodies.png")});
    // Refused.
    const QString why = whyNoLockedFolder();
    if (!why.isEmpty()) QSKIP(qPrintable(why));
    checkRefusedAndNothingLeft(QStringLiteral("png"), [&](const QString& p, QString* e) {
        return panel.exportPng(p, e);
    });
}

void TestExports::accuracyPngAndCsvRefused()
{
    const QString why = whyNoLockedFolder();
    if (!why.isEmpty()) QSKIP(qPrintable(why));
    AccuracyPanel panel;
    panel.resize(1200, 800);
    panel.show();
    panel.setScene(loadLesson(QStringLiteral("10-accuracy-lab/constant-spin.json")), QStringLiteral("constant spin"));
    panel.setSelectedIntegrators({QStringLiteral("explicit-euler")});
    panel.setEndTime(1.0);
    panel.setDtText(QStringLiteral("0.1"));
    panel.setTimingBudget(0.0);
    QSignalSpy finished(&panel, &AccuracyPanel::studyFinished);
    QVERIFY2(panel.startStudy(), qPrintable(panel.statusText()));
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
    checkRefusedAndNothingLeft(QStringLiteral("png"), [&](const QString& path, QString* error) {
        return panel.exportPng(path, error);
    });
    if (QTest::currentTestFailed()) return;
    checkRefusedAndNothingLeft(QStringLiteral("csv"), [&](const QString& path, QString* error) {
        return panel.exportCsv(path, error);
    });
}

void TestExports::rbwStudyOutputRefused()
{
    const QString why = whyNoLockedFolder();
    if (!why.isEmpty()) QSKIP(qPrintable(why));
    // The child runs as nobody, who may not reach the build tree (a clone under root's
    // 0700 home on a fresh machine): it gets its own copies of rbw and the scene in a
    // folder everyone can read, so that exit 2 can only come from the refused --output.
    QTemporaryDir reachable;
    QVERIFY(reachable.isValid());
    const QFileDevice::Permissions readAndRun = QFileDevice::ReadOwner | QFileDevice::WriteOwner |
                                                QFileDevice::ExeOwner | QFileDevice::ReadGroup |
                                                QFileDevice::ExeGroup | QFileDevice::ReadOther | QFileDevice::ExeOther;
    QVERIFY(QFile::setPermissions(reachable.path(), readAndRun));
    const QString rbwCopy = reachable.filePath(QStringLiteral("rbw"));
    const QString sceneCopy = reachable.filePath(QStringLiteral("constant-spin.json"));
    QVERIFY(QFile::copy(QStringLiteral(RBW_CLI_PATH), rbwCopy));
    QVERIFY(QFile::copy(lessonPath(QStringLiteral("10-accuracy-lab/constant-spin.json")), sceneCopy));
    QVERIFY(QFile::setPermissions(rbwCopy, readAndRun));
    QVERIFY(QFile::setPermissions(sceneCopy, QFileDevice::ReadOwner | QFileDevice::WriteOwner |
                                                 QFileDevice::ReadGroup | QFileDevice::ReadOther));
    checkRefusedAndNothingLeft(QStringLiteral("csv"), [&rbwCopy, &sceneCopy](const QString& path, QString* error) {
        QProcess rbw;
        // Qt refuses to run with a real user other than the effective one ("running
        // setuid"): as root, the child becomes nobody entirely before it runs rbw.
        const bool asRoot = getuid() == 0;
        rbw.setChildProcessModifier([asRoot] {
            if (!asRoot) return;
            if (seteuid(0) != 0 || setgroups(0, nullptr) != 0 || setgid(kNobody) != 0 || setuid(kNobody) != 0) {
                _exit(125);
            }
        });
        rbw.start(rbwCopy,
                  {QStringLiteral("study"), sceneCopy,
                   QStringLiteral("--integrators"), QStringLiteral("explicit-euler"), QStringLiteral("--dt"),
                   QStringLiteral("0.1"), QStringLiteral("--t-end"), QStringLiteral("1"), QStringLiteral("--output"),
                   path});
        if (!rbw.waitForFinished(60000)) {
            *error = QStringLiteral("rbw did not finish");
            return true;
        }
        *error = QString::fromUtf8(rbw.readAllStandardError()) +
                 QStringLiteral(" (exit %1)").arg(rbw.exitCode());
        // Exit status 2 (bad input) is the documented answer to an unwritable --output.
        return !(rbw.exitStatus() == QProcess::NormalExit && rbw.exitCode() == 2);
    });
}

void TestExports::worksheetPdfAndHtml()
{
    // Lesson 1's exercise for seed 7: the worksheet and its key, as PDF and as HTML.
    const ExerciseLoadResult spec = loadExercise(lessonPath(QStringLiteral("01-one-step")));
    QVERIFY2(spec.ok(), qPrintable(spec.errors.join('\n')));
    const GeneratedExercise g = generateExercise(*spec.spec, 7);
    QVERIFY(g.ok());
    QTemporaryDir dir;
    WorksheetFiles written;
    QString error;
    QVERIFY2(exportWorksheet(*spec.spec, g, dir.filePath(QStringLiteral("sheet.pdf")), &written, &error), qPrintable(error));
    QCOMPARE(written.worksheet, dir.filePath(QStringLiteral("sheet.pdf")));
    QCOMPARE(written.answerKey, dir.filePath(QStringLiteral("sheet-key.pdf")));
    verifyWholePdf(written.worksheet);
    verifyWholePdf(written.answerKey);
    // The key has the answers the sheet leaves empty: a different, longer document.
    QVERIFY(QFileInfo(written.answerKey).size() > QFileInfo(written.worksheet).size());
    // HTML: the same pages rbw exercise writes.
    QVERIFY2(exportWorksheet(*spec.spec, g, dir.filePath(QStringLiteral("sheet.html")), &written, &error), qPrintable(error));
    QFile key(written.answerKey);
    QVERIFY(key.open(QIODevice::ReadOnly));
    QCOMPARE(QString::fromUtf8(key.readAll()), exerciseWorksheetHtml(*spec.spec, g, true));
    // Nothing else: no temporary files beside them.
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 4);
}

void TestExports::worksheetRefused()
{
    const QString why = whyNoLockedFolder();
    if (!why.isEmpty()) QSKIP(qPrintable(why));
    const ExerciseLoadResult spec = loadExercise(lessonPath(QStringLiteral("01-one-step")));
    QVERIFY(spec.ok());
    const GeneratedExercise g = generateExercise(*spec.spec, 7);
    checkRefusedAndNothingLeft(QStringLiteral("pdf"), [&](const QString& path, QString* error) {
        return exportWorksheet(*spec.spec, g, path, nullptr, error);
    });
}

int main(int argc, char** argv)
{
    // QtWebEngine shares OpenGL contexts with the widgets: set before the application.
    QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QApplication app(argc, argv);
    TestExports test;
    return QTest::qExec(&test, argc, argv);
}

#include "tst_exports.moc"
