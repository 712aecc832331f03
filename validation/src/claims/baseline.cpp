// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "claims/baseline.h"

#include <cmath>
#include <cstdio>

namespace stipple::validation {

BaselineComparison compareToBaseline(const std::vector<CellAggregate>& now, const std::vector<CellAggregate>& base,
                                     double timeFactor) {
    BaselineComparison out;
    char buf[512];
    for (const auto& b : base) {
        const CellAggregate* c = findCell(now, b.scene, b.pattern, b.spp);
        if (!c) {
            ++out.missing;
            continue;
        }
        ++out.compared;
        // A cell without a finite error (now or in the baseline) is never within tolerance.
        if (c->unmeasuredSeeds || b.unmeasuredSeeds || !std::isfinite(c->rms.mean) || !std::isfinite(b.rms.mean)) {
            out.failed = true;
            std::snprintf(buf, sizeof buf, "FAIL rms  %s %s @ %u spp: no finite error %s", b.scene.c_str(),
                          b.pattern.c_str(), b.spp,
                          c->unmeasuredSeeds || !std::isfinite(c->rms.mean) ? "now" : "in the baseline");
            out.lines.push_back(buf);
            continue;
        }
        double hNow = std::isfinite(c->rms.halfWidth) ? c->rms.halfWidth : 0;
        double hBase = std::isfinite(b.rms.halfWidth) ? b.rms.halfWidth : 0;
        double tolerance = std::sqrt(hNow * hNow + hBase * hBase);
        double delta = c->rms.mean - b.rms.mean;
        if (delta > tolerance) {
            out.failed = true;
            std::snprintf(buf, sizeof buf,
                          "FAIL rms  %s %s @ %u spp: %.5g ± %.2g now vs %.5g ± %.2g baseline (+%.3g > tolerance %.3g)",
                          b.scene.c_str(), b.pattern.c_str(), b.spp, c->rms.mean, hNow, b.rms.mean, hBase, delta,
                          tolerance);
            out.lines.push_back(buf);
        } else if (-delta > tolerance) {
            std::snprintf(buf, sizeof buf, "better    %s %s @ %u spp: %.5g now vs %.5g baseline", b.scene.c_str(),
                          b.pattern.c_str(), b.spp, c->rms.mean, b.rms.mean);
            out.lines.push_back(buf);
        }
        double budget = timeFactor * b.medianRenderSeconds + 0.005;
        if (c->medianRenderSeconds > budget) {
            out.failed = true;
            std::snprintf(buf, sizeof buf,
                          "FAIL time %s %s @ %u spp: %.4fs now vs %.4fs baseline (budget %.4fs = %.2f× + 5 ms)",
                          b.scene.c_str(), b.pattern.c_str(), b.spp, c->medianRenderSeconds, b.medianRenderSeconds,
                          budget, timeFactor);
            out.lines.push_back(buf);
        }
    }
    if (out.missing) {
        std::snprintf(buf, sizeof buf, "%zu baseline cells are not in this run (not compared)", out.missing);
        out.lines.push_back(buf);
    }
    return out;
}

} // namespace stipple::validation
