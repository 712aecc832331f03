// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include <stipple/testing/statistics.h>

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace stipple::testing {

ChiSquareResult chiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected) {
    if (observed.size() != expected.size())
        throw std::invalid_argument("chiSquareTest: observed and expected differ in length");
    std::vector<size_t> order(observed.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return expected[a] < expected[b]; });
    ChiSquareResult r;
    double pooledObserved = 0, pooledExpected = 0;
    int cells = 0;
    for (size_t i : order) {
        if (expected[i] < 5.0 || pooledExpected > 0.0) {
            pooledObserved += observed[i];
            pooledExpected += expected[i];
            if (pooledExpected < 5.0) continue;
            r.statistic += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
            pooledObserved = pooledExpected = 0;
        } else {
            r.statistic += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
        }
        ++cells;
    }
    if (pooledExpected > 0.0 || pooledObserved > 0.0) {
        const double e = std::max(pooledExpected, 5.0);
        r.statistic += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / e;
        ++cells;
    }
    r.degreesOfFreedom = std::max(cells - 1, 1);
    r.pValue = boost::math::cdf(boost::math::complement(boost::math::chi_squared(r.degreesOfFreedom), r.statistic));
    return r;
}

double sidak(double alpha, int tests) { return 1.0 - std::pow(1.0 - alpha, 1.0 / tests); }

double sidakZ(double alpha, int tests) {
    return boost::math::quantile(boost::math::complement(boost::math::normal(), sidak(alpha, tests) / 2));
}

} // namespace stipple::testing
