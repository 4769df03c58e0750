// Where the workbook's files are at run time: the source tree, so the app can show the
// physics statement that computed a traced number (TraceEntry's source location,
// relative to the repository root, e.g. "physics/engine/integrators/explicit_euler.cpp"), and
// the installed data folder an installed rbw or rigid-workbook reads its lessons from.
#pragma once

#include <QString>

namespace rbw {

// The installed package's data folder, found from the executable's own location:
// <executable's directory>/../share/rigid-body-workbook (CMake's GNUInstallDirs
// layout, fixed at configure time), cleaned; empty without a QCoreApplication. The
// folder need not exist (it does not in a build tree).
QString installedDataDirectory();

// The root of the source tree, without a trailing slash, or empty if none is found.
// In this order:
//   1. the environment variable RBW_SOURCE_ROOT, if it names a directory;
//   2. installedDataDirectory()/source (an installed package: the copy of physics/
//      that the installed program was built from), if it holds physics/;
//   3. the tree the program was built from (CMake's PROJECT_SOURCE_DIR), if it still
//      holds physics/ (a build tree).
QString sourceRoot();

// The user guide (Help → User guide): the installed copy
// installedDataDirectory()/docs/user-guide.md, else docs/user-guide.md of the source
// tree (RBW_SOURCE_ROOT or the tree the program was built from); empty if neither
// exists.
QString userGuidePath();

// The absolute path of a file of the source tree (relative path as in the trace);
// empty if there is no source tree or no such file.
QString sourceFilePath(const QString& relative);

} // namespace rbw
