// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "timing.h"
#include "text.h"

#include <cmath>
#include <cstdio>
#include <limits>

namespace stipple::validation {

namespace {


double seconds(const ResultRow& r, TimeBasis basis) { return basis == TimeBasis::Cpu ? r.cpuSeconds : r.renderSeconds; }

std::string ratioText(const PairedRatio& r) {
    return fmt("%.3f (95%% %.3f-%.3f, 90%% %.3f-%.3f, %zu pairs)", r.ratio, r.lo, r.hi, r.lo90, r.hi90, r.pairs);
}

} // namespace

PairedRatio pairedTimeRatio(const std::vector<ResultRow>& rows, const std::string& scene, const std::string& numerator,
                            const std::string& denominator, uint32_t spp, TimeBasis basis) {
    // Pair the two patterns' rows of one seed: they ran next to each other (interleaved), so a drift of the
    // machine's speed over minutes cancels in the ratio. Ratios are compared on the log scale, where a
    // ratio and its inverse are symmetric.
    std::vector<double> logRatios;
    for (const auto& a : rows) {
        if (a.scene != scene || a.pattern != numerator || a.spp != spp || !(seconds(a, basis) > 0)) continue;
        for (const auto& b : rows)
            if (b.scene == scene && b.pattern == denominator && b.spp == spp && b.seed == a.seed &&
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

void evaluateTimeRatio(const Check& k, const Matrix& m, const std::vector<ResultRow>& rows, CheckOutcome& o) {
    const std::string bound =
        k.timeEquivalence ? fmt("within [%.3g, %.3g] (90%% interval inside: EQUIVALENT)", k.marginLo, k.marginHi)
                          : fmt("≤ %.3g", k.maxRatio);
    auto verdict = [&](const PairedRatio& r) {
        return k.timeEquivalence ? equivalenceVerdict(r, k.marginLo, k.marginHi) : ratioVerdict(r, k.maxRatio);
    };
    o.claim = fmt("time_ratio %s @ %u spp: %s / %s %s in thread CPU seconds (geometric mean of paired "
                  "per-seed ratios, t intervals; wall seconds beside)",
                  k.scene.c_str(), k.spp, k.numerator.c_str(), k.denominator.c_str(), bound.c_str());
    bool any = false;
    for (const auto& s : m.scenes) {
        if (k.scene != "all" && k.scene != s.name) continue;
        any = true;
        const PairedRatio cpu = pairedTimeRatio(rows, s.name, k.numerator, k.denominator, k.spp, TimeBasis::Cpu);
        const PairedRatio wall = pairedTimeRatio(rows, s.name, k.numerator, k.denominator, k.spp, TimeBasis::Wall);
        if (cpu.pairs == 0) {
            o.status = CheckStatus::Fail;
            o.figures.push_back(fmt("%s: cells missing (no paired rows with CPU seconds)", s.name.c_str()));
            continue;
        }
        const CheckStatus v = verdict(cpu);
        if (v == CheckStatus::Fail)
            o.status = CheckStatus::Fail;
        else if (v == CheckStatus::NotSeparated && o.status == CheckStatus::Pass)
            o.status = v;
        o.figures.push_back(fmt("%s: CPU ratio %s; wall ratio %s [wall alone: %s]%s", s.name.c_str(),
                                ratioText(cpu).c_str(), ratioText(wall).c_str(), checkStatusName(verdict(wall)),
                                v == CheckStatus::Pass ? "" : fmt("   <-- %s", checkStatusName(v)).c_str()));
    }
    if (!any) {
        o.status = CheckStatus::Fail;
        o.figures.push_back("no scene matches");
    }
}

} // namespace stipple::validation
