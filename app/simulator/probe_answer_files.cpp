#include "app/simulator/probe_answer_files.h"

#include "app/simulator/simulator_process.h"
#include "app/core/step_numbering.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <algorithm>
#include <map>

namespace rbw {

namespace {

OfflineAnswers failure(const QString& message)
{
    OfflineAnswers r;
    r.failure = message;
    return r;
}

// The file's lines without their line ends (\n or \r\n); a last line end is optional.
std::optional<QList<QByteArray>> readLines(const QString& path, QString& error)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        error = path + ": cannot read: " + f.errorString();
        return std::nullopt;
    }
    QByteArray bytes = f.readAll();
    if (bytes.endsWith('\n')) bytes.chop(1);
    if (bytes.isEmpty()) return QList<QByteArray>{};
    QList<QByteArray> lines = bytes.split('\n');
    for (QByteArray& l : lines) {
        if (l.endsWith('\r')) l.chop(1);
    }
    return lines;
}

// "probe 2 (motion-02), after step k = 0, its answer to \"state 0\"": the answer after
// s.step steps, worded as every screen words a state (step_numbering.h)
QString slotText(int probeNumber, const probes::Probe& p, const probes::AnswerSlot& s)
{
    return QStringLiteral("probe %1 (%2), %3, its answer to \"state %4\"")
        .arg(probeNumber)
        .arg(QString::fromStdString(p.name))
        .arg(steps::stateName(s.step))
        .arg(s.body);
}

// One answer (9 or 13 numbers) strictly, or an error naming where.
std::optional<probes::Answer> parseAnswer(const QByteArray& text, const QString& at, const QString& slot,
                                          QString& error)
{
    const AnswerParse parsed = parseAnswerLine(text);
    if (!parsed.nonFinite.isEmpty()) {
        error = at + QStringLiteral(": your simulator printed %1 (%2)").arg(parsed.nonFinite, slot);
        return std::nullopt;
    }
    if (!parsed.error.isEmpty()) {
        QByteArray shown = text.size() > 200 ? text.left(200) + "..." : text;
        error = at + QStringLiteral(": \"%1\": %2 (%3)").arg(QString::fromUtf8(shown), parsed.error, slot);
        return std::nullopt;
    }
    return parsed.values;
}

std::vector<probes::Probe> candidates(std::optional<probes::ProbeGroup> group)
{
    return probes::probesOf(group.value_or(probes::ProbeGroup::All));
}

} // namespace

OfflineAnswers readAnswersFolder(const QString& dirPath, std::optional<probes::ProbeGroup> group)
{
    const QFileInfo info(dirPath);
    if (!info.isDir()) return failure(dirPath + ": cannot read: not a folder");
    const QDir dir(dirPath);
    OfflineAnswers r;
    int number = 0;
    for (const probes::Probe& p : candidates(group)) {
        ++number;
        const QString name = QString::fromStdString(p.name);
        const QString commandsPath = dir.filePath(name + ".commands");
        const QString statesPath = dir.filePath(name + ".states");
        if (!QFileInfo::exists(commandsPath)) {
            if (!group) continue;   // not written: not asked for
            return failure(commandsPath + ": cannot read: no such file (rbw probes --output " + dirPath +
                           " --probes " + probes::probeGroupName(*group) + " writes it)");
        }
        QString error;
        const std::optional<QList<QByteArray>> commands = readLines(commandsPath, error);
        if (!commands) return failure(error);
        const std::vector<std::string> expected = probes::protocolLines(p);
        for (std::size_t k = 0; k < std::max<std::size_t>(expected.size(), commands->size()); ++k) {
            const QByteArray want = k < expected.size() ? QByteArray::fromStdString(expected[k]) : QByteArray();
            const QByteArray got = k < static_cast<std::size_t>(commands->size()) ? commands->at(k) : QByteArray();
            if (want != got) {
                return failure(QStringLiteral("%1:%2: not the workbook's probe %3 (expected \"%4\", found \"%5\"); "
                                              "write the probes again with rbw probes")
                                   .arg(commandsPath)
                                   .arg(k + 1)
                                   .arg(name, QString::fromUtf8(want), QString::fromUtf8(got)));
            }
        }
        const std::optional<QList<QByteArray>> states = readLines(statesPath, error);
        if (!states) return failure(error + " (your program's answers to " + name + ".commands)");
        const std::vector<probes::AnswerSlot> asked = probes::answerSlots(p);
        probes::Answers answers;
        for (qsizetype k = 0; k < states->size(); ++k) {
            const QString at = QStringLiteral("%1:%2").arg(statesPath).arg(k + 1);
            if (k >= static_cast<qsizetype>(asked.size())) {
                return failure(at + QStringLiteral(": an answer where none was asked for (the probe asks %1)")
                                        .arg(asked.size()));
            }
            const std::optional<probes::Answer> a =
                parseAnswer(states->at(k), at, slotText(number, p, asked[static_cast<std::size_t>(k)]), error);
            if (!a) return failure(error);
            answers.push_back(*a);
        }
        if (answers.size() < asked.size()) {
            return failure(QStringLiteral("%1: %2 answers, the probe asks %3 (none for %4: did your program stop "
                                          "early?)")
                               .arg(statesPath)
                               .arg(answers.size())
                               .arg(asked.size())
                               .arg(slotText(number, p, asked[answers.size()])));
        }
        r.probes.push_back(p);
        r.given.push_back(answers);
    }
    if (r.probes.empty()) {
        return failure(dirPath + ": no probe files (<probe>.commands) in it; rbw probes --output " + dirPath +
                       " writes them");
    }
    r.ok = true;
    return r;
}

OfflineAnswers readTrajectoryCsv(const QString& file, std::optional<probes::ProbeGroup> group)
{
    static const QByteArray kHeader = "probe,step,body,x,y,z,vx,vy,vz,wx,wy,wz,qw,qx,qy,qz";
    QString error;
    const std::optional<QList<QByteArray>> lines = readLines(file, error);
    if (!lines) return failure(error);
    if (lines->isEmpty() || lines->first() != kHeader) {
        return failure(file + ":1: the header must be \"" + QString::fromLatin1(kHeader) + "\", found \"" +
                       QString::fromUtf8(lines->isEmpty() ? QByteArray() : lines->first().left(200)) + "\"");
    }
    const std::vector<probes::Probe> all = candidates(group);
    std::map<std::string, probes::Answers> byProbe;
    std::map<std::string, int> firstLine;
    for (qsizetype k = 1; k < lines->size(); ++k) {
        const QString at = QStringLiteral("%1:%2").arg(file).arg(k + 1);
        const QList<QByteArray> fields = lines->at(k).split(',');
        if (fields.size() != 16) {
            return failure(at + QStringLiteral(": %1 fields, expected 16 (probe, step, body and 13 numbers)")
                                    .arg(fields.size()));
        }
        const std::string name = fields[0].trimmed().toStdString();
        const auto probe = std::find_if(all.begin(), all.end(), [&](const probes::Probe& p) { return p.name == name; });
        if (probe == all.end()) {
            return failure(at + ": no probe \"" + QString::fromStdString(name) + "\"" +
                           (group ? QStringLiteral(" in the group ") + probes::probeGroupName(*group) : QString()));
        }
        const int number = static_cast<int>(probe - all.begin()) + 1;
        probes::Answers& answers = byProbe[name];
        if (answers.empty()) firstLine[name] = static_cast<int>(k + 1);
        const std::vector<probes::AnswerSlot> asked = probes::answerSlots(*probe);
        if (answers.size() >= asked.size()) {
            return failure(at + QStringLiteral(": a row where none was asked for (probe %1 asks %2)")
                                    .arg(QString::fromStdString(name))
                                    .arg(asked.size()));
        }
        const probes::AnswerSlot& slot = asked[answers.size()];
        bool stepOk = false, bodyOk = false;
        const int step = fields[1].trimmed().toInt(&stepOk);
        const int body = fields[2].trimmed().toInt(&bodyOk);
        if (!stepOk || !bodyOk || step != slot.step || body != slot.body) {
            // the step column counts the steps taken, n; in words the state after step k = n - 1
            return failure(at + QStringLiteral(": step \"%1\", body \"%2\"; the next answer of %3 has step %4 (the state %5), "
                                               "body %6 (rows in the order of the probe's state commands)")
                                    .arg(QString::fromUtf8(fields[1]), QString::fromUtf8(fields[2]),
                                         QString::fromStdString(name))
                                    .arg(slot.step)
                                    .arg(steps::stateName(slot.step))
                                    .arg(slot.body));
        }
        // the quaternion's four fields are all given or all empty
        int emptyR = 0;
        for (int i = 12; i < 16; ++i) emptyR += fields[i].trimmed().isEmpty() ? 1 : 0;
        if (emptyR != 0 && emptyR != 4) {
            return failure(at + ": qw, qx, qy, qz must all be given or all be empty");
        }
        const QList<QByteArray> numbers = fields.mid(3, emptyR == 4 ? 9 : 13);
        const std::optional<probes::Answer> a = parseAnswer(numbers.join(' '), at, slotText(number, *probe, slot), error);
        if (!a) return failure(error);
        answers.push_back(*a);
    }
    OfflineAnswers r;
    for (const probes::Probe& p : all) {
        const auto found = byProbe.find(p.name);
        if (found == byProbe.end()) {
            if (!group) continue;
            return failure(file + ": no rows for probe " + QString::fromStdString(p.name) + " (the group " +
                           probes::probeGroupName(*group) + " has it)");
        }
        const std::size_t want = probes::answerSlots(p).size();
        if (found->second.size() < want) {
            return failure(QStringLiteral("%1: probe %2 has %3 rows (from line %4), it asks %5")
                               .arg(file, QString::fromStdString(p.name))
                               .arg(found->second.size())
                               .arg(firstLine[p.name])
                               .arg(want));
        }
        r.probes.push_back(p);
        r.given.push_back(found->second);
    }
    if (r.probes.empty()) return failure(file + ": no rows");
    r.ok = true;
    return r;
}

} // namespace rbw
