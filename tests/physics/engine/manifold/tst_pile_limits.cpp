// Piles of overlapping boxes and the manifold model's work limits (issue 22, item 4;
// physics/engine/manifold/work_limits.h).
//
// Before the limits, one manifold step on n coincident boxes built a manifold for each of
// the n (n - 1) / 2 pairs: 1 000 boxes took 1.8 GB and 15 s, 2 000 ended in
// std::bad_alloc. Here each scene takes one step in a child process (fork) whose address
// space is capped with setrlimit(RLIMIT_AS) at what the test process maps already plus
// kBudget, so the cap does not reach the rest of the suite. The child reports how the
// step ended through its exit status and the status message through a pipe.
//
// Rows:
//   coincident      1 000 unit boxes at one point: every bounding box overlaps 999 others.
//                   The tree search finishes a subtree of 256 boxes as two subtrees of 128
//                   (2 * 128 * 127 / 2 = 16 256 pairs) and then pairs across them, so a box
//                   reaches 129 pairs after about 16 300 pairs, before the 32 * 1 000 + 128
//                   = 32 128 of the candidate limit: the per-body limit stops the step.
//   clusters        10 clusters of 100 coincident boxes, 10 m apart: 99 pairs per box
//                   (<= 128), but 10 * 100 * 99 / 2 = 49 500 pairs > 32 * 1 000 + 128 =
//                   32 128: the candidate limit stops the step.
//   lattice         1 000 unit boxes in a touching 10 x 10 x 10 block on the ground: at most
//                   26 neighbours per box (a 3 x 3 x 3 block), 13 pairs per box on
//                   average, below both limits: the step succeeds in the same budget
//                   (the negative control: the limits do not stop a dense legal pile).
//   coincident 2000 2 000 coincident boxes (bad_alloc before the limits): the per-body
//                   limit, in the same budget.
#include "tests/test_support.h"

#include "physics/engine/manifold/work_limits.h"
#include "physics/engine/world.h"

#include <QtTest>

#include <fstream>
#include <new>
#include <string>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace rbw;

namespace {

// What the child may allocate beyond the test process's mapping at the fork [bytes]:
// 1 000 boxes' states, the broad phase's pairs up to the limit (32 128 pairs of 8 bytes)
// and, for the lattice, about 13 000 manifolds of about 2 kB and the solver's rows.
constexpr rlim_t kBudget = rlim_t{256} << 20;

// The child's exit statuses.
constexpr int kStepOk = 0;
constexpr int kStopPerBody = 10;      // kind work-limit, quantity contact_pairs_per_body
constexpr int kStopCandidates = 11;   // kind work-limit, quantity broad_phase_candidates
constexpr int kOtherStatus = 12;
constexpr int kBadAlloc = 13;

// Under AddressSanitizer (the asan preset, scripts/run-asan-tests.sh) an allocation over
// the address-space limit does not throw: ASan's allocator reports "allocator is out of
// memory" and exits with its exitcode, 1 (allocator_may_return_null=0, the default).
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kUnderAsan = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kUnderAsan = true;
#else
constexpr bool kUnderAsan = false;
#endif
#else
constexpr bool kUnderAsan = false;
#endif
constexpr int kAsanOutOfMemory = 1;

enum class Pile { Coincident, Clusters, Lattice };

SceneDef pileScene(Pile pile, int n)
{
    SceneDef s;
    s.name = "pile";
    s.dt = 1.0 / 60.0;
    s.steps = 1;
    s.integrator = "symplectic-euler";
    s.g_W = Vec3(0.0, -9.81, 0.0);
    s.friction = 0.5;
    s.restitution = 0.0;
    s.contactModel = ContactModel::Manifold;
    PlaneDef ground;   // y = 0
    ground.name = "ground";
    s.planes.push_back(ground);
    for (int i = 0; i < n; ++i) {
        BodyDef b;
        b.name = "b";
        b.name += std::to_string(i);
        b.size = Vec3::Ones();
        b.mass = 1.0;
        switch (pile) {
        case Pile::Coincident: b.x0_W = Vec3(0.0, 0.5, 0.0); break;
        case Pile::Clusters: b.x0_W = Vec3(10.0 * double(i / 100), 0.5, 0.0); break;
        // x = ix, y = 0.5 + iy, z = iz: faces touch, the bottom layer on the ground
        case Pile::Lattice: b.x0_W = Vec3(double(i % 10), 0.5 + double(i / 100), double((i / 10) % 10)); break;
        }
        s.bodies.push_back(b);
    }
    return s;
}

// The mapped address space of this process [bytes] (VmSize of /proc/self/status).
rlim_t mappedBytes()
{
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key) {
        if (key == "VmSize:") {
            rlim_t kib = 0;
            status >> kib;
            return kib * 1024;
        }
        status.ignore(1 << 16, '\n');
    }
    return 0;
}

struct ChildResult {
    bool exited = false;
    int code = -1;
    int signal = 0;
    QString message;
};

// One step of `scene` in a child whose address space is capped at mapped + kBudget.
ChildResult stepInChild(const SceneDef& scene)
{
    int fds[2];
    if (pipe(fds) != 0) qFatal("pipe failed");
    const rlim_t limit = mappedBytes() + kBudget;
    const pid_t pid = fork();
    if (pid < 0) qFatal("fork failed");
    if (pid == 0) {
        close(fds[0]);
        const rlimit cap{limit, limit};
        if (setrlimit(RLIMIT_AS, &cap) != 0) _exit(kOtherStatus);
        int code = kOtherStatus;
        try {
            World world(scene);
            const StepStatus& st = world.step();
            if (st.ok) {
                code = kStepOk;
            } else {
                if (st.kind == "work-limit" && st.quantity == "contact_pairs_per_body") code = kStopPerBody;
                if (st.kind == "work-limit" && st.quantity == "broad_phase_candidates") code = kStopCandidates;
                const ssize_t written = write(fds[1], st.message.data(), st.message.size());
                (void)written;
            }
        } catch (const std::bad_alloc&) {
            code = kBadAlloc;
        }
        close(fds[1]);
        _exit(code);
    }
    close(fds[1]);
    QByteArray text;
    char buf[4096];
    for (ssize_t got; (got = read(fds[0], buf, sizeof buf)) > 0;) text.append(buf, static_cast<int>(got));
    close(fds[0]);
    int wstatus = 0;
    waitpid(pid, &wstatus, 0);
    ChildResult r;
    r.exited = WIFEXITED(wstatus);
    r.code = r.exited ? WEXITSTATUS(wstatus) : -1;
    r.signal = WIFSIGNALED(wstatus) ? WTERMSIG(wstatus) : 0;
    r.message = QString::fromUtf8(text);
    return r;
}

} // namespace

class TestPileLimits : public QObject {
    Q_OBJECT

private slots:
    void stepsWithinMemory_data();
    void stepsWithinMemory();
    void budgetIsReal();
};

void TestPileLimits::stepsWithinMemory_data()
{
    QTest::addColumn<int>("pile");
    QTest::addColumn<int>("n");
    QTest::addColumn<int>("expected");
    QTest::addColumn<QString>("words");   // the message names the limit and the number
    QTest::newRow("1000 coincident") << int(Pile::Coincident) << 1000 << kStopPerBody
                                     << QStringLiteral("contact_pairs_per_body|more than 128 others|\"b");
    QTest::newRow("2000 coincident") << int(Pile::Coincident) << 2000 << kStopPerBody
                                     << QStringLiteral("contact_pairs_per_body|more than 128 others");
    QTest::newRow("10 clusters of 100") << int(Pile::Clusters) << 1000 << kStopCandidates
                                        << QStringLiteral("broad_phase_candidates|more than 32128 pairs");
    QTest::newRow("1000 in a lattice") << int(Pile::Lattice) << 1000 << kStepOk << QString();
}

void TestPileLimits::stepsWithinMemory()
{
    QFETCH(int, pile);
    QFETCH(int, n);
    QFETCH(int, expected);
    QFETCH(QString, words);
    const ChildResult r = stepInChild(pileScene(static_cast<Pile>(pile), n));
    QVERIFY2(r.exited, qPrintable(QStringLiteral("the child was killed by signal %1").arg(r.signal)));
    QVERIFY2(r.code != kBadAlloc, "std::bad_alloc: the step needed more than the budget");
    QVERIFY2(r.code == expected,
             qPrintable(QStringLiteral("exit %1, expected %2; message: %3").arg(r.code).arg(expected).arg(r.message)));
    if (!words.isEmpty()) {
        for (const QString& w : words.split(QLatin1Char('|'))) {
            QVERIFY2(r.message.contains(w), qPrintable(QStringLiteral("\"%1\" not in: %2").arg(w, r.message)));
        }
    }
}

// Negative control: the cap is real. A child that allocates twice the budget in one
// block fails with std::bad_alloc under the same limit (under ASan: its allocator's
// out-of-memory exit), so a step that passes above did stay within it.
void TestPileLimits::budgetIsReal()
{
    const rlim_t limit = mappedBytes() + kBudget;
    const pid_t pid = fork();
    QVERIFY(pid >= 0);
    if (pid == 0) {
        const rlimit cap{limit, limit};
        if (setrlimit(RLIMIT_AS, &cap) != 0) _exit(kOtherStatus);
        try {
            std::vector<char> block(2 * kBudget, 1);
            _exit(block.back() == 1 ? kStepOk : kOtherStatus);
        } catch (const std::bad_alloc&) {
            _exit(kBadAlloc);
        }
    }
    int wstatus = 0;
    waitpid(pid, &wstatus, 0);
    QVERIFY(WIFEXITED(wstatus));
    QCOMPARE(WEXITSTATUS(wstatus), kUnderAsan ? kAsanOutOfMemory : kBadAlloc);
}

QTEST_GUILESS_MAIN(TestPileLimits)
#include "tst_pile_limits.moc"
