// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The slope check: a pattern's convergence rate, the slope of log RMS against log spp (the fit of results.h), equal
// to the expected one within a tolerance, in every named scene.
#include "matrix/check_kind.h"
#include "claims/checks.h"
#include "base/text.h"

#include <cmath>

namespace stipple::validation {

namespace {

struct Slope : CheckParams {
    std::string pattern;
    double expected = 0, tolerance = 0;
};

void evaluate(const Check& check, const CheckInputs& in, CheckOutcome& o) {
    const Slope& k = paramsOf<Slope>(check);
    o.claim = fmt("slope %s %s: log RMS vs log spp = %.3g ± %.3g", check.scene.c_str(), k.pattern.c_str(), k.expected,
                  k.tolerance);
    for (const MatrixScene* scene : scenesOf(check, in.matrix)) {
        const SlopeFit* f = nullptr;
        for (const auto& s : in.slopes)
            if (s.scene == scene->name && s.pattern == k.pattern) f = &s;
        if (!f || !std::isfinite(f->fit.slope)) {
            o.status = CheckStatus::Fail;
            o.figures.push_back(fmt("%s %s: no fit (too few points with RMS > 0, or a point without a finite error)",
                                    scene->name.c_str(), k.pattern.c_str()));
            continue;
        }
        bool ok = std::fabs(f->fit.slope - k.expected) <= k.tolerance;
        if (!ok) o.status = CheckStatus::Fail;
        o.figures.push_back(fmt("%s %s: slope %.3f (95%% CI ± %.3f, %zu points%s)%s", scene->name.c_str(),
                                k.pattern.c_str(), f->fit.slope, f->fit.slopeHalfWidth, f->fit.count,
                                f->excluded ? fmt(", %zu excluded at RMS 0", f->excluded).c_str() : "",
                                ok ? "" : "   <-- FAIL"));
    }
}

} // namespace

extern const CheckKind kSlopeCheck;
const CheckKind kSlopeCheck{
    .name = "slope",
    .keys =
        {
            sceneKey(true),
            requiredKey<std::string>("pattern", param(&Slope::pattern),
                                     [](const CheckReader& r, const yaml::Node& n, const Check&) { return r.pattern(n); }),
            requiredKey<double>(
                "expected", param(&Slope::expected),
                [](const CheckReader& r, const yaml::Node& n, const Check&) { return readNumber(r, n, "expected"); }),
            requiredKey<double>(
                "tolerance", param(&Slope::tolerance),
                [](const CheckReader& r, const yaml::Node& n, const Check&) { return readPositive(r, n, "tolerance"); }),
        },
    .makeParams = makeParams<Slope>,
    .validate =
        [](const CheckReader& r, const yaml::Node& c, Check&) {
            if (r.matrix.spp.size() < 2) r.fail(c, "a slope check needs at least two spp in the matrix");
        },
    .evaluate = evaluate,
};

} // namespace stipple::validation
