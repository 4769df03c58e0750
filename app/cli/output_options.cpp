#include "app/cli/output_options.h"

#include "app/output/output_target.h"

#include <QDir>
#include <QFileInfo>

namespace rbw::cli {

QString outputConflict(const std::vector<NamedFile>& outputs, const std::vector<NamedFile>& protectedFiles)
{
    std::vector<OutputTarget> targets;
    for (const NamedFile& o : outputs) {
        const OutputTarget t = resolveOutputTarget(o.path);
        if (t.kind == OutputTarget::Kind::Refused) {
            return QStringLiteral("%1: %2: cannot write: %3").arg(o.path, o.what, t.reason);
        }
        for (size_t j = 0; j < targets.size(); ++j) {
            if (targets[j].identity == t.identity) {
                return QStringLiteral("%1 and %2 name the same file (%3): each output needs a file of its own")
                    .arg(outputs[j].what, o.what, o.path);
            }
        }
        for (const NamedFile& p : protectedFiles) {
            if (resolveOutputTarget(p.path).identity == t.identity) {
                return QStringLiteral("%1: %2 is %3, which is never overwritten: write to another file")
                    .arg(o.what, o.path, p.what);
            }
        }
        targets.push_back(t);
    }
    return {};
}

std::vector<NamedFile> lessonFiles(const QString& folder)
{
    std::vector<NamedFile> files;
    const QDir dir(folder);
    for (const QFileInfo& f : dir.entryInfoList(QDir::Files | QDir::Hidden | QDir::System, QDir::Name)) {
        files.push_back(NamedFile{QStringLiteral("the lesson's %1").arg(f.fileName()), f.filePath()});
    }
    return files;
}

} // namespace rbw::cli
