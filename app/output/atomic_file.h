// The one writer of every file the workbook writes (issue 22): it never reports success
// for a file it did not write, and never destroys what it did not mean to replace.
//
// Where the bytes go is decided first (output_target.h, every symbolic link followed):
// - a regular file, or a new one, is replaced atomically: the bytes go to a temporary
//   file beside it (QSaveFile), which is flushed, checked, synced to disk and checked
//   again before it is renamed over the target. A write error at any point (a full
//   disk raises ENOSPC only when the buffer is flushed, which QSaveFile::commit() alone
//   does not notice) removes the temporary file: the old file is untouched;
// - a FIFO or a character device is written in place, without truncating or replacing
//   it (a FIFO's reader gets the whole content);
// - /dev/stdout, /dev/fd/N, /proc/self/fd/N are written through that open descriptor
//   (so `--output /dev/stdout >> log` appends to log);
// - a directory, block device or socket is refused.
#pragma once

#include <QByteArray>
#include <QString>

namespace rbw {

// Writes `bytes` to `path`. False with *error (if given) set to
// "PATH: cannot write: REASON" when the file cannot be opened, written, synced or
// committed, or is not a file that may be written; then nothing has been replaced.
bool writeFileAtomically(const QString& path, const QByteArray& bytes, QString* error);

} // namespace rbw
