#include "fuzz/fuzz_scene.h"

#include "app/output/csv_output.h"
#include "app/output/json_output.h"
#include "app/scene/scene_loader.h"
#include "physics/engine/scene.h"
#include "physics/engine/world.h"

#include <QBuffer>
#include <QByteArray>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <QTextStream>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace rbw::fuzz {

namespace {

const QString kLabel = QStringLiteral("fuzz.json");

[[noreturn]] void fail(const char* what, const QString& detail = {})
{
    std::fprintf(stderr, "fuzzOneScene: %s%s%s\n", what, detail.isEmpty() ? "" : ": ",
                 detail.toLocal8Bit().constData());
    std::fflush(stderr);
    std::abort();
}

bool checkFinite()
{
    // On unless RBW_FUZZ_CHECK_FINITE=0.
    static const bool on = !qEnvironmentVariableIsSet("RBW_FUZZ_CHECK_FINITE") ||
                           qEnvironmentVariableIntValue("RBW_FUZZ_CHECK_FINITE") != 0;
    return on;
}

bool rawBytes()
{
    static const bool on = qEnvironmentVariableIntValue("RBW_FUZZ_RAW_BYTES") != 0;
    return on;
}

// The first non-finite number in a JSON value, as "path = value"; empty if none.
QString nonFinite(const QJsonValue& v, const QString& path)
{
    if (v.isDouble()) {
        return std::isfinite(v.toDouble()) ? QString() : path + " = " + QString::number(v.toDouble());
    }
    if (v.isArray()) {
        const QJsonArray a = v.toArray();
        for (qsizetype i = 0; i < a.size(); ++i) {
            const QString bad = nonFinite(a.at(i), path + '[' + QString::number(i) + ']');
            if (!bad.isEmpty()) return bad;
        }
    }
    if (v.isObject()) {
        const QJsonObject o = v.toObject();
        for (auto it = o.begin(); it != o.end(); ++it) {
            const QString bad = nonFinite(it.value(), path + '.' + it.key());
            if (!bad.isEmpty()) return bad;
        }
    }
    return {};
}

// Under RBW_FUZZ_CHECK_FINITE: the members a JSON run prints hold only finite numbers.
void checkJson(const QJsonObject& o, const char* what)
{
    if (!checkFinite()) return;
    const QString bad = nonFinite(o, QStringLiteral("$"));
    if (!bad.isEmpty()) fail(what, bad);
}

// The CSV rows (not the header, whose cells are body names) hold only finite numbers.
void checkCsvRows(const QString& csv)
{
    const QStringList lines = csv.split('\n', Qt::SkipEmptyParts);
    for (qsizetype i = 1; i < lines.size(); ++i) {
        for (const QString& cell : lines[i].split(',')) {
            bool ok = false;
            const double x = cell.toDouble(&ok);
            if (!ok || !std::isfinite(x)) fail("non-finite cell in the CSV output", lines[i]);
        }
    }
}

void checkBlowUp(const StepStatus& status)
{
    if (status.message.empty()) fail("a blow-up without a message");
    checkJson(blowUpToJson(status, kLabel), "non-finite number in the blow-up report");
}

// `rbw run --format json` (--trace last, app/cli/main.cpp): the initial state is
// checked, every step is traced (a traced step checks all it records), and the
// document is streamed with the last step's trace, or ends with the blow-up.
void runJson(const SceneDef& scene, long steps)
{
    World world(scene);
    QBuffer out;
    out.open(QIODevice::WriteOnly);
    JsonRunWriter json(out, world, kLabel);
    json.begin();
    if (const StepStatus initial = world.checkOutputs(); !initial.ok) {
        checkBlowUp(initial);
        json.finishBlowUp(initial);
        return;
    }
    StepTrace current;
    for (long k = 0; k < steps; ++k) {
        const StepStatus status = world.step(&current);
        if (!status.ok) {
            checkBlowUp(status);
            json.finishBlowUp(status);
            return;
        }
    }
    if (steps > 0) {
        checkJson(traceToJson(current, world.scene()), "non-finite number in the trace");
        json.addTrace(current);
    }
    checkJson(runResultToJson(world), "non-finite number in the result");
    json.finish();
    if (!out.data().startsWith('{') || !out.data().trimmed().endsWith('}')) fail("the JSON output is not one object");
}

// `rbw run --format csv`: untraced steps, each checked before its row is written.
void runCsv(const SceneDef& scene, long steps)
{
    World world(scene);
    QString text;
    QTextStream out(&text);
    Diagnostics d = world.diagnostics();
    if (const StepStatus initial = world.checkOutputs(d); !initial.ok) {
        checkBlowUp(initial);
        return;
    }
    CsvWriter csv(out);
    csv.writeHeader(world.scene());
    csv.writeRow(world, d);
    for (long k = 0; k < steps; ++k) {
        StepStatus status = world.step();
        if (status.ok) {
            d = world.diagnostics();
            status = world.checkOutputs(d);
        }
        if (!status.ok) {
            checkBlowUp(status);
            break;
        }
        csv.writeRow(world, d);
    }
    out.flush();
    if (checkFinite()) checkCsvRows(text);
}

} // namespace

int fuzzOneScene(const std::uint8_t* data, std::size_t size)
{
    // A copy, '\0'-terminated like the QFile::readAll() of loadSceneFile() and every other
    // caller; RBW_FUZZ_RAW_BYTES=1 passes the bytes as they are (fromRawData, no
    // terminator), to check that the loader stays within QByteArray::size().
    const char* const chars = reinterpret_cast<const char*>(data);
    const qsizetype n = static_cast<qsizetype>(size);
    const QByteArray bytes = rawBytes() ? QByteArray::fromRawData(chars, n) : QByteArray(chars, n);
    SceneLoadResult loaded = parseScene(bytes, kLabel);
    if (!loaded.ok()) {
        // A refused file always says why, naming the file.
        if (loaded.errors.isEmpty()) fail("scene refused without a message");
        for (const QString& e : loaded.errors) {
            if (!e.startsWith(kLabel + ": ")) fail("error message does not name the file", e);
        }
        return 0;
    }
    if (!loaded.errors.isEmpty()) fail("scene loaded but with errors", loaded.errors.join('\n'));

    SceneDef scene = std::move(*loaded.scene);
    // World asserts this; check it here too, so release builds catch it as well.
    if (!validate(scene).empty()) fail("the loader returned a scene that validate() refuses");
    const long steps = std::clamp(scene.steps, 0L, kMaxSteps);
    runJson(scene, steps);
    runCsv(scene, steps);
    return 0;
}

} // namespace rbw::fuzz
