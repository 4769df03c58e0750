// `rigid-workbook --measure SECONDS`: the app measures itself as a student would
// meet it and prints one JSON object on stdout, then quits (docs/performance.md).
//   ready_epoch_ms   wall clock when the first frame is drawn AND the first step's
//                    derivation is typeset (KaTeX rendered, fonts loaded); the
//                    script that launched the app subtracts its start time
//   fps              frames the 3D view drew per second while playing for SECONDS
//   steps_per_s      simulation steps taken per second meanwhile
//   rss_mb           resident memory of the app and all its child processes
//                    (QtWebEngineProcess), from /proc, at the end
#pragma once

#include <QObject>
#include <QElapsedTimer>

namespace rbw {

class MainWindow;

class PerformanceProbe : public QObject {
    Q_OBJECT
public:
    PerformanceProbe(MainWindow* window, double seconds, QObject* parent = nullptr);
    void start();

private:
    void checkReady();
    void beginPlaying();
    void finish();

    MainWindow* window_;
    double seconds_;
    qint64 readyEpochMs_ = -1;
    int framesAtStart_ = 0;
    long stepsAtStart_ = 0;
    QElapsedTimer playClock_;
};

// Resident set size in MiB of a process and all its descendants (Linux /proc).
double processTreeRssMb(qint64 pid);

} // namespace rbw
