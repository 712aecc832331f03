// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The time_ratio check: one pattern's render cost over another's, in thread CPU seconds paired seed by seed
// (timing.h), at most a bound (max) or equal within a margin (two one-sided tests), with the wall-clock ratio
// beside. spp: all pairs every spp's cells of a seed, for more pairs than the seeds alone give.
#include "matrix/check_kind.h"
#include "claims/checks.h"
#include "base/text.h"
#include "claims/timing.h"

#include <optional>

namespace stipple::validation {

namespace {

struct TimeRatio : CheckParams {
    std::string numerator, denominator;
    std::optional<double> max;                       // a bound: ratio ≤ max
    std::optional<std::pair<double, double>> margin; // or an equivalence: ratio within [lo, hi]
    uint32_t spp = 0;                                // kAllSpp: every spp of the matrix
};

template <class T>
Json spellOptional(const std::optional<T>& v) {
    return v ? Json(*v) : Json(nullptr);
}

std::string ratioText(const PairedRatio& r) {
    return fmt("%.3f (95%% %.3f-%.3f, 90%% %.3f-%.3f, %zu pairs)", r.ratio, r.lo, r.hi, r.lo90, r.hi90, r.pairs);
}

void evaluate(const Check& check, const CheckInputs& in, CheckOutcome& o) {
    const TimeRatio& k = paramsOf<TimeRatio>(check);
    const std::string bound =
        k.margin ? fmt("within [%.3g, %.3g] (90%% interval inside: EQUIVALENT)", k.margin->first, k.margin->second)
                 : fmt("≤ %.3g", *k.max);
    auto verdict = [&](const PairedRatio& r) {
        return k.margin ? equivalenceVerdict(r, k.margin->first, k.margin->second) : ratioVerdict(r, *k.max);
    };
    const std::string at = k.spp == kAllSpp ? std::string("every spp") : fmt("%u spp", k.spp);
    o.claim = fmt("time_ratio %s @ %s: %s / %s %s in thread CPU seconds (geometric mean of paired "
                  "per-seed ratios, t intervals; wall seconds beside)",
                  check.scene.c_str(), at.c_str(), k.numerator.c_str(), k.denominator.c_str(), bound.c_str());
    bool any = false;
    for (const MatrixScene* s : scenesOf(check, in.matrix)) {
        any = true;
        const PairedRatio cpu = pairedTimeRatio(in.rows, s->name, k.numerator, k.denominator, k.spp, TimeBasis::Cpu);
        const PairedRatio wall = pairedTimeRatio(in.rows, s->name, k.numerator, k.denominator, k.spp, TimeBasis::Wall);
        if (cpu.pairs == 0) {
            o.status = CheckStatus::Fail;
            o.figures.push_back(fmt("%s: cells missing (no paired rows with CPU seconds)", s->name.c_str()));
            continue;
        }
        const CheckStatus v = verdict(cpu);
        worsen(o.status, v);
        o.figures.push_back(fmt("%s: CPU ratio %s; wall ratio %s [wall alone: %s]%s", s->name.c_str(),
                                ratioText(cpu).c_str(), ratioText(wall).c_str(), checkStatusName(verdict(wall)),
                                v == CheckStatus::Pass ? "" : fmt("   <-- %s", checkStatusName(v)).c_str()));
    }
    if (!any) {
        o.status = CheckStatus::Fail;
        o.figures.push_back("no scene matches");
    }
}

// A bound (≤ max) or an equivalence (within [lo, hi], two one-sided tests), not both.
void validate(const CheckReader& r, const yaml::Node& c, Check& check) {
    const TimeRatio& k = paramsOf<TimeRatio>(check);
    if (k.margin && k.max) r.fail(c["margin"], "a time_ratio check takes max or margin, not both");
    if (!k.margin && !k.max) r.fail(c, "a time_ratio check needs 'max'");
}

} // namespace

extern const CheckKind kTimeRatioCheck;
const CheckKind kTimeRatioCheck{
    .name = "time_ratio",
    .keys =
        {
            sceneKey(false),
            requiredKey<std::string>(
                "numerator", param(&TimeRatio::numerator),
                [](const CheckReader& r, const yaml::Node& n, const Check&) { return r.pattern(n); }),
            requiredKey<std::string>("denominator", param(&TimeRatio::denominator),
                                     [](const CheckReader& r, const yaml::Node& n, const Check& c) {
                                         const std::string p = r.pattern(n);
                                         if (p == paramsOf<TimeRatio>(c).numerator)
                                             r.fail(n, "numerator and denominator are the same pattern '" + p + "'");
                                         return p;
                                     }),
            optionalKey<std::optional<double>>(
                "max", param(&TimeRatio::max),
                [](const CheckReader& r, const yaml::Node& n, const Check&) {
                    return std::optional<double>(readPositive(r, n, "max"));
                },
                {}, spellOptional<double>),
            optionalKey<std::optional<std::pair<double, double>>>(
                "margin", param(&TimeRatio::margin),
                [](const CheckReader& r, const yaml::Node& n, const Check& c) {
                    return std::optional<std::pair<double, double>>(readMargin(r, n, c));
                },
                {}, spellOptional<std::pair<double, double>>),
            // spp: one of the matrix's, or all (each seed's cells paired at every spp); absent: the largest.
            optionalKey<uint32_t>(
                "spp", param(&TimeRatio::spp),
                [](const CheckReader& r, const yaml::Node& n, const Check&) {
                    if (n.IsScalar() && n.ScalarView() == "all") return kAllSpp;
                    const std::string_view text = n.ScalarView();
                    if (text.empty() || text.find_first_not_of("0123456789") != std::string_view::npos)
                        r.fail(n, "spp must be one of the matrix's spp or all, got '" + std::string(text) + "'");
                    return r.spp(n, "spp");
                },
                [](const CheckReader& r, const Check&) { return r.matrix.spp.back(); },
                [](const uint32_t& spp) { return spp == kAllSpp ? Json("all") : Json(spp); }),
            // An interval straddling the bound says the run could not tell, not that the claim is false.
            notSeparatedKey(false),
        },
    .makeParams = makeParams<TimeRatio>,
    .validate = validate,
    .evaluate = evaluate,
};

} // namespace stipple::validation
