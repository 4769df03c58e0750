// The probes of "Check my simulator" (issue 23, physics/workbook/probes/): well formed,
// replayed right (against hand-derived numbers and against the engine's world), and
// the distinguishability table: every motion mistake model and the right algorithm
// replayed over the motion probes, no two giving the same answers.
//
// Hand derivation (motion-02, step 1): box 0.8 x 0.5 x 1.2, M = 3, x0 = (-1, 0.5, 2),
// r = 1 (never set), v0 = (0.5, -0.2, 0.3), f = (1, 2, -1) at p = (-0.7, 0.8, 2.4), h = 0.25:
//   x1 = x0 + h v0 = (-0.875, 0.45, 2.075)
//   v1 = v0 + h f/M = (0.5 + 0.25/3, -0.2 + 0.5/3, 0.3 - 0.25/3)
//   q = (p - x) x f = (0.3, 0.3, 0.4) x (1, 2, -1) = (-1.1, 0.7, 0.3);  L1 = h q = (-0.275, 0.175, 0.075)
//   omega0 = 0, so r1 = 1 and I^-1 = I0^-1;  I0 = M/12 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2)
//      = 0.25 diag(1.69, 2.08, 0.89) = diag(0.4225, 0.52, 0.2225)
//   omega1 = (-0.275/0.4225, 0.175/0.52, 0.075/0.2225)
#include "tests/test_support.h"

#include "physics/workbook/probes/probe_models.h"
#include "physics/workbook/probes/probe_verdict.h"
#include "physics/workbook/probes/probes.h"
#include "physics/workbook/probes/replay.h"

#include <QtTest>

#include <optional>

using namespace rbw::probes;
using rbw::Mistake;
using rbw::Vec3;

namespace {

// The answers without r: what the TUM template's adapter prints (9 numbers).
Answers withoutOrientation(Answers a)
{
    for (Answer& x : a) x.resize(9);
    return a;
}

// The first probe on which the two models' answers (x, v, omega only) differ by more
// than ten times the tolerance, both ways round; -1 when none does.
int separatingProbe(const std::vector<Probe>& probes, const ReplayModel& a, const ReplayModel& b)
{
    for (int p = 0; p < static_cast<int>(probes.size()); ++p) {
        const Answers ra = withoutOrientation(replay(probes[p], a));
        const Answers rb = withoutOrientation(replay(probes[p], b));
        if (firstDivergence(probes[p], ra, rb, 10.0) && firstDivergence(probes[p], rb, ra, 10.0)) return p;
    }
    return -1;
}

QString describe(const Divergence& d)
{
    return QStringLiteral("step %1, body %2, %3[%4]: %5 vs %6")
        .arg(d.step)
        .arg(d.body)
        .arg(QString::fromStdString(d.quantity))
        .arg(d.component)
        .arg(d.expected[d.component], 0, 'g', 10)
        .arg(d.given[d.component], 0, 'g', 10);
}

} // namespace

class TestProbes : public QObject {
    Q_OBJECT
private slots:
    void probesAreWellFormedAndPlain()
    {
        const std::vector<std::string> issues = probesAreWellFormed(motionProbes());
        QVERIFY2(issues.empty(), issues.empty() ? "" : issues.front().c_str());
        QVERIFY(motionProbes().size() >= 4);
        // Every number is a plain decimal: no exponent, nan or inf; masses whole numbers.
        for (const Probe& p : motionProbes()) {
            const std::vector<std::string> lines = protocolLines(p);
            QCOMPARE(QString::fromStdString(lines.front()), QStringLiteral("reset"));
            QCOMPARE(QString::fromStdString(lines.back()), QStringLiteral("quit"));
            static const QRegularExpression plain(QStringLiteral("^-?[0-9]+(\\.[0-9]+)?$"));
            for (const std::string& line : lines) {
                const QStringList words = QString::fromStdString(line).split(' ');
                for (const QString& w : words.mid(1)) QVERIFY2(plain.match(w).hasMatch(), line.c_str());
                if (words.front() == "add_body") QVERIFY2(!words.last().contains('.'), line.c_str());
            }
        }
        QCOMPARE(QString::fromStdString(plainDecimal(0.1)), QStringLiteral("0.1"));
        QCOMPARE(QString::fromStdString(plainDecimal(-2.0)), QStringLiteral("-2"));
        QCOMPARE(QString::fromStdString(plainDecimal(-0.0)), QStringLiteral("0"));
        QCOMPARE(QString::fromStdString(plainDecimal(1e-5)), QStringLiteral("0.00001"));
        const double third = 1.0 / 3.0;
        QCOMPARE(std::stod(plainDecimal(third)), third);   // reads back exactly
    }

    // Negative control: the rule check names each broken rule.
    void brokenProbeIsRefused()
    {
        Probe bad{"bad", "breaks every rule",
                  {addBody(Vec3(0, 0, 0), Vec3(1, 0, 1), 0), step(0.1), setOrientation(0, turn(10, Vec3(0, 0, 1))),
                   setVelocity(0, Vec3(1, 0, 0)), step(0.2), state(3)}};
        const std::vector<std::string> issues = probesAreWellFormed({bad});
        QStringList all;
        for (const std::string& s : issues) all << QString::fromStdString(s);
        const QString text = all.join('\n');
        for (const char* expected : {"mass", "size", "set_orientation after", "set_velocity after",
                                     "different h", "body 3"}) {
            QVERIFY2(text.contains(QLatin1String(expected)), qPrintable(text));
        }
    }

    void replayMatchesHandDerivation()
    {
        const Probe& p = motionProbes()[1];
        QCOMPARE(QString::fromStdString(p.name), QStringLiteral("motion-02"));
        const Answers a = replay(p, {});
        QCOMPARE(a.size(), std::size_t(4));
        QCOMPARE(a[0], (Answer{-1, 0.5, 2, 0.5, -0.2, 0.3, 0, 0, 0, 1, 0, 0, 0}));   // step 0: as set
        const Answer expected{-0.875, 0.45, 2.075, 0.5 + 0.25 / 3, -0.2 + 0.5 / 3, 0.3 - 0.25 / 3,
                              -0.275 / 0.4225, 0.175 / 0.52, 0.075 / 0.2225, 1, 0, 0, 0};
        const QString m = rbw::test::mismatch(QList<double>(a[1].begin(), a[1].end()),
                                              QList<double>(expected.begin(), expected.end()), 1e-14);
        QVERIFY2(m.isEmpty(), qPrintable(m));
        const std::vector<AnswerSlot> where = answerSlots(p);
        QCOMPARE(where[0].step, 0);
        QCOMPARE(where[3].step, 3);
    }

    // Without a mistake, the chained hand steps and the engine's world agree on every
    // probe; transposed-inertia (whose chaining gives the steps its own omega) agrees
    // with the engine in the course template's convention R^T I0^-1 R.
    void engineAgreesWithReplay_data()
    {
        QTest::addColumn<int>("probe");
        QTest::addColumn<bool>("transposed");
        for (int i = 0; i < static_cast<int>(motionProbes().size()); ++i) {
            const QByteArray name = QByteArray::fromStdString(motionProbes()[i].name);
            QTest::newRow(name + " right") << i << false;
            QTest::newRow(name + " transposed-inertia") << i << true;
        }
    }
    void engineAgreesWithReplay()
    {
        QFETCH(int, probe);
        QFETCH(bool, transposed);
        const Probe& p = motionProbes()[probe];
        const Answers mine = replay(p, {transposed ? Mistake::TransposedInertia : Mistake::None, 0});
        const Answers engine = replayWithEngine(
            p, transposed ? rbw::InertiaConvention::CourseTemplate : rbw::InertiaConvention::Standard);
        QCOMPARE(mine.size(), engine.size());
        // 1e-12 of each quantity's size: round-off of a few steps, nothing more
        const std::optional<Divergence> d = firstDivergence(p, engine, mine, 1e-8);
        QVERIFY2(!d, d ? qPrintable(describe(*d)) : "");
        // ...and the two conventions differ on this probe (the check can fail)
        if (!transposed) {
            QVERIFY(firstDivergence(p, engine, replayWithEngine(p, rbw::InertiaConvention::CourseTemplate)));
        }
    }

    void everyMistakeHasAScope()
    {
        for (const rbw::MistakeInfo& m : rbw::mistakeCatalogue()) {
            QVERIFY2(scopeOf(m.mistake).has_value(),
                     qPrintable(QStringLiteral("%1 has no probe scope: add it to mistakeScopes() "
                                               "(physics/workbook/probes/probe_models.cpp)").arg(m.id)));
        }
        for (const ScopedMistake& s : mistakeScopes()) QVERIFY(std::string(s.reason).size() > 3);
        // The motion candidates: every Motion model, each variant (inertia-axes-swapped: 3).
        int swapped = 0;
        for (const ReplayModel& m : motionModels()) {
            QCOMPARE(scopeOf(m.mistake), std::optional<ProbeScope>(ProbeScope::Motion));
            swapped += m.mistake == Mistake::InertiaAxesSwapped;
        }
        QCOMPARE(swapped, 3);
    }

    // The distinguishability table (issue 23 item 2): the right algorithm and every
    // motion model, each pair separated by some probe through x, v and omega alone
    // (the TUM adapter prints no r), by more than ten times the tolerance.
    void distinguishability()
    {
        std::vector<ReplayModel> models{ReplayModel{}};
        for (const ReplayModel& m : motionModels()) models.push_back(m);
        const std::vector<Probe>& probes = motionProbes();
        QStringList failures;
        for (std::size_t i = 0; i < models.size(); ++i) {
            for (std::size_t j = i + 1; j < models.size(); ++j) {
                const int p = separatingProbe(probes, models[i], models[j]);
                if (p < 0) {
                    failures << QStringLiteral("%1 and %2 give the same answers on every motion probe: add a probe "
                                               "that separates them")
                                    .arg(QString::fromStdString(modelLabel(models[i])),
                                         QString::fromStdString(modelLabel(models[j])));
                }
            }
        }
        QVERIFY2(failures.isEmpty(), qPrintable(failures.join('\n')));
        // Where each model first shows against the right algorithm (printed for the record).
        for (std::size_t i = 1; i < models.size(); ++i) {
            const int p = separatingProbe(probes, models[0], models[i]);
            const std::optional<Divergence> d =
                firstDivergence(probes[p], replay(probes[p], {}), replay(probes[p], models[i]));
            qInfo("%-36s first shows in %s, %s", modelLabel(models[i]).c_str(), probes[p].name.c_str(),
                  qPrintable(describe(*d)));
        }
    }

    // Negative control of the table: a model is never separated from itself, and the
    // step-0 answer of motion-02 alone (a body not yet stepped) separates nothing.
    void separationCanFail()
    {
        const ReplayModel t{Mistake::TransposedInertia, 0};
        QCOMPARE(separatingProbe(motionProbes(), t, t), -1);
        Probe stillBox = motionProbes()[1];
        stillBox.commands.resize(3);   // add_body, set_velocity, state
        QCOMPARE(separatingProbe({stillBox}, ReplayModel{}, t), -1);
        QVERIFY(separatingProbe(motionProbes(), ReplayModel{}, t) >= 0);
    }

    // diagnoseAnswers on replayed answers: the right algorithm matches; each model is
    // explained by its own id; a mix of two models' answers is only partly explained.
    void verdictsOfReplayedAnswers()
    {
        const std::vector<Probe>& probes = motionProbes();
        auto answersOf = [&](const ReplayModel& m) {
            std::vector<Answers> all;
            for (const Probe& p : probes) all.push_back(replay(p, m));
            return all;
        };
        SimulatorDiagnosis d = diagnoseAnswers(probes, answersOf({}), motionModels());
        QCOMPARE(QString(verdictName(d.verdict)), QStringLiteral("matches"));
        QVERIFY(!d.firstDivergence);
        for (const ReplayModel& m : motionModels()) {
            d = diagnoseAnswers(probes, answersOf(m), motionModels());
            QCOMPARE(QString(verdictName(d.verdict)), QStringLiteral("explained"));
            QCOMPARE(d.mistakes, std::vector<std::string>{modelId(m)});
            QVERIFY(d.possibleMistakes.empty());
            QVERIFY(d.firstDivergence);
        }
        std::vector<Answers> mixed = answersOf({Mistake::TorqueReversed, 0});
        mixed.back() = replay(probes.back(), {Mistake::HalfExtentsForSize, 0});
        d = diagnoseAnswers(probes, mixed, motionModels());
        QCOMPARE(QString(verdictName(d.verdict)), QStringLiteral("partly-explained"));
        QCOMPARE(d.mistakes, std::vector<std::string>{"torque-reversed"});
        // answers no model gives: the right ones with x of the first answer moved
        std::vector<Answers> odd = answersOf({});
        odd[0][0][0] += 0.5;
        d = diagnoseAnswers(probes, odd, motionModels());
        QCOMPARE(QString(verdictName(d.verdict)), QStringLiteral("unexplained"));
        QCOMPARE(d.divergenceProbe, 0);
        QCOMPARE(QString::fromStdString(d.firstDivergence->quantity), QStringLiteral("x"));
        QCOMPARE(d.firstDivergence->step, 1);
    }
};

QTEST_APPLESS_MAIN(TestProbes)
#include "tst_probes.moc"
