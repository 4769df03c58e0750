// The app's settings (QSettings: on Linux ~/.config/rigid-workbook/Rigid Body
// Workbook.conf): every key is named once, here, with its type and default. Nothing
// else in the app spells a settings key.
//
// A settings file is the user's and can hold anything (issue 22): a value of the
// wrong type, a truncated blob, a flipped byte. No value may crash the app or stop
// it from starting. So every value is read as its type or dropped (removed from the
// file, with one note on standard error), and the window layout is sealed: saved
// with a magic, the layout version and a SHA-256 of the Qt blob, and handed to
// QMainWindow::restoreState only if the seal is whole and the version is this app's.
// (Qt's restoreState trusts its input: one dock position set to 0x7fffffff was a
// SIGSEGV at every start.) A blob Qt wrote and the seal vouches for is what Qt
// itself restores; anything else gets the default layout.
#pragma once

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <optional>

namespace rbw {

class AppSettings {
public:
    // Raise when the docks or toolbars change: an older layout is then dropped (with
    // its note) instead of restored into a window it does not describe.
    static constexpr int kLayoutVersion = 2;

    // Every key the app writes (the settings fuzz test corrupts each of them).
    static const QStringList& keys();

    // The lesson open when the app was last closed ("" if none or not a string).
    static QString lastLesson();
    static void setLastLesson(const QString& lessonId);

    // File → Open recent, most recent first (paths as saved; "" entries dropped).
    static QStringList recentFiles();
    static void setRecentFiles(const QStringList& paths);

    // The window's geometry and dock/toolbar state as QMainWindow saved them, or
    // empty if none was saved or the saved one is not whole (dropped, with a note).
    static QByteArray windowGeometry();
    static QByteArray windowState();
    static void setWindowLayout(const QByteArray& geometry, const QByteArray& state);
    // A layout that failed to restore although sealed (restoreState said no): dropped.
    static void dropWindowLayout(const QString& reason);

    // The seal: magic, layout version, SHA-256, blob. unseal() gives the blob back, or
    // nothing with the reason (public for the tests).
    static QByteArray seal(const QByteArray& blob);
    static std::optional<QByteArray> unseal(const QByteArray& sealed, QString* reason);

private:
    static void drop(const QString& key, const QString& reason);
    static QByteArray sealedValue(const QString& key);
};

} // namespace rbw
