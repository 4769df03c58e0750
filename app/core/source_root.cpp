#include "app/core/source_root.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

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

QString sourceRoot()
{
    const QString fromEnv = qEnvironmentVariable("RBW_SOURCE_ROOT");
    if (!fromEnv.isEmpty() && QFileInfo(fromEnv).isDir()) {
        return clean(fromEnv);
    }
#ifdef RBW_SOURCE_TREE
    const QString built = QStringLiteral(RBW_SOURCE_TREE);
    if (holdsPhysics(built)) {
        return clean(built);
    }
#endif
    if (QCoreApplication::instance() != nullptr) {
        const QString installed =
            QCoreApplication::applicationDirPath() + QStringLiteral("/../share/rigid-body-workbook/source");
        if (holdsPhysics(installed)) {
            return clean(installed);
        }
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
