// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The ordering check: in every named scene and at every spp from spp_min up, the patterns' RMS errors in the
// claimed order, best first, each pair separated with 95% confidence.
#include "matrix/check_kind.h"
#include "claims/checks.h"
#include "base/text.h"

#include <cmath>

namespace stipple::validation {

namespace {

struct Ordering : CheckParams {
    uint32_t sppMin = 0;
    std::vector<std::string> order; // best → worst
};

std::string rmsText(const CellAggregate& c) {
    return fmt("%s %.5g ± %.2g", c.pattern.c_str(), c.rms.mean, c.rms.halfWidth);
}

// -1 when a's RMS is established below b's, +1 above, 0 undecided; `why` gets the figures behind it.
// Per-seed RMS of a render is right-skewed (one seed meets a rare bright path), so the comparison is made on
// log RMS: a < b when Welch's 95% interval of mean log RMS(a) - mean log RMS(b) lies below 0, i.e. the ratio
// of geometric means is below 1 with 95% confidence. A seed at the reference's noise floor has zero corrected
// RMS and no logarithm; then both cells are compared on the measured RMS, which carries the same floor on both
// sides and so can only pull the ratio towards 1 (conservative). Failing that, the 95% intervals of mean RMS
// must be disjoint.
int compareRms(const CellAggregate& a, const CellAggregate& b, std::string& why) {
    auto complete = [](const CellAggregate& c, const SampleSummary& s) { return c.seeds >= 2 && s.count == c.seeds; };
    const bool corrected = complete(a, a.logRms) && complete(b, b.logRms);
    if (corrected || (complete(a, a.logRmsMeasured) && complete(b, b.logRmsMeasured))) {
        const Interval d =
            corrected ? welchDifference(a.logRms, b.logRms) : welchDifference(a.logRmsMeasured, b.logRmsMeasured);
        why = fmt(" (%sgeometric-mean ratio %.3g, 95%% %.3g-%.3g)",
                  corrected ? "" : "measured RMS, a seed at the floor: ", std::exp(d.mean), std::exp(d.lo()),
                  std::exp(d.hi()));
        return d.hi() < 0 ? -1 : d.lo() > 0 ? 1 : 0;
    }
    why = " (mean RMS intervals)";
    return separatedBelow(a.rms, b.rms) ? -1 : separatedBelow(b.rms, a.rms) ? 1 : 0;
}

void evaluate(const Check& check, const CheckInputs& in, CheckOutcome& o) {
    const Ordering& k = paramsOf<Ordering>(check);
    std::string chain;
    for (const auto& p : k.order) chain += (chain.empty() ? "" : " < ") + p;
    o.claim = fmt("ordering %s spp ≥ %u: RMS %s (Welch 95%% on log RMS: geometric-mean ratio < 1)",
                  check.scene.c_str(), k.sppMin, chain.c_str());
    for (const MatrixScene* s : scenesOf(check, in.matrix))
        for (uint32_t spp : in.matrix.spp) {
            if (spp < k.sppMin) continue;
            const std::string& scene = s->name;
            std::string line = fmt("%s @ %u spp: ", scene.c_str(), spp);
            CheckStatus cellStatus = CheckStatus::Pass;
            for (size_t i = 0; i + 1 < k.order.size(); ++i) {
                const CellAggregate* a = findCell(in.cells, scene, k.order[i], spp);
                const CellAggregate* b = findCell(in.cells, scene, k.order[i + 1], spp);
                if (!a || !b) {
                    line += fmt("[cell %s/%s missing] ", scene.c_str(), (!a ? k.order[i] : k.order[i + 1]).c_str());
                    worsen(cellStatus, CheckStatus::Fail);
                    continue;
                }
                if (a->unmeasuredSeeds || b->unmeasuredSeeds) { // no verdict from a cell without a finite error
                    line += fmt("[cell %s/%s: %zu seeds without a finite error] ", scene.c_str(),
                                (a->unmeasuredSeeds ? a : b)->pattern.c_str(),
                                (a->unmeasuredSeeds ? a : b)->unmeasuredSeeds);
                    worsen(cellStatus, CheckStatus::Fail);
                    continue;
                }
                std::string why;
                const int order = compareRms(*a, *b, why);
                const char* relation = order < 0 ? "<" : order > 0 ? "> (reversed)" : "~ (not separated)";
                if (order > 0) worsen(cellStatus, CheckStatus::Fail);
                if (order == 0) worsen(cellStatus, CheckStatus::NotSeparated);
                if (i == 0) line += rmsText(*a);
                line += fmt(" %s %s%s", relation, rmsText(*b).c_str(), why.c_str());
            }
            if (cellStatus != CheckStatus::Pass) line += fmt("   <-- %s", checkStatusName(cellStatus));
            worsen(o.status, cellStatus);
            o.figures.push_back(line);
        }
    if (o.figures.empty()) {
        o.status = CheckStatus::Fail;
        o.figures.push_back("no cell matches (no spp ≥ spp_min for these scenes)");
    }
}

} // namespace

extern const CheckKind kOrderingCheck;
const CheckKind kOrderingCheck{
    .name = "ordering",
    .keys =
        {
            sceneKey(true),
            optionalKey<uint32_t>(
                "spp_min", param(&Ordering::sppMin),
                [](const CheckReader& r, const yaml::Node& n, const Check&) {
                    const uint32_t v = r.yaml.spp(n, "spp_min");
                    if (v > r.matrix.spp.back()) r.fail(n, "spp_min is above every spp of the matrix");
                    return v;
                },
                [](const CheckReader& r, const Check&) { return r.matrix.spp.back(); }),
            requiredKey<std::vector<std::string>>(
                "order", param(&Ordering::order),
                [](const CheckReader& r, const yaml::Node& n, const Check&) {
                    return readPatternList(r, n, "order", ", best first");
                }),
            // An undecided order fails the run unless the matrix says otherwise.
            notSeparatedKey(true),
        },
    .makeParams = makeParams<Ordering>,
    .evaluate = evaluate,
};

} // namespace stipple::validation
