// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The equal_time check: per scene (and per region of the scene), the patterns' equal-time efficiency ranking
// with 95% intervals, the claimed order judged pair by pair (PASS / FAIL / NOT SEPARATED), and the study's own
// conclusion printed beside the measured one.
#pragma once

#include <vector>

#include "checks.h"
#include "results.h"

namespace stipple::validation {

// The reference's noise floor of a scene (region < 0) or of its region'th region, recovered from its rows:
// mse − mse_corrected of a row whose correction was not clamped at 0.
double floorFromRows(const std::vector<ResultRow>& rows, const std::string& scene, int region = -1);

void evaluateEqualTime(const Check& check, const Matrix& matrix, const std::vector<ResultRow>& rows,
                       CheckOutcome& outcome);

} // namespace stipple::validation
