// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "efficiency_claims.h"
#include "text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "efficiency.h"

namespace stipple::validation {

namespace {

// Judges the claimed order on one ranking; appends the figures.
CheckStatus judge(const Check& k, const EfficiencyRanking& r, const std::string& where,
                  std::vector<std::string>& figures) {
    CheckStatus status = CheckStatus::Pass;
    std::string line = where + ": ";
    for (size_t i = 0; i + 1 < k.order.size(); ++i) {
        double lo = NAN, hi = NAN;
        const double ratio = r.ratioOf(k.order[i], k.order[i + 1], &lo, &hi);
        CheckStatus s = std::isnan(ratio) ? CheckStatus::Fail
                        : lo > 1          ? CheckStatus::Pass
                        : hi < 1          ? CheckStatus::Fail
                                          : CheckStatus::NotSeparated;
        worsen(status, s);
        line += fmt("%s%s/%s %.2f× (95%% %.2f-%.2f) %s", i ? "; " : "", k.order[i].c_str(), k.order[i + 1].c_str(),
                    ratio, lo, hi, checkStatusName(s));
    }
    figures.push_back(line + (status == CheckStatus::Pass ? "" : fmt("   <-- %s", checkStatusName(status))));
    figures.push_back("    measured ranking: " + rankingText(r));
    for (const auto& p : r.ranked)
        if (p.floorShare > kFloorShareLimit)
            figures.push_back(fmt("    note: %s's reference noise floor is %.0f%% of its MSE (> %.0f%%): the claim "
                                  "uses a floor-limited cell",
                                  p.pattern.c_str(), 100 * p.floorShare, 100 * kFloorShareLimit));
    return status;
}
} // namespace

double floorFromRows(const std::vector<ResultRow>& rows, const std::string& scene, int region) {
    double floor = 0;
    for (const auto& r : rows) {
        if (r.scene != scene) continue;
        const size_t i = size_t(region);
        const double mse = region < 0 ? r.mse : i < r.regionMse.size() ? r.regionMse[i] : NAN;
        const double corrected = region < 0                        ? r.mseCorrected
                                 : i < r.regionMseCorrected.size() ? r.regionMseCorrected[i]
                                                                   : NAN;
        if (std::isfinite(mse) && std::isfinite(corrected)) floor = std::max(floor, mse - corrected);
    }
    return floor;
}

void evaluateEqualTime(const Check& k, const Matrix& m, const std::vector<ResultRow>& rows, CheckOutcome& o) {
    std::string chain;
    for (const auto& p : k.order) chain += (chain.empty() ? "" : " > ") + p;
    const bool equalTime = k.type == CheckType::EqualTime;
    const char* measure = k.flipMetric ? (equalTime ? "1/(mean FLIP·CPU s)" : "1/mean FLIP at equal samples")
                                       : (equalTime ? "efficiency 1/(MSE·CPU s)" : "1/MSE at equal samples");
    o.claim = fmt("%s %s%s @ %u spp: %s %s (geometric means over seeds, Welch 95%%)%s", checkTypeName(k.type),
                  k.scene.c_str(), k.region.empty() ? "" : (" region " + k.region).c_str(), k.spp, measure,
                  chain.c_str(), k.study.empty() ? "" : ("; study: " + k.study).c_str());
    bool any = false;
    for (const auto& s : m.scenes) {
        if (k.scene != "all" && k.scene != s.name) continue;
        any = true;
        // FLIP has no reference-noise correction: its floor is 0 here.
        if (k.region.empty()) {
            const EfficiencyRanking r =
                k.flipMetric ? rankEfficiency(rows, s.name, k.spp, m.patterns, 0, equalTime,
                                              [](const ResultRow& row) { return row.flip; })
                             : rankEfficiency(rows, s.name, k.spp, m.patterns, floorFromRows(rows, s.name), equalTime);
            worsen(o.status, judge(k, r, fmt("%s @ %u spp", s.name.c_str(), k.spp), o.figures));
        }
        for (size_t ri = 0; ri < s.regions.size(); ++ri) {
            if (!k.region.empty() && k.region != s.regions[ri].name) continue;
            const EfficiencyRanking rr =
                k.flipMetric ? rankEfficiency(rows, s.name, k.spp, m.patterns, 0, equalTime,
                                              [ri](const ResultRow& row) {
                                                  return ri < row.regionFlip.size() ? row.regionFlip[ri] : NAN;
                                              })
                             : rankEfficiency(rows, s.name, k.spp, m.patterns, floorFromRows(rows, s.name, int(ri)),
                                              equalTime, [ri](const ResultRow& row) {
                                                  return ri < row.regionMse.size() ? row.regionMse[ri] : NAN;
                                              });
            worsen(o.status, judge(k, rr, fmt("%s region %s", s.name.c_str(), s.regions[ri].name.c_str()), o.figures));
        }
    }
    if (!any) {
        o.status = CheckStatus::Fail;
        o.figures.push_back("no scene matches");
    }
}

} // namespace stipple::validation
