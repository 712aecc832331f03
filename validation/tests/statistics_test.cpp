// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Known answers for the statistics behind every interval and slope in the report.
#define BOOST_TEST_MODULE validation_statistics
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "metrics/statistics.h"

using namespace stipple::validation;

BOOST_AUTO_TEST_CASE(t_quantiles_match_tables) {
    // Two-sided 95%: t_{0.975} for 1, 3 and 30 dof (standard tables).
    BOOST_CHECK_CLOSE(studentTQuantile(0.975, 1), 12.7062047, 1e-4);
    BOOST_CHECK_CLOSE(studentTQuantile(0.975, 3), 3.18244631, 1e-4);
    BOOST_CHECK_CLOSE(studentTQuantile(0.975, 30), 2.04227246, 1e-4);
    BOOST_CHECK_THROW(studentTQuantile(0.975, 0), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(mean_interval_of_four_values) {
    // {1,2,3,4}: mean 2.5, s = sqrt(5/3), half width = t_{0.975,3} s / 2.
    Interval i = meanInterval({1, 2, 3, 4});
    BOOST_CHECK_CLOSE(i.mean, 2.5, 1e-12);
    BOOST_CHECK_CLOSE(i.halfWidth, 3.18244631 * std::sqrt(5.0 / 3.0) / 2.0, 1e-4);
    BOOST_CHECK_EQUAL(i.count, 4u);
    BOOST_CHECK(std::isnan(meanInterval({1.0}).halfWidth));
}

BOOST_AUTO_TEST_CASE(separation_needs_disjoint_intervals) {
    Interval a{1.0, 0.1, 4}, b{1.3, 0.1, 4}, c{1.15, 0.1, 4};
    BOOST_CHECK(separatedBelow(a, b));
    BOOST_CHECK(!separatedBelow(b, a));
    BOOST_CHECK(!separatedBelow(a, c)); // overlap: neither order is established
    BOOST_CHECK(!separatedBelow(c, a));
}

BOOST_AUTO_TEST_CASE(welch_interval_known_answer) {
    // a = {1, 2, 3, 4}: mean 2.5, variance 5/3; b = {2, 4, 6, 8}: mean 5, variance 20/3. Standard errors squared
    // 5/12 and 5/3; Welch-Satterthwaite dof = (25/12)^2 / ((5/12)^2 / 3 + (5/3)^2 / 3) = 4.41176...
    const SampleSummary a = summarize({1, 2, 3, 4}), b = summarize({2, 4, 6, 8});
    BOOST_CHECK_CLOSE(a.variance, 5.0 / 3.0, 1e-12);
    const Interval d = welchDifference(a, b);
    BOOST_CHECK_CLOSE(d.mean, -2.5, 1e-12);
    const double dof = (625.0 / 144.0) / ((25.0 / 144.0 + 25.0 / 9.0) / 3.0);
    BOOST_CHECK_CLOSE(dof, 4.4117647, 1e-5);
    BOOST_CHECK_CLOSE(d.halfWidth, studentTQuantile(0.975, dof) * std::sqrt(25.0 / 12.0), 1e-9);
    BOOST_CHECK(d.lo() < 0 && d.hi() > 0); // 2.5 apart, but the samples are too spread to tell at 95%
    BOOST_CHECK(std::isnan(welchDifference(summarize({1}), b).halfWidth));
    BOOST_CHECK_EQUAL(welchDifference(summarize({1, 1}), summarize({2, 2})).halfWidth, 0.0);
}

BOOST_AUTO_TEST_CASE(median_even_and_odd) {
    BOOST_CHECK_EQUAL(median({3, 1, 2}), 2.0);
    BOOST_CHECK_EQUAL(median({4, 1, 3, 2}), 2.5);
}

BOOST_AUTO_TEST_CASE(slope_of_an_exact_power_law) {
    // RMS = 2 spp^-0.5 exactly: slope −0.5, zero residual, zero half width.
    std::vector<double> x, y;
    for (double spp : {4.0, 16.0, 64.0, 256.0}) {
        x.push_back(std::log(spp));
        y.push_back(std::log(2.0 * std::pow(spp, -0.5)));
    }
    LineFit f = fitLine(x, y);
    BOOST_CHECK_CLOSE(f.slope, -0.5, 1e-9);
    BOOST_CHECK_CLOSE(f.intercept, std::log(2.0), 1e-9);
    BOOST_CHECK_SMALL(f.slopeHalfWidth, 1e-9);
}

BOOST_AUTO_TEST_CASE(slope_interval_known_answer) {
    // Worked by hand: slope 0.425, intercept 0.785, standard error 0.305, t_{0.975,3} × se = 0.97065.
    LineFit f = fitLine({1, 2, 3, 4, 5}, {1, 2, 1.3, 3.75, 2.25});
    BOOST_CHECK_CLOSE(f.slope, 0.425, 1e-9);
    BOOST_CHECK_CLOSE(f.intercept, 0.785, 1e-9);
    BOOST_CHECK_CLOSE(f.slopeHalfWidth, 0.9706461, 1e-4);
    BOOST_CHECK(std::isnan(fitLine({1, 1, 1}, {1, 2, 3}).slope)); // x does not vary
    BOOST_CHECK_THROW(fitLine({1, 2}, {1}), std::invalid_argument);
}
