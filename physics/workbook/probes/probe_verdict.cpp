#include "physics/workbook/probes/probe_verdict.h"

#include "physics/workbook/probes/collision_replay.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

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

std::optional<Divergence> firstDivergence(const Probe& probe, const Answers& expected, const Answers& given,
                                          double margin)
{
    const std::vector<double> s = scales(expected);
    const std::vector<AnswerSlot> slots = answerSlots(probe);
    const std::size_t n = std::min({expected.size(), given.size(), slots.size()});
    for (std::size_t k = 0; k < n; ++k) {
        const Answer& e = expected[k];
        const Answer& g = given[k];
        for (int bi = 0; bi < 4; ++bi) {
            const Block& b = kBlocks[bi];
            if (static_cast<int>(e.size()) < b.first + b.size || static_cast<int>(g.size()) < b.first + b.size) continue;
            const double tol = margin * kRelativeTolerance * s[bi];
            // r and -r are the same orientation: compare with the sign that fits better
            double sign = 1.0;
            if (bi == 3) {
                double plus = 0.0, minus = 0.0;
                for (int i = b.first; i < b.first + b.size; ++i) {
                    plus = std::max(plus, std::abs(g[i] - e[i]));
                    minus = std::max(minus, std::abs(g[i] + e[i]));
                }
                if (minus < plus) sign = -1.0;
            }
            for (int i = b.first; i < b.first + b.size; ++i) {
                if (std::abs(g[i] - sign * e[i]) <= tol) continue;   // false for nan: a divergence
                Divergence d;
                d.answer = static_cast<int>(k);
                d.step = slots[k].step;
                d.body = slots[k].body;
                d.quantity = b.name;
                d.component = i - b.first;
                d.expected = slice(e, b);
                if (sign < 0.0) {
                    for (double& v : d.expected) v = -v;
                }
                d.given = slice(g, b);
                d.tolerance = tol;
                return d;
            }
        }
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

// The distinct ids of `models`, in their order.
std::vector<std::string> idsOf(const std::vector<ReplayModel>& models)
{
    std::vector<std::string> ids;
    for (const ReplayModel& m : models) {
        const std::string id = modelId(m);
        if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
    }
    return ids;
}

void name(SimulatorDiagnosis& d, const std::vector<ReplayModel>& best,
          const std::vector<std::optional<double>>& fits, const std::vector<ReplayModel>& candidates)
{
    const std::vector<std::string> ids = idsOf(best);
    if (ids.size() == 1) d.mistakes = ids;
    else d.possibleMistakes = ids;
    for (const ReplayModel& m : best) {
        const std::size_t k = static_cast<std::size_t>(std::find(candidates.begin(), candidates.end(), m) - candidates.begin());
        if (k < fits.size() && fits[k]) d.restitution.push_back({modelLabel(m), *fits[k]});
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
    std::vector<ReplayModel> full;
    std::vector<ReplayModel> best;
    int bestCount = 0;
    std::vector<std::optional<double>> fits;
    for (const ReplayModel& m : candidates) {
        bool all = true;
        int wrongReproduced = 0;
        fits.emplace_back();
        const std::vector<Answers> expected = modelAnswers(probes, given, m, &fits.back());
        for (std::size_t p = 0; p < n; ++p) {
            const bool same = !firstDivergence(probes[p], expected[p], given[p]);
            all = all && same;
            if (same && !d.probes[p].matchesRight) {
                ++wrongReproduced;
                d.probes[p].reproducedBy.push_back(modelLabel(m));
            }
        }
        if (all) full.push_back(m);
        if (wrongReproduced > bestCount) {
            bestCount = wrongReproduced;
            best.clear();
        }
        if (wrongReproduced == bestCount && wrongReproduced > 0) best.push_back(m);
    }
    if (!full.empty()) {
        d.verdict = Verdict::Explained;
        name(d, full, fits, candidates);
    } else if (!best.empty()) {
        d.verdict = Verdict::PartlyExplained;
        name(d, best, fits, candidates);
    } else {
        d.verdict = Verdict::Unexplained;
    }
    return d;
}

} // namespace rbw::probes
