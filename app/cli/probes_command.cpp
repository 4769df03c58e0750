#include "app/cli/probes_command.h"
#include "app/cli/standard_output.h"

#include "app/output/atomic_file.h"
#include "physics/workbook/probes/probes.h"

#include <QDir>
#include <QFileInfo>
#include <QTextStream>

namespace rbw {

namespace {

int fail(const QString& message)
{
    QTextStream(stderr) << "rbw: probes: " << message << '\n';
    return 2;
}

} // namespace

int runProbesCommand(const QCommandLineParser& parser, const QStringList& arguments)
{
    if (!arguments.isEmpty()) return fail("takes no file, got \"" + arguments.join(' ') + "\" (use --output DIR)");
    if (!parser.isSet("output")) return fail("--output DIR is required (the folder the probe files go to)");
    const QString groupName = parser.isSet("probes") ? parser.value("probes") : QStringLiteral("all");
    const std::optional<probes::ProbeGroup> group = probes::probeGroupNamed(groupName.toStdString());
    if (!group) return fail("--probes: must be motion, collision or all, got \"" + groupName + "\"");

    const QString dirPath = parser.value("output");
    const QFileInfo info(dirPath);
    if (info.exists() && !info.isDir()) return fail(dirPath + ": cannot write: it is not a folder");
    if (!QDir().mkpath(dirPath)) return fail(dirPath + ": cannot write: the folder cannot be made");

    const std::vector<probes::Probe> all = probes::probesOf(*group);
    for (const probes::Probe& p : all) {
        QByteArray bytes;
        for (const std::string& line : probes::protocolLines(p)) bytes += QByteArray::fromStdString(line) + '\n';
        const QString path = QDir(dirPath).filePath(QString::fromStdString(p.name) + ".commands");
        QString error;
        if (!writeFileAtomically(path, bytes, &error)) return fail(error);
    }
    QTextStream& out = cli::out();
    out << "rbw probes: " << all.size() << ' ' << probes::probeGroupName(*group) << " probes written to " << dirPath
        << " (one .commands file each); run your program on each, its answers to <probe>.states, then "
           "rbw diagnose "
        << dirPath << '\n';
    return 0;
}

} // namespace rbw
