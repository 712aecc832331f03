// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The time_ceiling check: no render of a named scene (any cell, any seed) took longer than a number of wall seconds.
#include "matrix/check_kind.h"
#include "claims/checks.h"
#include "base/text.h"

namespace stipple::validation {

namespace {

struct TimeCeiling : CheckParams {
    double seconds = 0;
};

void evaluate(const Check& check, const CheckInputs& in, CheckOutcome& o) {
    const TimeCeiling& k = paramsOf<TimeCeiling>(check);
    o.claim = fmt("time_ceiling %s: render seconds of every cell × seed ≤ %.3g", check.scene.c_str(), k.seconds);
    for (const MatrixScene* scene : scenesOf(check, in.matrix)) {
        const ResultRow* worst = nullptr;
        for (const auto& r : in.rows)
            if (r.scene == scene->name && (!worst || r.renderSeconds > worst->renderSeconds)) worst = &r;
        if (!worst) {
            o.status = CheckStatus::Fail;
            o.figures.push_back(fmt("%s: no cells", scene->name.c_str()));
            continue;
        }
        bool ok = worst->renderSeconds <= k.seconds;
        if (!ok) o.status = CheckStatus::Fail;
        o.figures.push_back(fmt("%s: slowest %s @ %u spp seed %llu: %.4fs%s", scene->name.c_str(),
                                worst->pattern.c_str(), worst->spp, (unsigned long long)worst->seed,
                                worst->renderSeconds, ok ? "" : "   <-- FAIL"));
    }
}

} // namespace

extern const CheckKind kTimeCeilingCheck;
const CheckKind kTimeCeilingCheck{
    .name = "time_ceiling",
    .keys =
        {
            sceneKey(false),
            requiredKey<double>(
                "seconds", param(&TimeCeiling::seconds),
                [](const CheckReader& r, const yaml::Node& n, const Check&) { return readPositive(r, n, "seconds"); }),
        },
    .makeParams = makeParams<TimeCeiling>,
    .evaluate = evaluate,
};

} // namespace stipple::validation
