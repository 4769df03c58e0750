// Where the workbook's source tree is, so the app can show the physics statement that
// computed a traced number (TraceEntry's source location, relative to the repository
// root, e.g. "physics/integrators/explicit_euler.cpp").
#pragma once

#include <QString>

namespace rbw {

// The root of the source tree, without a trailing slash, or empty if none is found.
// In this order:
//   1. the environment variable RBW_SOURCE_ROOT, if it names a directory;
//   2. the tree the app was built from (CMake's PROJECT_SOURCE_DIR), if it still holds
//      physics/;
//   3. <executable's directory>/../share/rigid-body-workbook/source (an installed
//      package), if it holds physics/.
QString sourceRoot();

// The absolute path of a file of the source tree (relative path as in the trace);
// empty if there is no source tree or no such file.
QString sourceFilePath(const QString& relative);

} // namespace rbw
