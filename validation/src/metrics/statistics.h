// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Small statistics used by the validation report: means, Student-t intervals, medians and the
// least-squares slope of log RMS against log spp with its interval. Student's t and Welch's degrees of freedom
// come from statistics/ (<stipple/statistics/student_t.h>).
#pragma once

#include <stipple/statistics/student_t.h>

#include <cstddef>
#include <vector>

namespace stipple::validation {

// Two-sided interval of a mean: mean ± halfWidth. halfWidth is NaN with fewer than 2 values.
struct Interval {
    double mean = 0;
    double halfWidth = 0;
    size_t count = 0;
    double lo() const { return mean - halfWidth; }
    double hi() const { return mean + halfWidth; }
};

double mean(const std::vector<double>& values);
// Unbiased sample variance (n - 1 in the denominator); 0 for fewer than two values.
double sampleVariance(const std::vector<double>& values);
double median(std::vector<double> values);

// Quantile of Student's t (statistics/: the project's one Student-t and Welch).
using statistics::studentTQuantile;

// Mean with the t-distribution interval at the given confidence (0.95: two-sided 95%).
Interval meanInterval(const std::vector<double>& values, double confidence = 0.95);

// A sample's mean, unbiased variance and size.
struct SampleSummary {
    double mean = 0;
    double variance = 0;
    size_t count = 0;
};
SampleSummary summarize(const std::vector<double>& values);

// Welch's interval for mean(a) - mean(b): unequal variances, Welch-Satterthwaite degrees of freedom.
// halfWidth is NaN when either sample has fewer than two values.
Interval welchDifference(const SampleSummary& a, const SampleSummary& b, double confidence = 0.95);

// Least-squares line y = intercept + slope x, with a t interval on the slope (n - 2 dof).
struct LineFit {
    double slope = 0;
    double intercept = 0;
    double slopeHalfWidth = 0; // NaN when n < 3 or the x values do not vary
    size_t count = 0;
};
LineFit fitLine(const std::vector<double>& x, const std::vector<double>& y, double confidence = 0.95);

// True when the two intervals do not overlap: a < b is established only when a.hi() < b.lo().
inline bool separatedBelow(const Interval& a, const Interval& b) { return a.hi() < b.lo(); }

} // namespace stipple::validation
