// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The reference's noise floor recovered from a run's rows, which the efficiency rankings (equal_efficiency_check.cpp)
// and the comparisons (comparison_claims.h) subtract.
#pragma once

#include <vector>

#include "run/results.h"

namespace stipple::validation {

// The reference's noise floor of a scene (region < 0) or of its region'th region, recovered from its rows:
// mse − mse_corrected of a row whose correction was not clamped at 0.
double floorFromRows(const std::vector<ResultRow>& rows, const std::string& scene, int region = -1);

} // namespace stipple::validation
