#include "app/gui/shell/performance_probe.h"

#include "app/gui/panels/derivation/derivation_view.h"
#include "app/gui/shell/main_window.h"
#include "app/gui/panels/view/scene_view.h"

#include <QAction>
#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>
#include <QTextStream>
#include <QTimer>

#include <cstdio>

namespace rbw {

double processTreeRssMb(qint64 pid)
{
    // Parent of every process, from /proc/<pid>/stat (field 4), and its VmRSS.
    QMap<qint64, qint64> parent;
    QMap<qint64, double> rssKb;
    const QDir proc("/proc");
    for (const QString& entry : proc.entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        bool isPid = false;
        const qint64 p = entry.toLongLong(&isPid);
        if (!isPid) continue;
        QFile stat(proc.filePath(entry + "/stat"));
        if (!stat.open(QIODevice::ReadOnly)) continue;
        const QByteArray s = stat.readAll();
        const int close = s.lastIndexOf(')');   // the command name may hold spaces
        const QList<QByteArray> fields = s.mid(close + 2).split(' ');
        if (fields.size() > 1) parent[p] = fields[1].toLongLong();
        QFile status(proc.filePath(entry + "/status"));
        if (!status.open(QIODevice::ReadOnly)) continue;
        for (const QByteArray& line : status.readAll().split('\n')) {
            if (line.startsWith("VmRSS:")) rssKb[p] = line.mid(6).trimmed().split(' ').value(0).toDouble();
        }
    }
    double total = 0.0;
    for (auto it = rssKb.cbegin(); it != rssKb.cend(); ++it) {
        // Walk up the parents: is `pid` an ancestor (or the process itself)?
        qint64 p = it.key();
        for (int depth = 0; depth < 64 && p > 1; ++depth) {
            if (p == pid) {
                total += it.value();
                break;
            }
            p = parent.value(p, 0);
        }
    }
    return total / 1024.0;
}

PerformanceProbe::PerformanceProbe(MainWindow* window, double seconds, QObject* parent)
    : QObject(parent), window_(window), seconds_(seconds)
{
}

void PerformanceProbe::start()
{
    // The derivation must be on screen to count as typeset.
    window_->findChild<QDockWidget*>("derivationDock")->raise();
    connect(window_->derivationView(), &DerivationView::rendered, this, [this](int katex, int) {
        if (katex > 0) checkReady();
    });
    window_->stepOnce();
}

void PerformanceProbe::checkReady()
{
    if (readyEpochMs_ >= 0) return;
    if (window_->sceneView()->framesRendered() == 0) {
        QTimer::singleShot(5, this, &PerformanceProbe::checkReady);
        return;
    }
    readyEpochMs_ = QDateTime::currentMSecsSinceEpoch();
    QTimer::singleShot(200, this, &PerformanceProbe::beginPlaying);
}

void PerformanceProbe::beginPlaying()
{
    framesAtStart_ = window_->sceneView()->framesRendered();
    stepsAtStart_ = window_->world()->stepIndex();
    playClock_.start();
    window_->setPlaying(true);
    QTimer::singleShot(static_cast<int>(seconds_ * 1000.0), this, &PerformanceProbe::finish);
}

void PerformanceProbe::finish()
{
    const double elapsed = static_cast<double>(playClock_.elapsed()) * 1e-3;
    window_->setPlaying(false);
    QJsonObject o{
        {"ready_epoch_ms", static_cast<double>(readyEpochMs_)},
        {"seconds", elapsed},
        {"bodies", static_cast<int>(window_->world()->states().size())},
        {"fps", (window_->sceneView()->framesRendered() - framesAtStart_) / elapsed},
        {"steps_per_s", static_cast<double>(window_->world()->stepIndex() - stepsAtStart_) / elapsed},
        {"view_width", window_->sceneView()->width()},
        {"view_height", window_->sceneView()->height()},
        {"gl", window_->sceneView()->glVersionString()},
        {"rss_mb", processTreeRssMb(QCoreApplication::applicationPid())},
    };
    std::fputs(QJsonDocument(o).toJson(QJsonDocument::Compact).constData(), stdout);
    std::fputs("\n", stdout);
    std::fflush(stdout);
    QCoreApplication::quit();
}

} // namespace rbw
