// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "claims/efficiency_claims.h"
#include "base/text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "claims/efficiency.h"

namespace stipple::validation {

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

} // namespace stipple::validation
