// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "checks.h"
#include "text.h"

#include "comparison_claims.h"
#include "efficiency_claims.h"
#include "timing.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace stipple::validation {

const char* checkStatusName(CheckStatus status) {
    switch (status) {
    case CheckStatus::Pass: return "PASS";
    case CheckStatus::Fail: return "FAIL";
    case CheckStatus::NotSeparated: return "NOT SEPARATED";
    }
    return "?";
}

namespace {


std::vector<std::string> scenesOf(const Check& c, const Matrix& m) {
    std::vector<std::string> names;
    for (const auto& s : m.scenes)
        if (c.scene == "all" || c.scene == s.name) names.push_back(s.name);
    return names;
}

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

void ordering(const Check& k, const Matrix& m, const std::vector<CellAggregate>& cells, CheckOutcome& o) {
    std::string chain;
    for (const auto& p : k.order) chain += (chain.empty() ? "" : " < ") + p;
    o.claim = fmt("ordering %s spp ≥ %u: RMS %s (Welch 95%% on log RMS: geometric-mean ratio < 1)", k.scene.c_str(),
                  k.sppMin, chain.c_str());
    for (const auto& scene : scenesOf(k, m))
        for (uint32_t spp : m.spp) {
            if (spp < k.sppMin) continue;
            std::string line = fmt("%s @ %u spp: ", scene.c_str(), spp);
            CheckStatus cellStatus = CheckStatus::Pass;
            for (size_t i = 0; i + 1 < k.order.size(); ++i) {
                const CellAggregate* a = findCell(cells, scene, k.order[i], spp);
                const CellAggregate* b = findCell(cells, scene, k.order[i + 1], spp);
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

void slope(const Check& k, const Matrix& m, const std::vector<SlopeFit>& slopes, CheckOutcome& o) {
    o.claim = fmt("slope %s %s: log RMS vs log spp = %.3g ± %.3g", k.scene.c_str(), k.pattern.c_str(), k.expected,
                  k.tolerance);
    for (const auto& scene : scenesOf(k, m)) {
        const SlopeFit* f = nullptr;
        for (const auto& s : slopes)
            if (s.scene == scene && s.pattern == k.pattern) f = &s;
        if (!f || !std::isfinite(f->fit.slope)) {
            o.status = CheckStatus::Fail;
            o.figures.push_back(fmt("%s %s: no fit (too few points with RMS > 0, or a point without a finite error)",
                                    scene.c_str(), k.pattern.c_str()));
            continue;
        }
        bool ok = std::fabs(f->fit.slope - k.expected) <= k.tolerance;
        if (!ok) o.status = CheckStatus::Fail;
        o.figures.push_back(fmt("%s %s: slope %.3f (95%% CI ± %.3f, %zu points%s)%s", scene.c_str(), k.pattern.c_str(),
                                f->fit.slope, f->fit.slopeHalfWidth, f->fit.count,
                                f->excluded ? fmt(", %zu excluded at RMS 0", f->excluded).c_str() : "",
                                ok ? "" : "   <-- FAIL"));
    }
}

void timeCeiling(const Check& k, const Matrix& m, const std::vector<ResultRow>& rows, CheckOutcome& o) {
    o.claim = fmt("time_ceiling %s: render seconds of every cell × seed ≤ %.3g", k.scene.c_str(), k.seconds);
    for (const auto& scene : scenesOf(k, m)) {
        const ResultRow* worst = nullptr;
        for (const auto& r : rows)
            if (r.scene == scene && (!worst || r.renderSeconds > worst->renderSeconds)) worst = &r;
        if (!worst) {
            o.status = CheckStatus::Fail;
            o.figures.push_back(fmt("%s: no cells", scene.c_str()));
            continue;
        }
        bool ok = worst->renderSeconds <= k.seconds;
        if (!ok) o.status = CheckStatus::Fail;
        o.figures.push_back(fmt("%s: slowest %s @ %u spp seed %llu: %.4fs%s", scene.c_str(), worst->pattern.c_str(),
                                worst->spp, (unsigned long long)worst->seed, worst->renderSeconds,
                                ok ? "" : "   <-- FAIL"));
    }
}

} // namespace

std::vector<CheckOutcome> evaluateChecks(const Matrix& matrix, const std::vector<ResultRow>& rows,
                                         const std::vector<CellAggregate>& cells, const std::vector<SlopeFit>& slopes) {
    std::vector<CheckOutcome> out;
    for (const auto& k : matrix.checks) {
        CheckOutcome o;
        o.check = k;
        switch (k.type) {
        case CheckType::Ordering: ordering(k, matrix, cells, o); break;
        case CheckType::Slope: slope(k, matrix, slopes, o); break;
        case CheckType::TimeRatio: evaluateTimeRatio(k, matrix, rows, o); break;
        case CheckType::TimeCeiling: timeCeiling(k, matrix, rows, o); break;
        case CheckType::EqualTime:
        case CheckType::EqualSpp: evaluateEqualTime(k, matrix, rows, o); break;
        case CheckType::Compare: evaluateCompare(k, matrix, rows, o); break;
        }
        o.failsRun = (o.status == CheckStatus::Fail && k.failFails) ||
                     (o.status == CheckStatus::NotSeparated && k.notSeparatedFails);
        out.push_back(o);
    }
    return out;
}

std::string formatOutcome(const CheckOutcome& o) {
    std::string s = fmt("%-13s %s   [%s]", checkStatusName(o.status), o.claim.c_str(), o.check.where.c_str());
    if (o.status != CheckStatus::Pass && !o.failsRun) s += " (does not fail the run)";
    if (o.status == CheckStatus::NotSeparated && o.failsRun) s += " (fails the run)";
    s += "\n";
    for (const auto& f : o.figures) s += "      " + f + "\n";
    return s;
}

const Fields<CheckOutcome>& outcomeFields() {
    using O = CheckOutcome;
    auto text = [](const char* name, std::string (*get)(const O&)) {
        Field<O> f;
        f.name = name;
        f.toJson = [get](const O& o) { return Json(get(o)); };
        f.toCsv = [get](const O& o) { return csvField(get(o)); };
        return f;
    };
    static const Fields<O> fields = {
        text("type", [](const O& o) { return std::string(checkTypeName(o.check.type)); }),
        text("where", [](const O& o) { return o.check.where; }),
        text("status", [](const O& o) { return std::string(checkStatusName(o.status)); }),
        field("fails_run", &O::failsRun),
        text("study", [](const O& o) { return o.check.study; }),
        field("claim", &O::claim),
        {"figures",
         [](const O& o) { return Json(o.figures); },
         {},
         [](const O& o) {
             std::string all;
             for (const auto& f : o.figures) all += (all.empty() ? "" : "; ") + f;
             return csvField(all);
         }},
        {"verdicts", [](const O& o) { return verdictsJson(o.verdicts); }, {}, {}},
    };
    return fields;
}

Json outcomesJson(const std::vector<CheckOutcome>& outcomes) {
    Json a = Json::array();
    for (const auto& o : outcomes) a.push_back(toJson(o, outcomeFields()));
    return a;
}

} // namespace stipple::validation
