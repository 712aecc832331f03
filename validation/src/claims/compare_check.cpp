// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The compare check: pattern A against pattern B (more than two: every pair, in list order) per scene and region,
// per sample or at equal CPU time, on the relative squared error or mean FLIP (comparison_claims.h), judged
// EQUIVALENT / BETTER / WORSE / NOT SEPARATED and then against what the check expects.
#include "matrix/check_kind.h"
#include "claims/checks.h"
#include "claims/comparison_claims.h"
#include "metrics/image_metrics.h"
#include "base/text.h"

namespace stipple::validation {

namespace {

struct Compare : CheckParams {
    std::string region; // empty: the whole image and every region; "image": the whole image only
    std::vector<std::string> patterns;
    bool equalTime = false; // basis: time
    bool flip = false;      // metric: flip
    Expectation expect = Expectation::Any;
    std::pair<double, double> margin = {0.8, 1.25};
    uint32_t spp = 0;
};

void evaluate(const Check& check, const CheckInputs& in, CheckOutcome& o) {
    const Compare& k = paramsOf<Compare>(check);
    const auto& rows = in.rows;
    std::string pairs;
    for (size_t i = 0; i < k.patterns.size(); ++i)
        pairs += (i ? (k.patterns.size() == 2 ? " vs " : ", ") : "") + k.patterns[i];
    const Margin margin{k.margin.first, k.margin.second};
    o.claim = fmt("compare %s%s @ %u spp: %s, %s %s, expect %s (margin %.2f-%.2f; 90%% inside: EQUIVALENT, 95%% "
                  "excludes 1: BETTER/WORSE)%s",
                  check.scene.c_str(), k.region.empty() ? "" : (" region " + k.region).c_str(), k.spp, pairs.c_str(),
                  k.flip ? "mean FLIP"
                         : fmt("relative squared error Σ_rgb e² / (reference + image mean)², capped at 3·%g², "
                               "noisy blocks divided by their noise over the median's",
                               kRelativeErrorCap)
                               .c_str(),
                  k.equalTime ? "× CPU s (equal time)" : "per sample", expectationName(k.expect), margin.lo, margin.hi,
                  check.study.empty() ? "" : ("; study: " + check.study).c_str());
    bool any = false;
    for (const MatrixScene* sp : scenesOf(check, in.matrix)) {
        const MatrixScene& s = *sp;
        any = true;
        for (int ri = -1; ri < int(s.regions.size()); ++ri) {
            if (ri < 0 && !k.region.empty() && k.region != "image") continue;
            if (ri >= 0 && (k.region == "image" || (!k.region.empty() && k.region != s.regions[size_t(ri)].name)))
                continue;
            for (size_t i = 0; i < k.patterns.size(); ++i)
                for (size_t j = i + 1; j < k.patterns.size(); ++j) {
                    VerdictRow v;
                    v.scene = s.name;
                    v.region = ri < 0 ? "" : s.regions[size_t(ri)].name;
                    v.a = k.patterns[i];
                    v.b = k.patterns[j];
                    v.spp = k.spp;
                    v.equalTime = k.equalTime;
                    v.flip = k.flip;
                    v.comparison = comparePatterns(rows, s, v.a, v.b, k.spp, ri, k.flip, k.equalTime, margin);
                    v.status = statusFor(k.expect, v.comparison);
                    v.decidedAs = decidingVerdict(k.expect, v.comparison);
                    // The plain MSE ratio beside, labelled and without a verdict word: what the weights and the cap
                    // changed. Only the main figure decides; a second word on the same line read as a second verdict.
                    std::string plainText;
                    if (!k.flip) {
                        const Comparison plain =
                            comparePatterns(rows, s, v.a, v.b, k.spp, ri, false, k.equalTime, margin, false);
                        plainText = fmt("; the study's plain MSE%s, not the verdict's error: %s",
                                        k.equalTime ? " × CPU s" : "", ratioText(plain).c_str());
                    }
                    worsen(o.status, v.status);
                    o.figures.push_back(fmt(
                        "%s %s: %s/%s %s %s (dof %.0f)%s%s", s.name.c_str(),
                        v.region.empty() ? "whole image" : v.region.c_str(), v.a.c_str(), v.b.c_str(),
                        ratioText(v.comparison).c_str(), verdictName(v.comparison.verdict), v.comparison.dof,
                        plainText.c_str(),
                        v.status == CheckStatus::Pass ? "" : fmt("   <-- %s", checkStatusName(v.status)).c_str()));
                    o.verdicts.push_back(v);
                }
        }
    }
    if (!any) {
        o.status = CheckStatus::Fail;
        o.figures.push_back("no scene matches");
    }
}

// A compare check's verdicts for the sentence: the whole image's where it has them, else its regions'.
std::vector<const VerdictRow*> sentenceVerdicts(const CheckOutcome& o, const std::string& a, const std::string& b) {
    std::vector<const VerdictRow*> whole, any;
    for (const auto& v : o.verdicts) {
        if (v.a != a || v.b != b) continue;
        any.push_back(&v);
        if (v.region.empty()) whole.push_back(&v);
    }
    return whole.empty() ? any : whole;
}

// One clause per compared pair: "the study's Poisson disk (poisson-seed) per sample is as good as …".
std::string sentence(const CheckOutcome& o, const SentenceWords& w) {
    const Compare& k = paramsOf<Compare>(o.check);
    const char* basis = k.flip ? "by mean FLIP" : k.equalTime ? "at equal CPU time" : "per sample";
    std::string s;
    for (size_t i = 0; i < k.patterns.size(); ++i)
        for (size_t j = i + 1; j < k.patterns.size(); ++j) {
            const auto vs = sentenceVerdicts(o, k.patterns[i], k.patterns[j]);
            if (vs.empty()) continue;
            s += (s.empty() ? "" : "; ") + w.patternLabel(k.patterns[i]) + " " + basis + " is " +
                 w.verdicts(vs, k.patterns[j], !o.check.study.empty());
        }
    return s;
}

// "image", or (scene: all) a region every scene has, or a region of the one scene named: one claim for a region the
// scenes share.
std::string readRegion(const CheckReader& r, const yaml::Node& n, const Check& c) {
    const std::string region = r.yaml.get<std::string>(n, "region");
    std::vector<std::string> lacking;
    for (const MatrixScene* s : scenesOf(c, r.matrix)) {
        bool has = false;
        for (const auto& rg : s->regions) has |= rg.name == region;
        if (!has) lacking.push_back(s->name);
    }
    if (region != "image" && !lacking.empty())
        r.fail(n, c.scene == "all" ? "region '" + region + "' is not a region of every scene (" + joined(lacking) +
                                         " lack it); 'image' or a region all have"
                                   : "region must be 'image' or a region of the one scene named, got '" + region + "'");
    return region;
}

void validate(const CheckReader& r, const yaml::Node& c, Check& check) {
    const Compare& k = paramsOf<Compare>(check);
    if (k.flip && k.equalTime) r.fail(c["metric"], "metric flip is compared at equal samples only (basis: samples)");
}

} // namespace

extern const CheckKind kCompareCheck;
const CheckKind kCompareCheck{
    .name = "compare",
    .keys =
        {
            sceneKey(false),
            optionalKey<std::string>("region", param(&Compare::region), readRegion),
            requiredKey<std::vector<std::string>>("patterns", param(&Compare::patterns),
                                                  [](const CheckReader& r, const yaml::Node& n, const Check&) {
                                                      return readPatternList(r, n, "patterns", " (A, B, ...)");
                                                  }),
            choiceKey<bool>("basis", param(&Compare::equalTime), {{"samples", false}, {"time", true}}),
            metricKey(&Compare::flip),
            choiceKey<Expectation>("expect", param(&Compare::expect),
                                   {{"any", Expectation::Any},
                                    {"equivalent", Expectation::Equivalent},
                                    {"better", Expectation::Better},
                                    {"worse", Expectation::Worse}}),
            optionalKey<std::pair<double, double>>("margin", param(&Compare::margin), readMargin),
            sppKey(&Compare::spp),
            studyKey(),
            failsRunKey(),
            notSeparatedKey(false),
        },
    .makeParams = makeParams<Compare>,
    .validate = validate,
    .evaluate = evaluate,
    .sentence = sentence,
};

} // namespace stipple::validation
