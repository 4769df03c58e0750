// Where a write to a path really goes, before anything is written (issue 22): every
// symbolic link is followed, and the file at the end decides how it may be written.
// A regular file (or a new one) is replaced atomically; a FIFO or a character device is
// written in place (renaming a file over it would destroy it); a path that names an
// open file descriptor (/dev/stdout, /dev/fd/N, /proc/self/fd/N) is written through
// that descriptor, so `--output /dev/stdout >> log` appends to log and erases nothing;
// a directory, block device or socket is refused.
#pragma once

#include <QString>

namespace rbw {

struct OutputTarget {
    enum class Kind {
        Replace,         // a regular file or none yet: written beside it, renamed over it
        InPlace,         // a FIFO, a character device or another process's descriptor: opened, appended to
        OwnDescriptor,   // this process's descriptor `descriptor` (e.g. 1 for /dev/stdout)
        Refused,         // not writable as an output; `reason` says why
    };
    Kind kind = Kind::Refused;
    QString resolved;     // the path after every symbolic link (absolute)
    int descriptor = -1;  // OwnDescriptor
    QString reason;       // Refused
    QString identity;     // equal for two paths that name the same file (device:inode, or the resolved path)
};

OutputTarget resolveOutputTarget(const QString& path);

} // namespace rbw
