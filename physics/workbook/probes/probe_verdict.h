// What a simulator's answers to the probes say (issue 23, docs/simulator-protocol.md,
// "Verdicts"): whether the right algorithm reproduces them, which mistake model does,
// and where they first leave the right algorithm. Used by `rbw diagnose --simulator`
// (app/cli/diagnose_command.cpp) and by the distinguishability test.
//
// When two numbers are the same: |given - expected| <= kRelativeTolerance * s, s the
// largest |value| of that quantity (x, v, omega or r) in the expected answers of the
// whole probe (1 when it is zero throughout), so that float round-off matches, as in
// the TUM template's own tests (relative 1e-4). r is compared up to its sign (r and -r
// are the same orientation), and only when both sides give it (13 numbers).
#pragma once

#include "physics/workbook/probes/probes.h"
#include "physics/workbook/probes/replay.h"

#include <optional>
#include <string>
#include <vector>

namespace rbw::probes {

constexpr double kRelativeTolerance = 1e-4;

// The first number that differs.
struct Divergence {
    int answer = 0;         // index of the answer among the probe's `state` answers
    int step = 0;           // steps before it (answerSlots)
    int body = 0;
    std::string quantity;   // "x", "v", "omega" or "r"
    int component = 0;      // 0, 1, 2 (, 3 for r: w, x, y, z)
    std::vector<double> expected, given;   // the whole quantity, 3 (r: 4) numbers
    double tolerance = 0.0;                // the allowed |difference|, times the margin
};

// The first number of `given` farther than margin * tolerance from `expected` (answers
// in order, then x, v, omega, r, then components); none when every number agrees.
// `given` may have 9 or 13 numbers per answer; a missing answer is not compared.
std::optional<Divergence> firstDivergence(const Probe& probe, const Answers& expected, const Answers& given,
                                          double margin = 1.0);

// How one quantity (x, v, omega or r) of one answer compares with the expected one, by
// the rule of firstDivergence (the same tolerance and margin, r up to its sign): the
// first entry that `differs`, in order, is firstDivergence's answer and quantity.
struct QuantityDifference {
    int answer = 0;         // index among the probe's `state` answers
    int step = 0;           // steps before it (answerSlots)
    int body = 0;
    std::string quantity;   // "x", "v", "omega" or "r"
    std::vector<double> expected, given;   // 3 (r: 4) numbers; expected with r's sign turned to fit
    double largest = 0.0;   // the largest |given - expected| of its components (nan if one is nan)
    double tolerance = 0.0; // the allowed |difference|, times the margin
    bool differs = false;
};

// Every quantity of every answer both sides give, in the order firstDivergence reads them.
std::vector<QuantityDifference> answerDifferences(const Probe& probe, const Answers& expected, const Answers& given,
                                                  double margin = 1.0);

enum class Verdict { Matches, Explained, PartlyExplained, Unexplained };
const char* verdictName(Verdict v);   // "matches", "explained", "partly-explained", "unexplained"

struct ProbeOutcome {
    bool matchesRight = false;
    std::optional<Divergence> divergence;    // this probe's first divergence from the right algorithm
    std::vector<std::string> reproducedBy;   // labels of the single models that give these answers,
                                             // and of the named pairs
};

// A fitted coefficient of restitution (collision probes) and the model it belongs to.
struct RestitutionOf {
    std::string model;   // modelLabel()
    double c = 0.0;
};

struct SimulatorDiagnosis {
    Verdict verdict = Verdict::Unexplained;
    std::vector<std::string> mistakes;           // the one explanation's id (a pair: both ids)
    std::vector<std::string> possibleMistakes;   // every id of them, when several explain equally well
    std::vector<std::string> possibleExplanations;   // then each of them: "a", or a pair "a + b" (modelId)
    int divergenceProbe = -1;                    // index of the probe of firstDivergence, -1: none
    std::optional<Divergence> firstDivergence;   // against the right algorithm
    std::vector<ProbeOutcome> probes;            // one per probe
    // With collision probes: c fitted for the right algorithm (matches) or for each
    // named model (mistakes, possible_mistakes) whose answers depend on c; empty
    // without collision probes.
    std::vector<RestitutionOf> restitution;
};

// What `model` answers to each probe; a probe that collides is replayed with contacts
// and the c fitted to `given` over all such probes (collision_replay.h), which
// *restitution receives (nullopt: no collision probe, or c changes none of the model's
// answers: relative-velocity-reversed never applies an impulse on an approaching
// contact).
std::vector<Answers> modelAnswers(const std::vector<Probe>& probes, const std::vector<Answers>& given,
                                  const ReplayModel& model, std::optional<double>* restitution = nullptr);

// `given[i]` holds the answers to probes[i]; `candidates` are single models (a pair
// among them is tried with the pairs). Verdicts:
//   matches           the right algorithm reproduces every answer;
//   explained         a candidate, or a pair of two of them (modelPairs()), reproduces
//                     every answer of every probe; pairs are tried only when no single
//                     model does (Occam: a pair that explains as well as a single model
//                     is never named);
//   partly-explained  none does, but some reproduce the answers of a probe where the
//                     right algorithm does not (the ones that do so for most probes are
//                     named; a pair only when it reproduces more probes than any single);
//   unexplained       no candidate reproduces any probe where the answers are wrong.
// Several explanations that do equally well are possibleExplanations (their ids in
// possibleMistakes). Candidates that differ only in their variant count as one id.
// Probes that collide are replayed with contacts and each candidate's own fitted c
// (modelAnswers).
SimulatorDiagnosis diagnoseAnswers(const std::vector<Probe>& probes, const std::vector<Answers>& given,
                                   const std::vector<ReplayModel>& candidates);

} // namespace rbw::probes
