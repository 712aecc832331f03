// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "claims/efficiency.h"
#include "base/text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "metrics/statistics.h"

namespace stipple::validation {

namespace {


// Time of a row: thread CPU seconds when the renderer reported them, else wall seconds (older results).
double cost(const ResultRow& r) { return r.cpuSeconds > 0 ? r.cpuSeconds : r.renderSeconds; }

} // namespace

RobustRms robustRms(const std::vector<double>& perSeed) {
    RobustRms r;
    if (perSeed.empty()) return r;
    std::vector<double> v = perSeed;
    std::sort(v.begin(), v.end());
    const size_t trim = v.size() >= 4 ? 1 : 0;
    double sum = 0;
    for (size_t i = trim; i < v.size() - trim; ++i) sum += v[i];
    r.trimmedMean = sum / double(v.size() - 2 * trim);
    r.maxOverMin = v.front() > 0 ? v.back() / v.front() : INFINITY;
    r.heavyTailed = v.size() >= 2 && r.maxOverMin >= kHeavyTailFactor;
    return r;
}

double EfficiencyRanking::ratioOf(const std::string& a, const std::string& b, double* lo, double* hi) const {
    const PatternEfficiency *pa = nullptr, *pb = nullptr;
    for (const auto& p : ranked) {
        if (p.pattern == a) pa = &p;
        if (p.pattern == b) pb = &p;
    }
    if (!pa || !pb) return NAN;
    const Interval d =
        welchDifference({pa->logMean, pa->logVariance, pa->seeds}, {pb->logMean, pb->logVariance, pb->seeds});
    if (lo) *lo = std::exp(d.lo());
    if (hi) *hi = std::exp(d.hi());
    return std::exp(d.mean);
}

EfficiencyRanking rankEfficiency(const std::vector<ResultRow>& rows, const std::string& scene, uint32_t spp,
                                 const std::vector<std::string>& patterns, double floor, bool equalTime,
                                 const RowError& mse) {
    EfficiencyRanking out;
    out.scene = scene;
    out.spp = spp;
    out.equalTime = equalTime;
    for (const auto& pattern : patterns) {
        std::vector<const ResultRow*> mine;
        for (const auto& r : rows)
            if (r.scene == scene && r.pattern == pattern && r.spp == spp && cost(r) > 0) mine.push_back(&r);
        if (mine.empty()) continue;
        PatternEfficiency p;
        p.pattern = pattern;
        p.seeds = mine.size();
        std::vector<double> corrected, rms;
        for (const ResultRow* r : mine) {
            corrected.push_back(std::max(mse(*r) - floor, 0.0));
            rms.push_back(std::sqrt(corrected.back()));
        }
        // A seed at the floor has no finite efficiency; the measured MSE (floor included) is then used for the
        // whole cell, which can only understate its efficiency.
        p.measuredMse = std::any_of(corrected.begin(), corrected.end(), [](double e) { return !(e > 0); });
        std::vector<double> logs;
        for (size_t i = 0; i < mine.size(); ++i) {
            const double e = p.measuredMse ? mse(*mine[i]) : corrected[i];
            if (e > 0) logs.push_back(-std::log(e * (equalTime ? cost(*mine[i]) : 1.0)));
        }
        if (logs.empty()) continue;
        const SampleSummary s = summarize(logs);
        p.logMean = s.mean;
        p.logVariance = s.variance;
        p.seeds = s.count;
        const Interval i = meanInterval(logs);
        p.efficiency = std::exp(i.mean);
        p.lo = std::exp(i.lo());
        p.hi = std::exp(i.hi());
        const double meanCorrected = mean(corrected);
        p.floorShare = meanCorrected > 0 ? floor / meanCorrected : INFINITY;
        p.rms = robustRms(rms);
        out.ranked.push_back(p);
    }
    std::stable_sort(out.ranked.begin(), out.ranked.end(),
                     [](const PatternEfficiency& a, const PatternEfficiency& b) { return a.logMean > b.logMean; });
    for (size_t i = 0; i + 1 < out.ranked.size(); ++i) {
        EfficiencyStep st;
        st.ratio = out.ratioOf(out.ranked[i].pattern, out.ranked[i + 1].pattern, &st.lo, &st.hi);
        st.separated = st.lo > 1;
        out.steps.push_back(st);
    }
    return out;
}

std::string rankingText(const EfficiencyRanking& r) {
    std::string s;
    for (size_t i = 0; i < r.ranked.size(); ++i) {
        const auto& p = r.ranked[i];
        s += p.pattern;
        if (p.rms.heavyTailed) s += " [heavy-tailed]";
        if (p.floorShare > kFloorShareLimit) s += fmt(" [reference floor %.0f%% of MSE]", 100 * p.floorShare);
        if (p.measuredMse) s += " [measured MSE]";
        if (i < r.steps.size()) {
            const auto& st = r.steps[i];
            s += fmt(" %s (%.2f×, 95%% %.2f-%.2f) ", st.separated ? ">" : "≈", st.ratio, st.lo, st.hi);
        }
    }
    return s;
}

} // namespace stipple::validation
