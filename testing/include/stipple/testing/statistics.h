// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The statistics the project's tests decide with: Pearson's chi-square with pooling of sparse cells, Sidak's
// per-test level, Student's and Welch's t-tests (in the words the tests use; Student's t and Welch's degrees of
// freedom are statistics/'s, <stipple/statistics/student_t.h>). Distributions come from Boost.Math.
#pragma once

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

// The two-sided critical |t| of Student's t with `degreesOfFreedom` at level `alpha`.
double studentCritical(double alpha, double degreesOfFreedom);
// Two-sided p-value of Student's t statistic with `degreesOfFreedom`.
double studentTwoSidedP(double t, double degreesOfFreedom);

// An estimate of a mean from k independent runs: its value, the variance of that mean and k.
struct MeanEstimate {
    double mean = 0;
    double varianceOfMean = 0;
    int k = 0;
};
// Two-sided p-value of Welch's t-test that two means are equal (Welch-Satterthwaite degrees of freedom);
// 1 when both are noise-free and equal, 0 when noise-free and different.
double welchPValue(const MeanEstimate& a, const MeanEstimate& b);

} // namespace stipple::testing
