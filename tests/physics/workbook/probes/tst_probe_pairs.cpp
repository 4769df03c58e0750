// Pairs of mistake models over the probes (issue 23 item 2: "every model and every pair
// of models replayed over the probes"; physics/workbook/probes/probe_models.h,
// modelPairs()). The distinguishability table of pairs: every pair is told apart from
// the right algorithm by some probe; a pair that gives the same answers as a single model
// or as another pair is allowed only as a measured equal explanation, listed in
// docs/simulator-protocol.md's section "Pairs that give the same answers", which this
// test writes (RBW_UPDATE_PROBES_DOC=1) and compares word for word. The pruned pairs
// (two models of one slot) replay exactly as the model that wins the slot. And
// diagnoseAnswers on a pair's own answers: `explained`, both ids, or the measured equals.
//
// Two models are "the same" as in tst_probes: no probe separates them through x, v and
// omega alone (the TUM adapter prints no r) by more than ten times the tolerance. In the
// collision probes each side fits its own c (modelAnswers); a model's answers are made
// with c = 0.3 and with c = 0.8, and it is the same as another when the other
// reproduces either.
#include "tests/test_support.h"

#include "physics/workbook/probes/collision_replay.h"
#include "physics/workbook/probes/probe_models.h"
#include "physics/workbook/probes/probe_verdict.h"
#include "physics/workbook/probes/probes.h"
#include "physics/workbook/probes/replay.h"

#include <QFile>
#include <QSaveFile>
#include <QtTest>

#include <algorithm>
#include <functional>
#include <map>
#include <numeric>

using namespace rbw::probes;
using rbw::Mistake;

namespace {

Answers withoutOrientation(Answers a)
{
    for (Answer& x : a) x.resize(9);
    return a;
}

std::vector<Answers> answersOf(const std::vector<Probe>& probes, const ReplayModel& m, double c)
{
    std::vector<Answers> all;
    for (const Probe& p : probes) {
        all.push_back(withoutOrientation(p.collides ? replayWithContacts(p, m, c) : replay(p, m)));
    }
    return all;
}

// No probe separates a's answers `given` from b's (b with the c fitted to them) by more
// than `margin` times the tolerance.
bool reproduces(const std::vector<Probe>& probes, const std::vector<Answers>& given, const ReplayModel& b,
                double margin = 10.0)
{
    const std::vector<Answers> other = modelAnswers(probes, given, b);
    for (std::size_t p = 0; p < probes.size(); ++p) {
        const Answers mine = withoutOrientation(other[p]);
        if (firstDivergence(probes[p], mine, given[p], margin) && firstDivergence(probes[p], given[p], mine, margin)) {
            return false;
        }
    }
    return true;
}

// The motion part of a model: its motion members (the collision probes' step).
ReplayModel motionPart(const ReplayModel& m)
{
    ReplayModel out{Mistake::None, m.variant};
    for (Mistake x : {m.mistake, m.second}) {
        if (scopeOf(x) != ProbeScope::Motion) continue;
        (out.mistake == Mistake::None ? out.mistake : out.second) = x;
    }
    if (!out.has(Mistake::InertiaAxesSwapped)) out.variant = 0;
    return out;
}

const char* kSectionHeading = "## Pairs that give the same answers";
const char* kNextHeading = "\n## ";

QString quoted(const ReplayModel& m) { return "`" + QString::fromStdString(modelLabel(m)) + "`"; }

} // namespace

class TestProbePairs : public QObject {
    Q_OBJECT
private slots:
    // The candidates: every pair of two models once, none of one model with itself, the
    // pruned ones only where two models share a slot.
    void pairsOfTheCatalogue()
    {
        std::vector<ReplayModel> singles = motionModels();
        for (const ReplayModel& m : collisionModels()) singles.push_back(m);
        const std::vector<ReplayModel> pairs = modelPairs(singles);
        int pruned = 0;
        for (std::size_t i = 0; i < singles.size(); ++i) {
            for (std::size_t k = i + 1; k < singles.size(); ++k) {
                if (singles[i].mistake == singles[k].mistake) continue;
                pruned += sameSlotWinner(singles[i].mistake, singles[k].mistake) != Mistake::None;
            }
        }
        // 23 motion models with variants (inertia-axes-swapped: 3) and 8 collision ones: 31;
        // C(31, 2) = 465 less the 3 pairs of two axes-swapped variants, less the same-slot ones
        QCOMPARE(singles.size(), std::size_t(31));
        QCOMPARE(pruned, 5);   // 1 (omega's matrix) + 3 (the world I^-1) + 1 (the numerator)
        QCOMPARE(pairs.size(), std::size_t(465 - 3 - pruned));
        for (const ReplayModel& p : pairs) {
            QVERIFY(p.isPair());
            QCOMPARE(modelIds(p).size(), std::size_t(2));
            QVERIFY(QString::fromStdString(modelId(p)).contains(" + "));
        }
        const ReplayModel t{Mistake::TransposedInertia, 0, Mistake::LeverArmFromOrigin};
        QCOMPARE(modelLabel(t), std::string("transposed-inertia + lever-arm-from-origin"));
        QCOMPARE(modelIds(t), (std::vector<std::string>{"transposed-inertia", "lever-arm-from-origin"}));
        QCOMPARE(modelLabel({Mistake::InertiaAxesSwapped, 1, Mistake::TorqueReversed}),
                 std::string("inertia-axes-swapped (y-z) + torque-reversed"));
        QVERIFY(std::find(pairs.begin(), pairs.end(), t) != pairs.end());
    }

    // A pruned pair replays exactly as the model that wins its slot, on every probe (so
    // leaving it out loses nothing); negative control: a pair that combines does not.
    void prunedPairsEqualTheirWinner()
    {
        const std::vector<Probe> probes = probesOf(ProbeGroup::All);
        const std::vector<Mistake> slotted = {Mistake::BodyInverseInertia, Mistake::InertiaNotInverted,
                                              Mistake::InertiaNotUpdated, Mistake::InertiaAccumulatedRotation,
                                              Mistake::InertiaFromOldOrientation, Mistake::ImpulseWithoutOnePlus,
                                              Mistake::RestitutionOneMinus};
        int checked = 0;
        for (Mistake a : slotted) {
            for (Mistake b : slotted) {
                const Mistake winner = sameSlotWinner(a, b);
                if (winner == Mistake::None) continue;
                const ReplayModel pair{a, 0, b};
                for (std::size_t p = 0; p < probes.size(); ++p) {
                    const Answers mine = answersOf({probes[p]}, pair, 0.3)[0];
                    const Answers its = answersOf({probes[p]}, {winner, 0}, 0.3)[0];
                    QVERIFY2(!firstDivergence(probes[p], its, mine, 1e-8),
                             qPrintable(QString::fromStdString(modelLabel(pair) + " on " + probes[p].name)));
                }
                ++checked;
            }
        }
        QCOMPARE(checked, 10);   // each of the 5 pruned pairs both ways round
        const ReplayModel combines{Mistake::TransposedInertia, 0, Mistake::LeverArmFromOrigin};
        QVERIFY(!reproduces(probes, answersOf(probes, combines, 0.3), {Mistake::TransposedInertia, 0}));
        QVERIFY(!reproduces(probes, answersOf(probes, combines, 0.3), {Mistake::LeverArmFromOrigin, 0}));
    }

    // The table: the right algorithm, every single model and every pair over all probes
    // (the default of rbw diagnose). Two models whose motion parts differ on the motion
    // probes are separated there; only within a class of equal motion answers do the
    // collision probes (with fitted c) have to tell them apart.
    void distinguishability()
    {
        const std::vector<Probe> all = probesOf(ProbeGroup::All);
        const std::vector<Probe>& motion = motionProbes();
        std::vector<ReplayModel> singles = motionModels();
        for (const ReplayModel& m : collisionModels()) singles.push_back(m);
        std::vector<ReplayModel> models{ReplayModel{}};
        for (const ReplayModel& m : singles) models.push_back(m);
        for (const ReplayModel& m : modelPairs(singles)) models.push_back(m);

        // classes of equal motion answers (motion parts compared on the motion probes)
        std::vector<ReplayModel> parts;
        std::vector<std::vector<Answers>> partAnswers;
        std::vector<int> classOf(models.size());
        for (std::size_t i = 0; i < models.size(); ++i) {
            const ReplayModel part = motionPart(models[i]);
            const std::vector<Answers> a = answersOf(motion, part, 0.0);
            int found = -1;
            for (std::size_t k = 0; k < parts.size() && found < 0; ++k) {
                if (parts[k] == part || reproduces(motion, a, parts[k])) found = static_cast<int>(k);
            }
            if (found < 0) {
                found = static_cast<int>(parts.size());
                parts.push_back(part);
                partAnswers.push_back(a);
            }
            classOf[i] = found;
        }
        // within a class: the same when either of a's answers (c = 0.3, 0.8) is reproduced by b
        std::vector<std::vector<std::vector<Answers>>> given(models.size());
        for (std::size_t i = 0; i < models.size(); ++i) {
            for (double c : {0.3, 0.8}) given[i].push_back(answersOf(all, models[i], c));
        }
        std::vector<int> group(models.size());
        std::iota(group.begin(), group.end(), 0);
        std::function<int(int)> root = [&](int i) { return group[i] == i ? i : group[i] = root(group[i]); };
        QStringList failures;
        for (std::size_t i = 0; i < models.size(); ++i) {
            for (std::size_t j = i + 1; j < models.size(); ++j) {
                if (classOf[i] != classOf[j]) continue;
                const bool same = reproduces(all, given[i][0], models[j]) || reproduces(all, given[i][1], models[j]) ||
                                  reproduces(all, given[j][0], models[i]) || reproduces(all, given[j][1], models[i]);
                if (!same) continue;
                if (i == 0) {
                    failures << QString::fromStdString(modelLabel(models[j])) +
                                    " gives the right algorithm's answers on every probe: add a probe that shows it";
                }
                group[root(static_cast<int>(j))] = root(static_cast<int>(i));
            }
        }
        QVERIFY2(failures.isEmpty(), qPrintable(failures.join('\n')));

        // the groups of two or more, each in the order of `models` (singles first)
        std::map<int, std::vector<std::size_t>> groups;
        for (std::size_t i = 0; i < models.size(); ++i) groups[root(static_cast<int>(i))].push_back(i);
        QStringList lines;
        int withPairs = 0;
        for (const auto& [r, members] : groups) {
            if (members.size() < 2) continue;
            // a member the group's first one reproduces only within ten times the tolerance,
            // not within it: the answers' round-off decides which of the two is named
            QStringList names;
            for (std::size_t i : members) {
                const std::size_t f = members.front();
                const bool exact = i == f || reproduces(all, given[i][0], models[f], 1.0) ||
                                   reproduces(all, given[i][1], models[f], 1.0);
                if (!exact) near_.push_back(i);
                names << quoted(models[i]) + (exact ? "" : " (nearly)");
            }
            QStringList singleNames;
            for (std::size_t i : members) {
                if (!models[i].isPair()) singleNames << quoted(models[i]);
            }
            lines << "- " + names.join(" = ") +
                         (singleNames.size() == 1 ? ": named as " + singleNames.front() + " alone (Occam)"
                          : singleNames.isEmpty() ? QStringLiteral(": the pairs are `possible_mistakes`")
                                                  : ": " + singleNames.join(" and ") + " are `possible_mistakes`");
            withPairs += 1;
        }
        // Over the motion probes alone (rbw diagnose --probes motion) and without r: the
        // models the motion probes cannot tell from the right algorithm (the collision
        // probes do, above). omega-before-orientation with inertia-from-old-orientation
        // turns r with I^-1(r_n) L_{n+1} and takes omega' = I^-1(r_n) L_{n+1}: with L_0 = 0
        // (the protocol sets no omega) its r_n is the right r_{n+1}, and x, v, omega are
        // the right ones at every step.
        QStringList motionOnly;
        for (std::size_t i = 1; i < models.size(); ++i) {
            if (classOf[i] == classOf[0] && !(motionPart(models[i]) == ReplayModel{})) motionOnly << "- " + quoted(models[i]);
        }
        measured_ = lines.join('\n') + "\n\n" + motionOnlyIntro() + "\n" +
                    (motionOnly.isEmpty() ? QStringLiteral("- none") : motionOnly.join('\n')) + '\n';
        measuredCount_ = withPairs;
        equals_ = groups;
        models_ = models;
        qInfo("%zu models (%zu pairs), %d groups of equal answers", models.size(), models.size() - 1 - singles.size(),
              withPairs);
        // negative control of the table: the one pair of singles no scene separates is found
        QVERIFY(measured_.contains("`impulse-without-one-plus` = `restitution-one-minus`"));
    }

    // docs/simulator-protocol.md's section is the list measured above, word for word.
    void docAgrees()
    {
        if (measured_.isEmpty()) QSKIP("run with distinguishability");
        const QString expected = QString(kSectionHeading) + "\n" + intro() + "\n" + measured_;
        QFile f(QStringLiteral(RBW_SOURCE_DIR "/docs/simulator-protocol.md"));
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QString doc = QString::fromUtf8(f.readAll());
        const qsizetype at = doc.indexOf(kSectionHeading);
        QVERIFY2(at >= 0, "docs/simulator-protocol.md has no section on equal pairs");
        qsizetype end = doc.indexOf(kNextHeading, at + 1);
        if (end < 0) end = doc.size();
        const QString section = doc.mid(at, end - at).trimmed();
        if (section != expected.trimmed()) {
            qWarning().noquote() << "docs/simulator-protocol.md's section should read:\n" << expected;
            if (qEnvironmentVariableIsSet("RBW_UPDATE_PROBES_DOC")) {
                QSaveFile out(f.fileName());
                QVERIFY(out.open(QIODevice::WriteOnly));
                out.write((doc.left(at) + expected.trimmed() + "\n" + doc.mid(end)).toUtf8());
                QVERIFY(out.commit());
            }
        }
        QCOMPARE(section, expected.trimmed());
    }

    // diagnoseAnswers on a pair's own answers (c = 0.3, without r): explained; named by both ids,
    // or, for a pair of a measured group, by the group's explanations (its single if it
    // has one, else its pairs as possible_mistakes), over all probes (rbw diagnose's
    // default): every pair of two motion models, every pair of a collision model with one
    // of five motion models, and every pair of two collision models.
    void pairsAreExplained()
    {
        if (models_.empty()) QSKIP("run with distinguishability");
        std::vector<ReplayModel> collisionSingles = collisionModels();
        const std::vector<Mistake> sample = {Mistake::TransposedInertia, Mistake::LeverArmFromOrigin,
                                             Mistake::OmegaAccumulated, Mistake::ForcesNotCleared,
                                             Mistake::QuaternionRightMultiplied};
        std::vector<ReplayModel> allCandidates = motionModels();
        for (const ReplayModel& m : collisionSingles) allCandidates.push_back(m);
        int tried = 0;
        QStringList failures;
        for (std::size_t i = 0; i < models_.size(); ++i) {
            const ReplayModel& m = models_[i];
            if (!m.isPair()) continue;
            const bool motionA = scopeOf(m.mistake) == ProbeScope::Motion;
            const bool motionB = scopeOf(m.second) == ProbeScope::Motion;
            const auto inSample = [&](Mistake x) { return std::find(sample.begin(), sample.end(), x) != sample.end(); };
            const bool tryIt = (motionA && motionB) || (!motionA && !motionB) ||
                               (motionA ? inSample(m.mistake) : inSample(m.second));
            if (!tryIt) continue;
            const std::vector<Probe> probes = probesOf(ProbeGroup::All);
            const std::vector<ReplayModel>& candidates = allCandidates;
            // 9 numbers an answer, as the TUM adapter prints: what the table compares
            const std::vector<Answers> given = answersOf(probes, m, 0.3);
            const SimulatorDiagnosis d = diagnoseAnswers(probes, given, candidates);
            ++tried;
            // what the measured group says it is named as
            std::vector<std::string> expected = modelIds(m);
            std::vector<std::string> explanations;
            for (const auto& [r, members] : equals_) {
                if (std::find(members.begin(), members.end(), i) == members.end()) continue;
                if (!models_[members.front()].isPair()) {
                    expected = modelIds(models_[members.front()]);
                } else {
                    for (std::size_t k : members) {
                        const std::string id = modelId(models_[k]);
                        if (std::find(explanations.begin(), explanations.end(), id) == explanations.end()) {
                            explanations.push_back(id);
                        }
                    }
                }
            }
            const bool near = std::find(near_.begin(), near_.end(), i) != near_.end();
            const bool asGroup = explanations.size() > 1
                                     ? d.possibleExplanations == explanations && d.mistakes.empty()
                                     : d.mistakes == expected && d.possibleMistakes.empty();
            const bool asItself = d.mistakes == modelIds(m) && d.possibleMistakes.empty();
            const bool ok = d.verdict == Verdict::Explained && (asGroup || (near && asItself));
            if (!ok) {
                QString got = QString(verdictName(d.verdict)) + " mistakes";
                for (const std::string& s : d.mistakes) got += " " + QString::fromStdString(s);
                got += "; possible";
                for (const std::string& s : d.possibleExplanations) got += " [" + QString::fromStdString(s) + "]";
                failures << QString::fromStdString(modelLabel(m)) + ": " + got;
            }
        }
        QVERIFY2(failures.isEmpty(), qPrintable(failures.join('\n')));
        QVERIFY(tried > 250);
    }

private:
    static QString motionOnlyIntro()
    {
        return QStringLiteral(
            "### With the motion probes alone\n"
            "\n"
            "With `--probes motion` and a program that does not print r (the TUM adapter), the motion\n"
            "probes cannot tell these from the right algorithm, measured by the same test: such a\n"
            "program `matches` there. The collision probes (in the default `--probes all`) tell\n"
            "each apart, and so does r where the program prints it.\n");
    }

    static QString intro()
    {
        return QStringLiteral(
            "\n"
            "Measured, not claimed: `tests/physics/workbook/probes/tst_probe_pairs.cpp` replays the\n"
            "right algorithm, every mistake model and every pair of two of them over all the probes\n"
            "and writes this list (`RBW_UPDATE_PROBES_DOC=1`); it fails when the list differs, or\n"
            "when a model or pair gives the right algorithm's answers. Each line is a group that\n"
            "no probe tells apart through x, v and ω (each with its own fitted c; a simulator that\n"
            "prints r may be told apart by it). \"(nearly)\": its answers differ from the group's\n"
            "first by more than the tolerance but less than ten times it, so the exact answers\n"
            "name it, a program's round-off may name the group. A group that\n"
            "holds a single model is named as that model alone: `rbw diagnose` tries pairs only\n"
            "when no single model explains every probe. A group of pairs is named as\n"
            "`possible_mistakes`, each pair in `possible_explanations`. Not tried at all (they\n"
            "replay exactly as one of them, `sameSlotWinner()` in\n"
            "`physics/workbook/probes/probe_models.cpp`, measured by the same test): two models of\n"
            "one slot, `body-inverse-inertia` with `inertia-not-inverted`; two of\n"
            "`inertia-not-updated`, `inertia-accumulated-rotation` and\n"
            "`inertia-from-old-orientation`; `impulse-without-one-plus` with\n"
            "`restitution-one-minus`.\n");
    }

    QString measured_;
    int measuredCount_ = 0;
    std::map<int, std::vector<std::size_t>> equals_;
    std::vector<ReplayModel> models_;
    std::vector<std::size_t> near_;
};

QTEST_APPLESS_MAIN(TestProbePairs)
#include "tst_probe_pairs.moc"
