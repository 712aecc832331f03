// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Equal-time efficiency: the study's question "at the same render time, which pattern has the least error?".
// Per seed, efficiency = 1 / (MSE_corrected · CPU seconds): a pattern twice as efficient reaches a given MSE in
// half the time. Patterns are ranked by the geometric mean over seeds, with a 95% t interval on the log scale
// (per-seed errors are right-skewed); consecutive patterns are compared with Welch's interval on the log
// difference. Also here: the reference's noise floor as a share of each cell's MSE, and the heavy-tail marking
// with its robust (trimmed) summary.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "matrix/matrix.h"
#include "run/results.h"

namespace stipple::validation {

// A cell's share of reference noise: floor / mean corrected MSE. Above this, the cell is flagged.
inline constexpr double kFloorShareLimit = 0.10;
// A cell is heavy-tailed when its worst seed's RMS is at least this multiple of its best seed's: over thousands
// of pixels a light-tailed error varies by some tens of percent between seeds (Cornell, independent, 16 spp:
// ±17%); Veach MIS's stratified seeds spread 3.8× (0.33-1.26), one bright path per seed deciding the error.
inline constexpr double kHeavyTailFactor = 2.0;

struct RobustRms {
    double trimmedMean = 0; // mean corrected RMS without the lowest and the highest seed (K ≥ 4; else the mean)
    double maxOverMin = 0;  // worst seed's RMS / best seed's
    bool heavyTailed = false;
};
RobustRms robustRms(const std::vector<double>& perSeedRms);

struct PatternEfficiency {
    std::string pattern;
    double efficiency = 0, lo = 0, hi = 0; // geometric mean over seeds and its 95% interval, 1 / (MSE · s)
    double logMean = 0, logVariance = 0;
    size_t seeds = 0;
    bool measuredMse = false; // a seed at the noise floor: measured MSE used (conservative)
    double floorShare = 0;    // noise floor / mean corrected MSE
    RobustRms rms;
};

struct EfficiencyStep {               // ranked[i] against ranked[i + 1]
    double ratio = 0, lo = 0, hi = 0; // efficiency ratio and its 95% Welch interval
    bool separated = false;           // lo > 1
};

struct EfficiencyRanking {
    std::string scene, region; // region empty: the whole image
    uint32_t spp = 0;
    bool equalTime = true;                 // 1 / (MSE · s); false: 1 / MSE
    std::vector<PatternEfficiency> ranked; // most efficient first
    std::vector<EfficiencyStep> steps;
    double ratioOf(const std::string& a, const std::string& b, double* lo = nullptr, double* hi = nullptr) const;
};

// Rows of one scene at one spp; `mse` picks the error (whole image or a region) from a row, `floor` is the
// reference's noise floor for that error.
using RowError = std::function<double(const ResultRow&)>; // measured MSE of a row (image or region)
// equalTime false: ranked by 1 / MSE alone (error at equal samples).
EfficiencyRanking rankEfficiency(
    const std::vector<ResultRow>& rows, const std::string& scene, uint32_t spp,
    const std::vector<std::string>& patterns, double floor, bool equalTime = true,
    const RowError& mse = [](const ResultRow& r) { return r.mse; });

// One-line form: "stratified 1.9× poisson (95% 1.6-2.3) > poisson ≈ independent (1.1×, 0.8-1.5)".
std::string rankingText(const EfficiencyRanking& r);

} // namespace stipple::validation
