#include "physics/workbook/probes/probe_verdict.h"

#include "physics/workbook/probes/collision_replay.h"
#include "physics/workbook/probes/probe_models.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

namespace rbw::probes {

namespace {

struct Block {
    const char* name;
    int first;
    int size;
};
constexpr Block kBlocks[] = {{"x", 0, 3}, {"v", 3, 3}, {"omega", 6, 3}, {"r", 9, 4}};

// s of each block: the largest |value| in the expected answers (1 when all are zero).
std::vector<double> scales(const Answers& expected)
{
    std::vector<double> s;
    for (const Block& b : kBlocks) {
        double m = 0.0;
        for (const Answer& a : expected) {
            for (int i = b.first; i < b.first + b.size && i < static_cast<int>(a.size()); ++i) {
                m = std::max(m, std::abs(a[i]));
            }
        }
        s.push_back(m > 0.0 ? m : 1.0);
    }
    return s;
}

std::vector<double> slice(const Answer& a, const Block& b)
{
    return std::vector<double>(a.begin() + b.first, a.begin() + b.first + b.size);
}

} // namespace

std::vector<QuantityDifference> answerDifferences(const Probe& probe, const Answers& expected, const Answers& given,
                                                  double margin)
{
    std::vector<QuantityDifference> out;
    const std::vector<double> s = scales(expected);
    const std::vector<AnswerSlot> slots = answerSlots(probe);
    const std::size_t n = std::min({expected.size(), given.size(), slots.size()});
    for (std::size_t k = 0; k < n; ++k) {
        const Answer& e = expected[k];
        const Answer& g = given[k];
        for (int bi = 0; bi < 4; ++bi) {
            const Block& b = kBlocks[bi];
            if (static_cast<int>(e.size()) < b.first + b.size || static_cast<int>(g.size()) < b.first + b.size) continue;
            QuantityDifference q;
            q.answer = static_cast<int>(k);
            q.step = slots[k].step;
            q.body = slots[k].body;
            q.quantity = b.name;
            q.tolerance = margin * kRelativeTolerance * s[bi];
            q.expected = slice(e, b);
            q.given = slice(g, b);
            // r and -r are the same orientation: compare with the sign that fits better
            if (bi == 3) {
                double plus = 0.0, minus = 0.0;
                for (int i = 0; i < b.size; ++i) {
                    plus = std::max(plus, std::abs(q.given[i] - q.expected[i]));
                    minus = std::max(minus, std::abs(q.given[i] + q.expected[i]));
                }
                if (minus < plus) {
                    for (double& v : q.expected) v = -v;
                }
            }
            for (int i = 0; i < b.size; ++i) {
                const double d = std::abs(q.given[i] - q.expected[i]);
                if (!(d <= q.tolerance)) q.differs = true;   // nan: differs
                q.largest = std::isnan(d) || std::isnan(q.largest) ? d + q.largest : std::max(q.largest, d);
            }
            out.push_back(std::move(q));
        }
    }
    return out;
}

std::optional<Divergence> firstDivergence(const Probe& probe, const Answers& expected, const Answers& given,
                                          double margin)
{
    for (const QuantityDifference& q : answerDifferences(probe, expected, given, margin)) {
        if (!q.differs) continue;
        Divergence d;
        d.answer = q.answer;
        d.step = q.step;
        d.body = q.body;
        d.quantity = q.quantity;
        d.expected = q.expected;
        d.given = q.given;
        d.tolerance = q.tolerance;
        // the first component out of tolerance (false for nan: a divergence)
        while (d.component + 1 < static_cast<int>(q.given.size())
               && std::abs(q.given[d.component] - q.expected[d.component]) <= q.tolerance) {
            ++d.component;
        }
        return d;
    }
    return std::nullopt;
}

const char* verdictName(Verdict v)
{
    switch (v) {
    case Verdict::Matches: return "matches";
    case Verdict::Explained: return "explained";
    case Verdict::PartlyExplained: return "partly-explained";
    case Verdict::Unexplained: return "unexplained";
    }
    return "unexplained";
}

namespace {

// One candidate replayed against the answers.
struct Tried {
    ReplayModel model;
    bool all = false;                 // it reproduces every probe
    int wrongReproduced = 0;          // probes it reproduces where the right algorithm does not
    std::vector<std::size_t> probes;  // those probes
    std::optional<double> fit;        // its fitted c
};

// The distinct ids (a pair's as "a + b") of `models`, in their order.
std::vector<std::string> idsOf(const std::vector<Tried>& models)
{
    std::vector<std::string> ids;
    for (const Tried& t : models) {
        const std::string id = modelId(t.model);
        if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
    }
    return ids;
}

// One explanation: `mistakes` gets its ids (both of a pair); several: `possibleMistakes`
// every id of them once and `possibleExplanations` each one.
void name(SimulatorDiagnosis& d, const std::vector<Tried>& best)
{
    const std::vector<std::string> explanations = idsOf(best);
    if (explanations.size() == 1) {
        d.mistakes = modelIds(best.front().model);
    } else {
        d.possibleExplanations = explanations;
        for (const Tried& t : best) {
            for (const std::string& id : modelIds(t.model)) {
                if (std::find(d.possibleMistakes.begin(), d.possibleMistakes.end(), id) == d.possibleMistakes.end()) {
                    d.possibleMistakes.push_back(id);
                }
            }
        }
    }
    for (const Tried& t : best) {
        if (t.fit) d.restitution.push_back({modelLabel(t.model), *t.fit});
    }
}

} // namespace

std::vector<Answers> modelAnswers(const std::vector<Probe>& probes, const std::vector<Answers>& given,
                                  const ReplayModel& model, std::optional<double>* restitution)
{
    const bool anyCollides =
        std::any_of(probes.begin(), probes.end(), [](const Probe& p) { return p.collides; });
    const RestitutionFit fit = anyCollides ? fitRestitution(probes, given, model) : RestitutionFit{};
    const double c = fit.c;
    if (restitution != nullptr) *restitution = fit.determined ? std::optional<double>(c) : std::nullopt;
    std::vector<Answers> out;
    for (const Probe& p : probes) out.push_back(p.collides ? replayWithContacts(p, model, c) : replay(p, model));
    return out;
}

SimulatorDiagnosis diagnoseAnswers(const std::vector<Probe>& probes, const std::vector<Answers>& given,
                                   const std::vector<ReplayModel>& candidates)
{
    SimulatorDiagnosis d;
    const std::size_t n = std::min(probes.size(), given.size());
    d.probes.resize(n);
    bool allRight = true;
    std::optional<double> rightC;
    const std::vector<Answers> right = modelAnswers(probes, given, {}, &rightC);
    for (std::size_t p = 0; p < n; ++p) {
        const std::optional<Divergence> div = firstDivergence(probes[p], right[p], given[p]);
        d.probes[p].matchesRight = !div;
        d.probes[p].divergence = div;
        if (div && allRight) {
            d.divergenceProbe = static_cast<int>(p);
            d.firstDivergence = div;
        }
        allRight = allRight && !div;
    }
    if (allRight) {
        d.verdict = Verdict::Matches;
        if (rightC) d.restitution.push_back({modelLabel({}), *rightC});
        return d;
    }

    // Per candidate: does it reproduce every probe, and how many of the wrong ones.
    auto tryAll = [&](const std::vector<ReplayModel>& models) {
        std::vector<Tried> out;
        for (const ReplayModel& m : models) {
            Tried t{m, true, 0, {}, std::nullopt};
            const std::vector<Answers> expected = modelAnswers(probes, given, m, &t.fit);
            for (std::size_t p = 0; p < n; ++p) {
                const bool same = !firstDivergence(probes[p], expected[p], given[p]);
                t.all = t.all && same;
                if (same && !d.probes[p].matchesRight) {
                    ++t.wrongReproduced;
                    t.probes.push_back(p);
                }
            }
            out.push_back(std::move(t));
        }
        return out;
    };
    auto full = [](const std::vector<Tried>& tried) {
        std::vector<Tried> out;
        for (const Tried& t : tried) {
            if (t.all) out.push_back(t);
        }
        return out;
    };
    // Occam: a single model first; pairs of them only when no single one explains every
    // probe (a pair that explains them as well as a single model is never named).
    std::vector<ReplayModel> singles, givenPairs;
    for (const ReplayModel& m : candidates) (m.isPair() ? givenPairs : singles).push_back(m);
    const std::vector<Tried> single = tryAll(singles);
    std::vector<Tried> pairs;
    std::vector<Tried> named = full(single);
    if (named.empty()) {
        std::vector<ReplayModel> pairModels = modelPairs(singles);
        for (const ReplayModel& m : givenPairs) pairModels.push_back(m);
        pairs = tryAll(pairModels);
        named = full(pairs);
    }
    if (!named.empty()) {
        d.verdict = Verdict::Explained;
    } else {
        // the candidates that reproduce most of the wrong probes; a pair only when it
        // reproduces more than every single model
        int most = 0;
        for (const Tried& t : single) most = std::max(most, t.wrongReproduced);
        int mostOfPairs = 0;
        for (const Tried& t : pairs) mostOfPairs = std::max(mostOfPairs, t.wrongReproduced);
        const std::vector<Tried>& from = mostOfPairs > most ? pairs : single;
        most = std::max(most, mostOfPairs);
        for (const Tried& t : from) {
            if (most > 0 && t.wrongReproduced == most) named.push_back(t);
        }
        d.verdict = named.empty() ? Verdict::Unexplained : Verdict::PartlyExplained;
    }
    // Each probe's rows: the single models that reproduce it, and the named pairs.
    for (const Tried& t : single) {
        for (std::size_t p : t.probes) d.probes[p].reproducedBy.push_back(modelLabel(t.model));
    }
    for (const Tried& t : named) {
        if (!t.model.isPair()) continue;
        for (std::size_t p : t.probes) d.probes[p].reproducedBy.push_back(modelLabel(t.model));
    }
    if (!named.empty()) name(d, named);
    return d;
}

} // namespace rbw::probes
