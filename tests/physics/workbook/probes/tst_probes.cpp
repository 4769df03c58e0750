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

#include "physics/workbook/probes/collision_replay.h"
#include "physics/workbook/probes/probe_models.h"
#include "physics/workbook/probes/probe_verdict.h"
#include "physics/workbook/probes/probes.h"
#include "physics/workbook/probes/replay.h"

#include <QtTest>

#include <algorithm>
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
        const std::vector<std::string> issues = probesAreWellFormed(probesOf(ProbeGroup::All));
        QVERIFY2(issues.empty(), issues.empty() ? "" : issues.front().c_str());
        QVERIFY(motionProbes().size() >= 4);
        QVERIFY(collisionProbes().size() >= 2);
        QCOMPARE(probesOf(ProbeGroup::All).size(), motionProbes().size() + collisionProbes().size());
        for (const Probe& p : collisionProbes()) QVERIFY(p.collides && findProbe(p.name) != nullptr);
        for (const Probe& p : motionProbes()) QVERIFY(!p.collides && findProbe(p.name) != nullptr);
        // Every number is a plain decimal: no exponent, nan or inf; masses whole numbers.
        for (const Probe& p : probesOf(ProbeGroup::All)) {
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

    // answerDifferences (what the app's "Yours" column marks) reads the answers by
    // firstDivergence's rule: its first entry that differs is firstDivergence's answer and
    // quantity, and with the right algorithm's own answers nothing differs (the negative
    // control). probeScene is the scene replayWithEngine runs: one body per add_body and
    // the probe's number of steps (motion-02: one body, 3 steps, replayMatchesHandDerivation).
    void answerDifferencesAgreeWithFirstDivergence_data()
    {
        QTest::addColumn<int>("mistake");
        for (Mistake m : {Mistake::None, Mistake::TransposedInertia, Mistake::LeverArmFromOrigin})
            QTest::newRow(m == Mistake::None ? "right" : modelId({m, 0}).c_str()) << static_cast<int>(m);
    }
    void answerDifferencesAgreeWithFirstDivergence()
    {
        QFETCH(int, mistake);
        int differing = 0;
        for (const Probe& p : motionProbes()) {
            const Answers right = replay(p, {});
            const Answers given = replay(p, {static_cast<Mistake>(mistake), 0});
            const std::optional<Divergence> d = firstDivergence(p, right, given);
            const std::vector<QuantityDifference> all = answerDifferences(p, right, given);
            QCOMPARE(all.size(), 4 * right.size());   // x, v, omega, r of every answer
            const auto first = std::find_if(all.begin(), all.end(), [](const QuantityDifference& q) { return q.differs; });
            QCOMPARE(first != all.end(), d.has_value());
            if (d) {
                QCOMPARE(first->answer, d->answer);
                QCOMPARE(first->step, d->step);
                QCOMPARE(first->body, d->body);
                QCOMPARE(first->quantity, d->quantity);
                QCOMPARE(first->tolerance, d->tolerance);
            }
            for (const QuantityDifference& q : all) {
                QCOMPARE(q.differs, q.largest > q.tolerance);
                differing += q.differs ? 1 : 0;
            }
        }
        QCOMPARE(differing > 0, static_cast<Mistake>(mistake) != Mistake::None);
        const rbw::SceneDef scene = probeScene(motionProbes()[1]);
        QCOMPARE(scene.bodies.size(), std::size_t(1));
        QCOMPARE(scene.steps, 3L);
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

    // The collision replay. Without contacts it is the motion replay (a motion probe's
    // bodies never touch); in every collision probe c changes some answer (an impulse
    // happens); and through the right impulse the total momentum P = sum M v and the
    // total angular momentum about the origin sum (x x M v + L) stay what the first
    // step's pushes made them: an impulse J n at p adds x_A x J n + (p - x_A) x J n =
    // p x J n to A and takes p x J n from B; a free explicit Euler step moves x along the
    // v it keeps and keeps L. L = R I0 R^T omega from the answer's r and omega, I0 = M/12
    // diag(b^2 + c^2, a^2 + c^2, a^2 + b^2). Negative control: with the lever arms from
    // the origin (x_a = x_b = p) the impulse adds (x_A - x_B) x J n.
    void collisionReplayConservesMomentum()
    {
        for (const Probe& p : motionProbes()) QVERIFY(replayWithContacts(p, {}, 0.5) == replay(p, {}));
        double wrongDrift = 0.0;
        for (const Probe& p : collisionProbes()) {
            // c changes an answer: an impulse happens (collision-03 separates: only
            // relative-velocity-reversed pushes there)
            const ReplayModel pusher = p.name == "collision-03" ? ReplayModel{Mistake::RelativeVelocityReversed, 0}
                                                                : ReplayModel{};
            QVERIFY2(replayWithContacts(p, pusher, 0.0) != replayWithContacts(p, pusher, 1.0), p.name.c_str());
            const std::vector<AnswerSlot> where = answerSlots(p);
            std::vector<double> masses;
            std::vector<Vec3> sizes;
            for (const rbw::probes::Command& c : p.commands) {
                if (c.kind != CommandKind::AddBody) continue;
                masses.push_back(c.mass);
                sizes.push_back(c.b);
            }
            QCOMPARE(masses.size(), std::size_t(2));
            // P and the total angular momentum of the two answers k, k + 1 (bodies 0, 1 of one step)
            auto momenta = [&](const Answers& a, std::size_t k) {
                Vec3 P = Vec3::Zero(), Ltotal = Vec3::Zero();
                for (std::size_t b = 0; b < 2; ++b) {
                    const Answer& s = a[k + b];
                    const Vec3 x(s[0], s[1], s[2]), v(s[3], s[4], s[5]), omega(s[6], s[7], s[8]);
                    const rbw::Mat3 R = rbw::Quat(s[9], s[10], s[11], s[12]).toRotationMatrix();
                    const Vec3 e = sizes[b].cwiseProduct(sizes[b]);
                    const rbw::Mat3 I0 = (masses[b] / 12.0 * Vec3(e.y() + e.z(), e.x() + e.z(), e.x() + e.y())).asDiagonal();
                    const rbw::Mat3 I_W = R * I0 * R.transpose();
                    P += masses[b] * v;
                    Ltotal += x.cross(masses[b] * v) + I_W * omega;
                }
                return std::pair<Vec3, Vec3>(P, Ltotal);
            };
            std::size_t first = 0;   // the answers after step 1
            while (where[first].step != 1) ++first;
            for (const ReplayModel& m : {ReplayModel{}, ReplayModel{Mistake::ImpulseLeverArmFromOrigin, 0}}) {
                const Answers a = replayWithContacts(p, m, 0.6);
                const auto [P1, L1] = momenta(a, first);
                const auto [Pn, Ln] = momenta(a, a.size() - 2);
                QVERIFY2((Pn - P1).norm() < 1e-12 * P1.norm(), p.name.c_str());
                const double drift = (Ln - L1).norm() / L1.norm();
                if (m.mistake == Mistake::None) QVERIFY2(drift < 1e-12, qPrintable(QString::number(drift)));
                else wrongDrift = std::max(wrongDrift, drift);
            }
        }
        QVERIFY2(wrongDrift > 1e-6, qPrintable(QString::number(wrongDrift)));
    }

    // The fit recovers c exactly for the right algorithm and every collision model;
    // the motion probes say nothing about c.
    void restitutionIsFitted_data()
    {
        QTest::addColumn<int>("mistake");
        QTest::addColumn<double>("c");
        std::vector<ReplayModel> models{ReplayModel{}};
        for (const ReplayModel& m : collisionModels()) models.push_back(m);
        for (const ReplayModel& m : models) {
            for (double c : {0.15, 0.6, 0.95}) {
                QTest::newRow(qPrintable(QStringLiteral("%1 c=%2").arg(QString::fromStdString(modelLabel(m))).arg(c)))
                    << static_cast<int>(m.mistake) << c;
            }
        }
    }
    void restitutionIsFitted()
    {
        QFETCH(int, mistake);
        QFETCH(double, c);
        const ReplayModel m{static_cast<Mistake>(mistake), 0};
        std::vector<Answers> given;
        for (const Probe& p : collisionProbes()) given.push_back(replayWithContacts(p, m, c));
        const RestitutionFit fit = fitRestitution(collisionProbes(), given, m);
        QVERIFY(fit.determined);
        QVERIFY2(std::abs(fit.c - c) < 1e-9, qPrintable(QString::number(fit.c, 'g', 17)));
        std::vector<Answers> motion;
        for (const Probe& p : motionProbes()) motion.push_back(replay(p, m));
        QVERIFY(!fitRestitution(motionProbes(), motion, m).determined);
    }

    // The distinguishability table of the collision group: the answers of the right
    // algorithm and of every collision model, with c = 0.3 or 0.8, are reproduced by no
    // other model of the catalogue at any c it can fit, by more than ten times the
    // tolerance, through x, v and omega alone. The one pair no scene can separate
    // (impulse-without-one-plus with c, restitution-one-minus with 1 - c: both
    // numerators are -c v_rel.n) must come out inseparable.
    void collisionDistinguishability()
    {
        std::vector<ReplayModel> own{ReplayModel{}};
        for (const ReplayModel& m : collisionModels()) own.push_back(m);
        std::vector<ReplayModel> all = own;
        for (const ReplayModel& m : motionModels()) all.push_back(m);
        const std::vector<Probe>& probes = collisionProbes();
        auto same = [&](const ReplayModel& a, const ReplayModel& b, double c) {
            std::vector<Answers> given;
            for (const Probe& p : probes) given.push_back(withoutOrientation(replayWithContacts(p, a, c)));
            const std::vector<Answers> other = modelAnswers(probes, given, b);
            for (std::size_t p = 0; p < probes.size(); ++p) {
                if (firstDivergence(probes[p], withoutOrientation(other[p]), given[p], 10.0)) return false;
            }
            return true;
        };
        const ReplayModel onePlus{Mistake::ImpulseWithoutOnePlus, 0}, oneMinus{Mistake::RestitutionOneMinus, 0};
        QStringList failures;
        for (const ReplayModel& a : own) {
            for (const ReplayModel& b : all) {
                if (a == b) continue;
                const bool pair = (a == onePlus && b == oneMinus) || (a == oneMinus && b == onePlus);
                for (double c : {0.3, 0.8}) {
                    if (same(a, b, c) != pair) {
                        failures << QStringLiteral("%1 (c = %2) %3 %4 on the collision probes")
                                        .arg(QString::fromStdString(modelLabel(a)))
                                        .arg(c)
                                        .arg(pair ? "is separated from" : "is reproduced by")
                                        .arg(QString::fromStdString(modelLabel(b)));
                    }
                }
            }
        }
        QVERIFY2(failures.isEmpty(), qPrintable(failures.join('\n')));
        // negative control: a model reproduces itself at its own c
        QVERIFY(same(own[1], own[1], 0.3));
    }

    // diagnoseAnswers over motion and collision probes: the right algorithm matches and
    // reports its c; each collision model is explained by its id (the inseparable pair
    // as possible mistakes), with its own c.
    void collisionVerdicts()
    {
        const std::vector<Probe> probes = probesOf(ProbeGroup::All);
        std::vector<ReplayModel> candidates = motionModels();
        for (const ReplayModel& m : collisionModels()) candidates.push_back(m);
        auto answersOf = [&](const ReplayModel& m, double c) {
            std::vector<Answers> all;
            for (const Probe& p : probes) all.push_back(p.collides ? replayWithContacts(p, m, c) : replay(p, m));
            return all;
        };
        SimulatorDiagnosis d = diagnoseAnswers(probes, answersOf({}, 0.4), candidates);
        QCOMPARE(QString(verdictName(d.verdict)), QStringLiteral("matches"));
        QCOMPARE(d.restitution.size(), std::size_t(1));
        QVERIFY(std::abs(d.restitution[0].c - 0.4) < 1e-9);
        for (const ReplayModel& m : collisionModels()) {
            d = diagnoseAnswers(probes, answersOf(m, 0.7), candidates);
            QCOMPARE(QString(verdictName(d.verdict)), QStringLiteral("explained"));
            const bool pair = m.mistake == Mistake::ImpulseWithoutOnePlus || m.mistake == Mistake::RestitutionOneMinus;
            if (pair) {
                QCOMPARE(d.possibleMistakes,
                         (std::vector<std::string>{"impulse-without-one-plus", "restitution-one-minus"}));
            } else {
                QCOMPARE(d.mistakes, std::vector<std::string>{modelId(m)});
            }
            QVERIFY(d.firstDivergence);
            QCOMPARE(probes[d.divergenceProbe].collides, true);   // every motion probe matches
            bool found = false;
            for (const RestitutionOf& r : d.restitution) {
                if (r.model == modelLabel(m)) found = std::abs(r.c - 0.7) < 1e-9;
            }
            QVERIFY(found);
        }
    }
};

QTEST_APPLESS_MAIN(TestProbes)
#include "tst_probes.moc"
