// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The statistics the project's tests decide with besides common/'s Student's t and Welch's test
// (<stipple/statistics/student_t.h>, included here): Pearson's chi-square with pooling of sparse cells and Sidak's
// per-test level. Distributions come from Boost.Math.
#pragma once

#include <stipple/statistics/student_t.h>

#include <vector>

namespace stipple::testing {

struct ChiSquareResult {
    double statistic = 0;
    int degreesOfFreedom = 0;
    double pValue = 1;
};

// Pearson's chi-square of observed counts against expected counts. Pooling rule (as Mitsuba 3's chi2 test and
// pbrt-v4's bsdfs test): cells expecting fewer than 5 counts are merged, smallest expectation first, until each
// pool expects at least 5; a leftover pool that still expects fewer is scored against max(its expectation, 5), so
// many samples where (almost) none are expected still fail.
ChiSquareResult chiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected);

// The per-test level that keeps the family-wise level `alpha` over `tests` independent tests.
double sidak(double alpha, int tests);
// The two-sided critical |z| of a standard normal at Sidak's per-test level.
double sidakZ(double alpha, int tests);

} // namespace stipple::testing
