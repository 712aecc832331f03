// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The equal_time and equal_spp checks: per scene (and per region of the scene), the patterns' efficiency ranking
// with 95% intervals (efficiency.h) — 1/(error · CPU s) at equal time, 1/error at equal samples, on MSE or mean
// FLIP — the claimed order judged pair by pair (PASS / FAIL / NOT SEPARATED), and the study's own conclusion
// printed beside the measured one.
#include "matrix/check_kind.h"
#include "claims/checks.h"
#include "claims/efficiency.h"
#include "claims/efficiency_claims.h"
#include "base/text.h"

#include <cmath>

namespace stipple::validation {

namespace {

struct EqualEfficiency : CheckParams {
    bool equalTime = false; // the kind: equal_time, else equal_spp
    std::string region;     // empty: the whole image and every region of the scene; else that region only
    std::vector<std::string> order; // most efficient first
    uint32_t spp = 0;
    bool flip = false; // metric: flip (mean LDR-FLIP) instead of mse
};

// Judges the claimed order on one ranking; appends the figures.
CheckStatus judge(const EqualEfficiency& k, const EfficiencyRanking& r, const std::string& where,
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

void evaluate(const Check& check, const CheckInputs& in, CheckOutcome& o) {
    const EqualEfficiency& k = paramsOf<EqualEfficiency>(check);
    const Matrix& m = in.matrix;
    const auto& rows = in.rows;
    std::string chain;
    for (const auto& p : k.order) chain += (chain.empty() ? "" : " > ") + p;
    const bool equalTime = k.equalTime;
    const char* measure = k.flip ? (equalTime ? "1/(mean FLIP·CPU s)" : "1/mean FLIP at equal samples")
                                 : (equalTime ? "efficiency 1/(MSE·CPU s)" : "1/MSE at equal samples");
    o.claim = fmt("%s %s%s @ %u spp: %s %s (geometric means over seeds, Welch 95%%)%s", check.kind->name,
                  check.scene.c_str(), k.region.empty() ? "" : (" region " + k.region).c_str(), k.spp, measure,
                  chain.c_str(), check.study.empty() ? "" : ("; study: " + check.study).c_str());
    bool any = false;
    for (const MatrixScene* sp : scenesOf(check, m)) {
        const MatrixScene& s = *sp;
        any = true;
        // FLIP has no reference-noise correction: its floor is 0 here.
        if (k.region.empty()) {
            const EfficiencyRanking r =
                k.flip ? rankEfficiency(rows, s.name, k.spp, m.patterns, 0, equalTime,
                                        [](const ResultRow& row) { return row.flip; })
                       : rankEfficiency(rows, s.name, k.spp, m.patterns, floorFromRows(rows, s.name), equalTime);
            worsen(o.status, judge(k, r, fmt("%s @ %u spp", s.name.c_str(), k.spp), o.figures));
        }
        for (size_t ri = 0; ri < s.regions.size(); ++ri) {
            if (!k.region.empty() && k.region != s.regions[ri].name) continue;
            const EfficiencyRanking rr =
                k.flip ? rankEfficiency(rows, s.name, k.spp, m.patterns, 0, equalTime,
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

// "stratified ahead of independent at equal CPU time in box, shadow (the study's plain MSE): holds".
std::string sentence(const CheckOutcome& o, const SentenceWords& w) {
    const EqualEfficiency& k = paramsOf<EqualEfficiency>(o.check);
    std::string order;
    for (const auto& p : k.order) order += (order.empty() ? "" : " ahead of ") + w.pattern(p);
    return order + (k.equalTime ? " at equal CPU time" : " per sample") + " in " + w.text(o.check.scene) +
           (k.region.empty() ? "" : ", " + w.text(k.region)) +
           (k.flip ? " (mean FLIP)" : " (the study's plain MSE)") + ": " + w.status(o.status);
}

// A region of the one scene named.
std::string readRegion(const CheckReader& r, const yaml::Node& n, const Check& c) {
    const std::string region = r.yaml.get<std::string>(n, "region");
    const MatrixScene* ms = r.matrix.findScene(c.scene);
    if (!ms) r.fail(n, "a region needs one scene, not 'all'");
    std::vector<std::string> names;
    bool known = false;
    for (const auto& rg : ms->regions) {
        names.push_back(rg.name);
        known |= rg.name == region;
    }
    if (!known)
        r.fail(n, "unknown region '" + region + "' of scene " + c.scene + " (its regions: " + joined(names) + ")");
    return region;
}

std::vector<CheckKey> keys() {
    return {
        sceneKey(true),
        optionalKey<std::string>("region", param(&EqualEfficiency::region), readRegion),
        requiredKey<std::vector<std::string>>("order", param(&EqualEfficiency::order),
                                              [](const CheckReader& r, const yaml::Node& n, const Check&) {
                                                  return readPatternList(r, n, "order", ", most efficient first");
                                              }),
        sppKey(&EqualEfficiency::spp),
        studyKey(),
        notSeparatedKey(false),
        metricKey(&EqualEfficiency::flip),
    };
}

} // namespace

extern const CheckKind kEqualTimeCheck;
const CheckKind kEqualTimeCheck{
    .name = "equal_time",
    .keys = keys(),
    .makeParams =
        [] {
            auto p = std::make_shared<EqualEfficiency>();
            p->equalTime = true;
            return p;
        },
    .evaluate = evaluate,
    .sentence = sentence,
};

extern const CheckKind kEqualSppCheck;
const CheckKind kEqualSppCheck{
    .name = "equal_spp",
    .keys = keys(),
    .makeParams = makeParams<EqualEfficiency>,
    .evaluate = evaluate,
    .sentence = sentence,
};

} // namespace stipple::validation
