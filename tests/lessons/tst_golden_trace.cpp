// The refactor guard: every lesson scene (and variant), under its own integrators and
// under each registered integrator for every body, runs 200 traced steps (with a
// drag force, a push and a switched couple on the way); a hash of the complete trace
// (every entry's id, formula, body, index and value bits, the contact headers, the
// diagnostics, the step status) every 20 steps must equal the one recorded in
// tests/golden/traces.txt before the physics was reorganised (issue 9). A refactor
// that changes no result keeps every hash; any changed bit in any number fails the
// row and names the first checkpoint that differs.
//
// Entries are hashed as a set per step (sorted entry hashes), so moving a record
// call to the line that computes its value may reorder entries within a step but
// never change one. The source location of an entry is not part of the hash.
//
// To record anew after a deliberate change of results:
//   RBW_RECORD_GOLDEN=1 build/tests/tst_golden_trace   (writes tests/golden/traces.txt)
// To see what a new hash stands for, RBW_DUMP_GOLDEN=<file> writes what is hashed as
// text, one line per entry (%.17g), sorted within a step: two dumps, before and after a
// change that only adds trace rows, differ only by added lines (issue 20).
#include "tests/test_support.h"

#include "app/core/lesson_catalogue.h"
#include "physics/engine/integrator_registry.h"
#include "physics/engine/world.h"

#include <QDir>
#include <QFile>
#include <QSaveFile>
#include <QTextStream>
#include <QtTest>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>

using namespace rbw;

namespace {

constexpr int kSteps = 200;
constexpr int kCheckpointEvery = 20;

// FNV-1a, 64 bit: a plain, fixed, portable byte hash.
struct Fnv {
    std::uint64_t h = 1469598103934665603ULL;
    void bytes(const void* p, size_t n)
    {
        const auto* c = static_cast<const unsigned char*>(p);
        for (size_t i = 0; i < n; ++i) {
            h ^= c[i];
            h *= 1099511628211ULL;
        }
    }
    void str(const char* s) { bytes(s, std::strlen(s) + 1); }
    void str(const std::string& s) { bytes(s.data(), s.size() + 1); }
    void num(double d) { bytes(&d, sizeof d); }
    void num(long long i) { bytes(&i, sizeof i); }
    void vec(const Vec3& v) { num(v.x()); num(v.y()); num(v.z()); }
};

std::uint64_t entryHash(const TraceEntry& e)
{
    Fnv f;
    f.str(e.info->id);
    f.str(e.info->symbol);
    f.str(e.info->formula);
    f.str(e.info->unit);
    f.num(static_cast<long long>(e.info->frame));
    f.num(static_cast<long long>(e.info->stage));
    f.num(static_cast<long long>(e.body));
    f.num(static_cast<long long>(e.index));
    f.num(static_cast<long long>(e.value.index()));
    for (double d : test::flatten(e.value)) f.num(d);
    return f.h;
}

QTextStream* gDump = nullptr;   // RBW_DUMP_GOLDEN's file, when set
QString gDumpRow;

void dumpStep(const StepTrace& t, const StepStatus& st)
{
    const QString head = gDumpRow + QStringLiteral(" k=%1 ").arg(t.step);
    QStringList lines;
    for (const TraceEntry& e : t.entries) {
        QString l = head + QStringLiteral("%1|%2|%3|%4|%5|").arg(QLatin1String(e.info->id), QLatin1String(e.info->formula))
                               .arg(e.body).arg(e.index).arg(e.value.index());
        for (double d : test::flatten(e.value)) l += QString::asprintf(" %.17g", d);
        lines << l;
    }
    for (const ContactHeader& c : t.contacts) {
        lines << head + QStringLiteral("contact %1 %2 %3 %4 %5 %6 %7").arg(c.bodyA).arg(c.bodyB).arg(c.plane)
                            .arg(QLatin1String(c.feature), QLatin1String(c.resolution)).arg(c.pointCount).arg(c.separating);
    }
    lines << head + QString::asprintf("energy %.17g %.17g status %d ", t.diagnostics.total, t.time, int(st.ok)) +
                 QString::fromStdString(st.kind);
    lines.sort();
    for (const QString& l : lines) *gDump << l << '\n';
}

void hashStep(Fnv& f, const StepTrace& t, const StepStatus& st)
{
    if (gDump != nullptr) dumpStep(t, st);
    f.num(static_cast<long long>(t.step));
    f.num(t.time);
    std::vector<std::uint64_t> hs;
    hs.reserve(t.entries.size());
    for (const TraceEntry& e : t.entries) hs.push_back(entryHash(e));
    std::sort(hs.begin(), hs.end());
    f.num(static_cast<long long>(hs.size()));
    f.bytes(hs.data(), hs.size() * sizeof(std::uint64_t));
    for (const ContactHeader& c : t.contacts) {
        f.num(static_cast<long long>(c.bodyA));
        f.num(static_cast<long long>(c.bodyB));
        f.num(static_cast<long long>(c.plane));
        f.str(c.feature);
        f.str(c.resolution);
        f.num(static_cast<long long>(c.pointCount));
        f.num(static_cast<long long>(c.separating));
    }
    const Diagnostics& d = t.diagnostics;
    f.num(d.kineticTranslational); f.num(d.kineticRotational); f.num(d.kinetic);
    f.num(d.potential); f.num(d.total); f.vec(d.P_W); f.vec(d.L_O_W);
    for (const BodyDiagnostics& b : d.bodies) {
        f.num(b.kineticTranslational); f.num(b.kineticRotational); f.num(b.kinetic);
        f.vec(b.L_W); f.num(b.L_norm);
    }
    f.num(static_cast<long long>(st.ok));
    f.str(st.kind);
    f.str(st.message);
}

// "<hash at step 19> <hash at 39> ... <final state>": one line of the golden file.
QString runHashes(SceneDef scene)
{
    World world(std::move(scene));
    StepTrace trace;
    Fnv f;
    QStringList checkpoints;
    for (int k = 0; k < kSteps; ++k) {
        // Interaction paths: a one-step drag on the first movable body at step 30,
        // and every switchable couple switched off at step 50 and on at step 120.
        if (k == 30) {
            for (int b = 0; b < static_cast<int>(world.states().size()); ++b) {
                if (!world.scene().bodies[b].fixed) {
                    world.applyForceOnce(b, world.bodyToWorld(b, Vec3(0.1, 0.2, -0.1)), Vec3(0.5, -0.3, 0.7));
                    break;
                }
            }
        }
        for (int j = 0; j < static_cast<int>(world.scene().torques.size()); ++j) {
            if (k == 50) world.setTorqueEnabled(j, false);
            if (k == 120) world.setTorqueEnabled(j, true);
        }
        trace.clear();
        const StepStatus st = world.step(&trace);
        hashStep(f, trace, st);
        if ((k + 1) % kCheckpointEvery == 0 || !st.ok) {
            checkpoints << QString::number(f.h, 16);
        }
        if (!st.ok) break;
    }
    Fnv s;
    for (const BodyState& b : world.states()) {
        s.vec(b.x_W); s.vec(b.v_W); s.vec(b.L_W); s.vec(b.omega_W);
        s.num(b.q_WB.w()); s.vec(b.q_WB.vec());
    }
    checkpoints << QString::number(s.h, 16);
    return checkpoints.join(QLatin1Char(' '));
}

QString goldenPath() { return QStringLiteral(RBW_SOURCE_DIR "/tests/golden/traces.txt"); }

struct Row {
    QString name;
    SceneDef scene;
};

// Every scene file of every lesson, as written and with each integrator for all bodies.
std::vector<Row> allRows()
{
    std::vector<Row> rows;
    const QDir lessons(QStringLiteral(RBW_SOURCE_DIR "/lessons"));
    for (const QString& dir : lessons.entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name)) {
        const QDir d(lessons.filePath(dir));
        for (const QString& file : d.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name)) {
            if (file == QLatin1String("exercise.json")) continue;   // not a scene (docs/exercises.md)
            const QString rel = dir + QLatin1Char('/') + file;
            const SceneDef scene = test::lessonScene(rel);
            rows.push_back({rel + QStringLiteral(" as-written"), scene});
            for (const IntegratorInfo& info : integratorCatalogue()) {
                SceneDef s = scene;
                s.integrator = info.name;
                for (BodyDef& b : s.bodies) b.integrator.clear();
                rows.push_back({rel + QLatin1Char(' ') + QLatin1String(info.name), s});
            }
        }
    }
    return rows;
}

std::map<QString, QString> readGolden()
{
    std::map<QString, QString> out;
    QFile f(goldenPath());
    if (!f.open(QIODevice::ReadOnly | QIODevice::Text)) return out;
    while (!f.atEnd()) {
        const QString line = QString::fromUtf8(f.readLine()).trimmed();
        const int bar = line.indexOf(QLatin1Char('|'));
        if (line.isEmpty() || line.startsWith(QLatin1Char('#')) || bar < 0) continue;
        out[line.left(bar).trimmed()] = line.mid(bar + 1).trimmed();
    }
    return out;
}

} // namespace

class TestGoldenTrace : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        if (qEnvironmentVariableIsSet("RBW_RECORD_GOLDEN")) {
            QDir().mkpath(QStringLiteral(RBW_SOURCE_DIR "/tests/golden"));
            QSaveFile out(goldenPath());
            QVERIFY(out.open(QIODevice::WriteOnly | QIODevice::Text));
            out.write("# tst_golden_trace: scene integrator | trace hash every 20 steps ... final-state hash\n");
            for (const Row& r : allRows()) {
                out.write((r.name + QStringLiteral(" | ") + runHashes(r.scene) + QLatin1Char('\n')).toUtf8());
            }
            QVERIFY(out.commit());
        }
        if (qEnvironmentVariableIsSet("RBW_DUMP_GOLDEN")) {
            QSaveFile f(qEnvironmentVariable("RBW_DUMP_GOLDEN"));
            QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Text));
            QTextStream ts(&f);
            gDump = &ts;
            for (const Row& r : allRows()) {
                gDumpRow = r.name;
                runHashes(r.scene);
            }
            gDump = nullptr;
            ts.flush();
            QVERIFY(f.commit());
        }
        golden_ = readGolden();
        QVERIFY2(!golden_.empty(), qPrintable(QStringLiteral("no golden file at ") + goldenPath()));
    }

    void sameTraceAsRecorded_data()
    {
        QTest::addColumn<int>("row");
        const std::vector<Row> rows = allRows();
        rows_ = rows;
        for (int i = 0; i < static_cast<int>(rows.size()); ++i) {
            QTest::newRow(qPrintable(rows[i].name)) << i;
        }
    }

    void sameTraceAsRecorded()
    {
        QFETCH(int, row);
        const Row& r = rows_[row];
        const auto it = golden_.find(r.name);
        QVERIFY2(it != golden_.end(), qPrintable(QStringLiteral("no golden line for ") + r.name));
        const QStringList expected = it->second.split(QLatin1Char(' '));
        const QStringList actual = runHashes(r.scene).split(QLatin1Char(' '));
        for (int i = 0; i < std::min(expected.size(), actual.size()); ++i) {
            QVERIFY2(actual[i] == expected[i],
                     qPrintable(QStringLiteral("first difference at checkpoint %1 (after step %2)")
                                    .arg(i)
                                    .arg((i + 1) * kCheckpointEvery - 1)));
        }
        QCOMPARE(actual.size(), expected.size());
    }

    // Negative control: the hash sees a one-ulp change of one value in one entry.
    void hashSeesOneUlp()
    {
        World world(test::lessonScene(QStringLiteral("01-one-step/scene.json")));
        StepTrace trace;
        const StepStatus st = world.step(&trace);
        Fnv a;
        hashStep(a, trace, st);
        const auto it = std::find_if(trace.entries.begin(), trace.entries.end(),
                                     [](const TraceEntry& x) { return std::holds_alternative<Vec3>(x.value); });
        QVERIFY(it != trace.entries.end());
        TraceEntry& e = *it;
        Vec3 v = std::get<Vec3>(e.value);
        v.x() = std::nextafter(v.x(), 1e300);
        e.value = v;
        Fnv b;
        hashStep(b, trace, st);
        QVERIFY(a.h != b.h);
    }

private:
    std::map<QString, QString> golden_;
    std::vector<Row> rows_;
};

QTEST_GUILESS_MAIN(TestGoldenTrace)
#include "tst_golden_trace.moc"
