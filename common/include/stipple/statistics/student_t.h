// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Student's t distribution and Welch's unequal-variance comparison of two means (Welch-Satterthwaite degrees of
// freedom): the one implementation validation's intervals and the tests' decisions share.
#pragma once

namespace stipple::statistics {

// The p-quantile of Student's t with `degreesOfFreedom` (e.g. p = 0.975 for a two-sided 95 % interval).
// Throws std::invalid_argument unless degreesOfFreedom > 0 and 0 < p < 1.
double studentTQuantile(double p, double degreesOfFreedom);
// The two-sided critical |t| at level `alpha`: the (1 - alpha/2)-quantile, computed from the upper tail so that
// tiny levels (Sidak-corrected families) keep their precision.
double studentTCritical(double alpha, double degreesOfFreedom);
// The two-sided p-value of a t statistic.
double studentTTwoSidedP(double t, double degreesOfFreedom);

// One side of a Welch comparison: a mean, the variance of that mean (the sample variance over the count) and the
// number of independent values it was estimated from.
struct MeanEstimate {
    double mean = 0;
    double varianceOfMean = 0;
    double count = 0;
};

// mean(a) - mean(b), its standard error and its Welch-Satterthwaite degrees of freedom. When both variances are
// zero the standard error is zero and the degrees of freedom are the pooled count a.count + b.count - 2.
struct WelchDifference {
    double difference = 0;
    double standardError = 0;
    double degreesOfFreedom = 0;
};
WelchDifference welchDifference(const MeanEstimate& a, const MeanEstimate& b);
// The two-sided p-value of Welch's test that the two means are equal; 1 when both are noise-free and equal, 0 when
// noise-free and different.
double welchTwoSidedP(const MeanEstimate& a, const MeanEstimate& b);

} // namespace stipple::statistics
