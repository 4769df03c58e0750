#include "app/core/source_root.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QStringList>

// Where the package's data folder is, relative to the folder holding the executables
// (app/CMakeLists.txt sets it from GNUInstallDirs).
#ifndef RBW_INSTALL_DATA_FROM_BIN
#define RBW_INSTALL_DATA_FROM_BIN "../share/rigid-body-workbook"
#endif

namespace rbw {

namespace {

bool holdsPhysics(const QString& dir)
{
    return !dir.isEmpty() && QFileInfo(QDir(dir).filePath(QStringLiteral("physics"))).isDir();
}

QString clean(const QString& dir)
{
    return QDir::cleanPath(QDir(dir).absolutePath());
}

} // namespace

QString installedDataDirectory()
{
    if (QCoreApplication::instance() == nullptr) {
        return {};
    }
    return QDir::cleanPath(QCoreApplication::applicationDirPath() + QLatin1Char('/') +
                           QStringLiteral(RBW_INSTALL_DATA_FROM_BIN));
}

QString sourceRoot()
{
    const QString fromEnv = qEnvironmentVariable("RBW_SOURCE_ROOT");
    if (!fromEnv.isEmpty() && QFileInfo(fromEnv).isDir()) {
        return clean(fromEnv);
    }
    // An installed program shows its own copy of the sources: the build tree may have
    // moved on since, and the trace's line numbers are those of the installed build.
    const QString installedData = installedDataDirectory();
    if (!installedData.isEmpty()) {
        const QString installed = installedData + QStringLiteral("/source");
        if (holdsPhysics(installed)) {
            return clean(installed);
        }
    }
#ifdef RBW_SOURCE_TREE
    const QString built = QStringLiteral(RBW_SOURCE_TREE);
    if (holdsPhysics(built)) {
        return clean(built);
    }
#endif
    return {};
}

QString userGuidePath()
{
    const QString guide = QStringLiteral("docs/user-guide.md");
    QStringList roots{installedDataDirectory()};
    const QString fromEnv = qEnvironmentVariable("RBW_SOURCE_ROOT");
    if (!fromEnv.isEmpty()) roots << fromEnv;
#ifdef RBW_SOURCE_TREE
    roots << QStringLiteral(RBW_SOURCE_TREE);
#endif
    for (const QString& root : roots) {
        if (root.isEmpty()) continue;
        const QString path = QDir(root).filePath(guide);
        if (QFileInfo(path).isFile()) return clean(path);
    }
    return {};
}

QString sourceFilePath(const QString& relative)
{
    const QString root = sourceRoot();
    if (root.isEmpty() || relative.isEmpty() || QDir::isAbsolutePath(relative)) {
        return {};
    }
    const QString path = QDir::cleanPath(root + QLatin1Char('/') + relative);
    // Only files inside the tree: "../" in a path does not leave it.
    if (!path.startsWith(root + QLatin1Char('/')) || !QFileInfo(path).isFile()) {
        return {};
    }
    return path;
}

} // namespace rbw
