// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "claims/timing.h"
#include "base/text.h"

#include <cmath>
#include <cstdio>
#include <limits>

namespace stipple::validation {

namespace {

double seconds(const ResultRow& r, TimeBasis basis) { return basis == TimeBasis::Cpu ? r.cpuSeconds : r.renderSeconds; }

} // namespace

PairedRatio pairedTimeRatio(const std::vector<ResultRow>& rows, const std::string& scene, const std::string& numerator,
                            const std::string& denominator, uint32_t spp, TimeBasis basis) {
    // Pair the two patterns' rows of one seed: they ran next to each other (interleaved), so a drift of the
    // machine's speed over minutes cancels in the ratio. Ratios are compared on the log scale, where a
    // ratio and its inverse are symmetric.
    std::vector<double> logRatios;
    for (const auto& a : rows) {
        if (a.scene != scene || a.pattern != numerator || (spp != kAllSpp && a.spp != spp) || !(seconds(a, basis) > 0))
            continue;
        for (const auto& b : rows)
            if (b.scene == scene && b.pattern == denominator && b.spp == a.spp && b.seed == a.seed &&
                seconds(b, basis) > 0)
                logRatios.push_back(std::log(seconds(a, basis) / seconds(b, basis)));
    }
    PairedRatio r;
    r.pairs = logRatios.size();
    if (logRatios.empty()) {
        r.ratio = r.lo = r.hi = r.lo90 = r.hi90 = std::numeric_limits<double>::quiet_NaN();
        return r;
    }
    const Interval i = meanInterval(logRatios), i90 = meanInterval(logRatios, 0.90);
    r.ratio = std::exp(i.mean);
    r.lo = std::exp(i.lo());
    r.hi = std::exp(i.hi());
    r.lo90 = std::exp(i90.lo());
    r.hi90 = std::exp(i90.hi());
    return r;
}

CheckStatus equivalenceVerdict(const PairedRatio& r, double lo, double hi) {
    if (r.lo90 >= lo && r.hi90 <= hi) return CheckStatus::Pass;
    if (r.lo > hi || r.hi < lo) return CheckStatus::Fail;
    return CheckStatus::NotSeparated; // reaches outside the margin without leaving it, or NaN (too few pairs)
}

CheckStatus ratioVerdict(const PairedRatio& r, double bound) {
    if (r.hi <= bound) return CheckStatus::Pass;
    if (r.lo > bound) return CheckStatus::Fail;
    return CheckStatus::NotSeparated; // straddles the bound, or NaN (too few pairs)
}

} // namespace stipple::validation
