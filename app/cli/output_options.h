// A command's output options checked together before anything is written (issue 22):
// an output that cannot be written (a directory, a block device) is named at once, and
// two outputs that name the same file, or an output that names one of the command's
// inputs or a lesson's own file, are refused; nothing is written then.
#pragma once

#include <QString>
#include <vector>

namespace rbw::cli {

struct NamedFile {
    QString what;   // "--output", or for a protected file "the lesson's exercise.json"
    QString path;
};

// Empty when the outputs may be written; else the message (without "rbw: ").
QString outputConflict(const std::vector<NamedFile>& outputs, const std::vector<NamedFile>& protectedFiles);

// Every file directly inside `folder` (a lesson's exercise.json, scene, variants, text),
// named "the lesson's NAME".
std::vector<NamedFile> lessonFiles(const QString& folder);

} // namespace rbw::cli
