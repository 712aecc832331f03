// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Regression against a stored run (--baseline results.json): error beyond the two runs' intervals or
// time beyond a budget factor fails.
#pragma once

#include <string>
#include <vector>

#include "run/results.h"

namespace stipple::validation {

struct BaselineComparison {
    bool failed = false;
    size_t compared = 0, missing = 0;
    std::vector<std::string> lines; // one per cell that regressed, improved or is missing
};

// RMS: a cell regresses when its mean exceeds the baseline's by more than sqrt(h_now² + h_base²), h the
// 95% half-widths (the intervals' combined tolerance). Time: when its median render seconds exceed
// timeFactor × the baseline's + 5 ms (the slack keeps millisecond cells from failing on scheduler noise).
BaselineComparison compareToBaseline(const std::vector<CellAggregate>& now, const std::vector<CellAggregate>& base,
                                     double timeFactor);

} // namespace stipple::validation
