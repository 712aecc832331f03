// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include <stipple/statistics/student_t.h>

#include <boost/math/distributions/students_t.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace stipple::statistics {

namespace {

boost::math::students_t studentT(double degreesOfFreedom, const char* caller) {
    if (!(degreesOfFreedom > 0))
        throw std::invalid_argument(std::string(caller) + ": degrees of freedom must be > 0, got " +
                                    std::to_string(degreesOfFreedom));
    return boost::math::students_t(degreesOfFreedom);
}

} // namespace

double studentTQuantile(double p, double degreesOfFreedom) {
    if (!(p > 0 && p < 1)) throw std::invalid_argument("studentTQuantile: p must lie in (0, 1), got " + std::to_string(p));
    return boost::math::quantile(studentT(degreesOfFreedom, "studentTQuantile"), p);
}

double studentTCritical(double alpha, double degreesOfFreedom) {
    if (!(alpha > 0 && alpha < 1))
        throw std::invalid_argument("studentTCritical: alpha must lie in (0, 1), got " + std::to_string(alpha));
    return boost::math::quantile(boost::math::complement(studentT(degreesOfFreedom, "studentTCritical"), alpha / 2));
}

double studentTTwoSidedP(double t, double degreesOfFreedom) {
    return 2 * boost::math::cdf(boost::math::complement(studentT(degreesOfFreedom, "studentTTwoSidedP"), std::fabs(t)));
}

WelchDifference welchDifference(const MeanEstimate& a, const MeanEstimate& b) {
    WelchDifference d;
    d.difference = a.mean - b.mean;
    const double variance = a.varianceOfMean + b.varianceOfMean;
    d.standardError = std::sqrt(variance);
    const double denominator = a.varianceOfMean * a.varianceOfMean / (a.count - 1) +
                               b.varianceOfMean * b.varianceOfMean / (b.count - 1);
    d.degreesOfFreedom = denominator > 0 ? variance * variance / denominator : a.count + b.count - 2;
    return d;
}

double welchTwoSidedP(const MeanEstimate& a, const MeanEstimate& b) {
    const WelchDifference d = welchDifference(a, b);
    if (d.standardError == 0) return a.mean == b.mean ? 1.0 : 0.0;
    return studentTTwoSidedP(d.difference / d.standardError, d.degreesOfFreedom);
}

} // namespace stipple::statistics
