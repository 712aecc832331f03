// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Timing claims that survive a busy machine. A render's cost is measured twice: wall seconds (what a user waits)
// and thread CPU seconds summed over the render's workers (what the cores spent on it; it does not grow when
// other processes take the cores). The two patterns of a claim render back to back within each (spp, seed)
// group, so each seed gives one paired ratio; the claim is judged on the geometric mean of the paired ratios
// with a 95% Student-t interval on the log scale: PASS when the whole interval is ≤ the bound, FAIL when it is
// all above, NOT SEPARATED when it straddles the bound. Stated as an equivalence (a margin [lo, hi]), the claim
// "costs the same within the margin" can be decided both ways: the 90% interval inside the margin passes.
#pragma once

#include <string>
#include <vector>

#include "claims/checks.h" // CheckStatus
#include "run/results.h"

namespace stipple::validation {

enum class TimeBasis { Cpu, Wall };

struct PairedRatio {
    double ratio = 0;      // geometric mean of the paired ratios numerator / denominator
    double lo = 0, hi = 0; // its 95% interval (exp of the t interval of the mean log ratio)
    double lo90 = 0, hi90 = 0; // its 90% interval (equivalence: two one-sided tests at 5%)
    size_t pairs = 0;
};

// spp for "every spp of the matrix": each (seed, spp) group gives its own pair.
constexpr uint32_t kAllSpp = 0;

// Pairs the rows of one seed at `spp` (kAllSpp: of one seed at each spp); NaN interval bounds with fewer than two
// pairs. Rows without a positive time on the chosen basis are left out.
PairedRatio pairedTimeRatio(const std::vector<ResultRow>& rows, const std::string& scene, const std::string& numerator,
                            const std::string& denominator, uint32_t spp, TimeBasis basis);

// PASS: hi ≤ bound; FAIL: lo > bound; NOT SEPARATED otherwise (or when the interval is undefined).
CheckStatus ratioVerdict(const PairedRatio& r, double bound);
// Equivalence within [lo, hi] (Schuirmann's two one-sided tests): PASS when the 90% interval lies inside the
// margin; FAIL when the 95% interval lies wholly outside it; NOT SEPARATED otherwise.
CheckStatus equivalenceVerdict(const PairedRatio& r, double lo, double hi);

} // namespace stipple::validation
