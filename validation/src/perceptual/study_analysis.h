// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The experiment's analysis: observers screened by the control and the consistency repeat, rankings turned into
// pairwise comparisons, Thurstone Case V scores per test set (JOD, thurstone.h) with 95% bootstrap intervals over
// observers, a verdict per pair, and the agreement of people's order with mean FLIP's and RMS's.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "perceptual/study_key.h"
#include "perceptual/votes.h"

namespace stipple::validation {

// Exclusion rule (README: The perceptual experiment): an observer is left out when any control trial is failed
// (the control crop, the same region at control spp, not ranked strictly last: "no visible difference" fails),
// or when the repeats reverse every pair they repeat, over at least kMinRepeatedPairs pairs: consistency (share
// of repeated pairs ordered the same way, a tie against an order counting half) below kMinConsistency. Crops
// nobody can tell apart make honest answers random, and a random answerer reverses two 3-crop repeats
// completely 1 time in 36: the rule catches a scale read backwards, not doubt.
inline constexpr double kMinConsistency = 0.05;
inline constexpr int kMinRepeatedPairs = 6;

struct ObserverScreen {
    std::string observer, source;
    int controlsPassed = 0, controls = 0;
    double consistency = 0; // NaN: no repeat
    double medianSeconds = 0;
    bool excluded = false;
    std::string reason;
};

enum class PairVerdictKind { PreferredA, PreferredB, NotSeparated, Equivalent };

struct PairVerdict {
    size_t a = 0, b = 0; // crop indices of the set
    double difference = 0; // JOD, q_a − q_b (> 0: a preferred)
    double lo95 = 0, hi95 = 0, lo90 = 0, hi90 = 0;
    PairVerdictKind verdict = PairVerdictKind::NotSeparated;
    int observers = 0;
    int observersNeeded = 0; // for a decided verdict at the measured effect (80% power); 0: not estimable
};

struct SetAnalysis {
    std::vector<double> score, lo95, hi95; // per crop, JOD relative to crops[0]
    std::vector<PairVerdict> pairs;
    int observers = 0;
    double kendallFlip = 0, kendallRms = 0; // people's order against mean FLIP's / RMS's (1: the same)
};

struct StudyAnalysis {
    std::vector<ObserverScreen> screens;
    std::vector<SetAnalysis> sets; // as key.sets
    int included = 0;
    int bootstrapSamples = 0;
    uint64_t seed = 0;
    // Over every set's pairs: the share on which people and FLIP (RMS) order the pair the same way.
    double agreementFlip = 0, agreementRms = 0;
    int agreementPairs = 0;
};

inline constexpr int kDefaultBootstrapSamples = 2000;
inline constexpr uint64_t kDefaultBootstrapSeed = 20261201;

ObserverScreen screenObserver(const ObserverVotes& votes, const StudyKey& key);
// wins[i][j] of one observer's test trials of set `set` (ties half each way).
std::vector<std::vector<double>> observerWins(const ObserverVotes& votes, const StudyKey& key, size_t set);
StudyAnalysis analyseStudy(const StudyKey& key, const std::vector<ObserverVotes>& votes,
                           int bootstrapSamples = kDefaultBootstrapSamples, uint64_t seed = kDefaultBootstrapSeed);

const char* pairVerdictName(PairVerdictKind v);
std::string studyAnalysisText(const StudyKey& key, const StudyAnalysis& a);
std::string studyAnalysisJson(const StudyKey& key, const StudyAnalysis& a);

} // namespace stipple::validation
