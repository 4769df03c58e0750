// Every file the workbook writes is replaced atomically: QSaveFile writes a temporary
// file beside it and renames it over the target on commit(), so the file is either
// the complete new one or the old one (or absent), never half written.
#pragma once

#include <QByteArray>
#include <QString>

namespace rbw {

// Writes `bytes` to `path` through QSaveFile. False with *error (if given) set to
// "PATH: cannot write: REASON" when the file cannot be opened, written or committed.
bool writeFileAtomically(const QString& path, const QByteArray& bytes, QString* error);

} // namespace rbw
