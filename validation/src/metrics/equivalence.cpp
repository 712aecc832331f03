// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "metrics/equivalence.h"
#include "base/text.h"

#include <algorithm>
#include <cmath>

#include "metrics/statistics.h"

namespace stipple::validation {

ErrorEstimate estimateFromBlocks(const std::vector<std::vector<double>>& perSeed, const std::vector<int>& unitOf,
                                 double pixels, double floor) {
    ErrorEstimate e;
    e.seeds = perSeed.size();
    if (perSeed.empty() || !(pixels > 0)) return e;
    const size_t blocks = perSeed.front().size();
    for (const auto& s : perSeed)
        if (s.size() != blocks) return ErrorEstimate{};
    int units = 0;
    for (size_t b = 0; b < blocks; ++b) units = std::max(units, unitOf.empty() ? int(b) + 1 : unitOf[b] + 1);
    e.units = size_t(units);
    // Per seed, the units' sums; then per unit its mean and variance over the seeds.
    std::vector<std::vector<double>> unitValues(size_t(units), std::vector<double>(e.seeds, 0.0));
    for (size_t k = 0; k < e.seeds; ++k)
        for (size_t b = 0; b < blocks; ++b) unitValues[unitOf.empty() ? b : size_t(unitOf[b])][k] += perSeed[k][b];
    double total = 0, varianceSum = 0, varianceSquares = 0;
    for (const auto& v : unitValues) {
        total += mean(v);
        const double s2 = sampleVariance(v);
        varianceSum += s2;
        varianceSquares += s2 * s2;
    }
    const double k = double(e.seeds);
    e.mean = total / pixels - floor;
    e.variance = varianceSum / (k * pixels * pixels);
    // Satterthwaite: each unit's variance has K − 1 dof; one dominating unit leaves K − 1 in all.
    e.dof = varianceSquares > 0 ? varianceSum * varianceSum / (varianceSquares / (k - 1)) : k - 1;
    return e;
}

const char* verdictName(Verdict v) {
    switch (v) {
    case Verdict::Equivalent: return "EQUIVALENT";
    case Verdict::Better: return "BETTER";
    case Verdict::Worse: return "WORSE";
    case Verdict::NotSeparated: return "NOT SEPARATED";
    case Verdict::Unmeasured: break;
    }
    return "UNMEASURED";
}

Comparison judgeLogRatio(double logRatio, double variance, double dof, const Margin& margin) {
    Comparison c;
    if (!std::isfinite(logRatio) || !(variance >= 0) || !(dof > 0)) return c;
    const double se = std::sqrt(variance);
    const double t95 = studentTQuantile(0.975, dof), t90 = studentTQuantile(0.95, dof);
    c.ratio = std::exp(logRatio);
    c.lo95 = std::exp(logRatio - t95 * se);
    c.hi95 = std::exp(logRatio + t95 * se);
    c.lo90 = std::exp(logRatio - t90 * se);
    c.hi90 = std::exp(logRatio + t90 * se);
    c.dof = dof;
    c.separated = c.hi95 < 1 || c.lo95 > 1;
    c.equivalent = c.lo90 >= margin.lo && c.hi90 <= margin.hi;
    // A difference smaller than the margin is reported as equivalent: the ratio and interval say which way it leans.
    c.verdict = c.equivalent ? Verdict::Equivalent
                : c.hi95 < 1 ? Verdict::Better
                : c.lo95 > 1 ? Verdict::Worse
                             : Verdict::NotSeparated;
    return c;
}

LogShift pairedLogRatio(const std::vector<double>& a, const std::vector<double>& b) {
    std::vector<double> d;
    for (size_t i = 0; i < std::min(a.size(), b.size()); ++i)
        if (a[i] > 0 && b[i] > 0) d.push_back(std::log(a[i] / b[i]));
    LogShift s;
    if (d.size() < 2) return {NAN, NAN, 0};
    s.mean = mean(d);
    s.variance = sampleVariance(d) / double(d.size());
    s.dof = double(d.size() - 1);
    return s;
}

Comparison compareErrors(const ErrorEstimate& a, const ErrorEstimate& b, const Margin& margin, const LogShift& shift) {
    if (!a.valid() || !b.valid() || !std::isfinite(shift.mean)) return Comparison{};
    // Delta method on the log scale: Var log m ≈ Var m / m².
    const double va = a.variance / (a.mean * a.mean), vb = b.variance / (b.mean * b.mean);
    const double vs = shift.variance;
    const double variance = va + vb + vs;
    // Welch–Satterthwaite over the independent parts.
    double denominator = va * va / a.dof + vb * vb / b.dof + (vs > 0 ? vs * vs / shift.dof : 0);
    const double dof = denominator > 0 ? variance * variance / denominator : std::min(a.dof, b.dof);
    return judgeLogRatio(std::log(a.mean / b.mean) + shift.mean, variance, dof, margin);
}

std::string ratioText(const Comparison& c) {
    if (c.verdict == Verdict::Unmeasured) return "–";
    return fmt("%.3g× (95%% %.3g–%.3g)", c.ratio, c.lo95, c.hi95);
}

} // namespace stipple::validation
