// The scene files the student opens in the app, apart from the lessons: File → Open
// (a Qt file dialog), the recent files (AppSettings::recentFiles), a .json dropped on
// the window, and the watch on the open file, so that saving it in an editor reloads
// it here. The window only wires these signals to its loading code.
//
// Editors save in two ways: in place (the watcher reports a change) or by writing a
// new file and renaming it over the old one (the watched inode is gone, and Qt drops
// the path from the watcher). Both end in one check a moment later (editors write in
// several pieces): the path is watched again if it exists, and a change of its bytes
// is reported once. The bytes the app itself saved are not reported back.
#pragma once

#include <QByteArray>
#include <QFileSystemWatcher>
#include <QObject>
#include <QPointer>
#include <QString>
#include <QStringList>
#include <QTimer>

class QFileDialog;
class QMimeData;
class QWidget;

namespace rbw {

class SceneFiles : public QObject {
    Q_OBJECT
public:
    // Takes a .json dropped anywhere on `window` (an application-wide event filter on
    // drag and drop events of the window's widgets).
    explicit SceneFiles(QWidget* window);

    static constexpr int kMaxRecent = 8;
    // Most recent first; only files that still exist.
    QStringList recentFiles() const;
    void addRecent(const QString& path);
    void clearRecent();

    // Watches this file (absolute path); an empty path stops watching.
    void watch(const QString& path);
    QString watchedPath() const { return watched_; }
    // The app wrote these bytes to the watched file: not a change to report.
    void noteWritten(const QByteArray& bytes) { lastBytes_ = bytes; }

    // File → Open: a non-native Qt dialog (the same everywhere, and drivable in tests),
    // opened window-modal; accepting it emits openRequested. Returns the dialog.
    QFileDialog* showOpenDialog(const QString& startFolder);
    // Save As: the path chosen, or empty if cancelled (a modal dialog).
    QString askSavePath(const QString& suggested);

    // The first local .json file a drag carries; empty if none.
    static QString sceneFileIn(const QMimeData* mime);

signals:
    void openRequested(const QString& path);
    // The watched file's bytes changed (saved in an editor), or it came back after a
    // rename; the window reloads it.
    void watchedFileChanged(const QString& path);
    void recentChanged();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void onSomethingChanged();
    void check();

    QWidget* window_;
    QFileSystemWatcher watcher_;
    QTimer settle_;   // editors write in pieces: look once they are done
    QString watched_;
    QByteArray lastBytes_;
    QPointer<QFileDialog> openDialog_;
};

} // namespace rbw
