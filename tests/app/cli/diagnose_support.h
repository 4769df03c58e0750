// Shared by the rbw diagnose tests (tests/app/cli/tst_diagnose*.cpp, issue 23): the
// example simulators' paths and running rbw diagnose for its JSON report.
#pragma once

#include "tests/test_support.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <QStringList>

namespace rbw::test::diagnose {

inline const QString kReference = QStringLiteral(RBW_REFERENCE_SIMULATOR_PATH);
inline const QString kAdapterStub = QStringLiteral(RBW_TUM_ADAPTER_STUB_PATH);

struct Diagnosed {
    int exitCode = -1;
    QJsonObject doc;
};

inline Diagnosed diagnoseJson(const QString& simulator, const QStringList& more = {})
{
    const rbw::test::RbwRun r =
        rbw::test::runRbw(QStringList{"diagnose", "--simulator", simulator, "--format", "json"} + more);
    if (!r.err.isEmpty()) qWarning("stderr: %s", qPrintable(r.err));
    return {r.exitCode, QJsonDocument::fromJson(r.out).object()};
}

// The names (with the version) of the template's public tests that passed.
inline QStringList templatePassed(const QJsonObject& doc)
{
    QStringList names;
    for (const QJsonValue& v : doc.value("template_tests").toObject().value("tests").toArray()) {
        const QJsonObject t = v.toObject();
        if (!t.value("passed").toBool()) continue;
        const QString version = t.value("version").toString();
        names << t.value("name").toString() + (version.isEmpty() ? QString() : " (" + version + ")");
    }
    return names;
}

// A process runs when /proc has it and it is not a zombie (a container's init may
// leave killed orphans unreaped).
inline bool running(qint64 pid)
{
    QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!stat.open(QIODevice::ReadOnly)) return false;
    const QByteArray text = stat.readAll();
    const qsizetype close = text.lastIndexOf(')');
    return close >= 0 && close + 2 < text.size() && text[close + 2] != 'Z';
}

} // namespace rbw::test::diagnose
