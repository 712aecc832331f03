// chi2.h — Pearson's chi-square test with pooling of sparse cells (as Mitsuba 3's chi2 test and pbrt-v4's
// bsdfs_test do): cells expecting fewer than 5 counts are merged, smallest first, before the statistic is taken.
#pragma once

#include <boost/math/distributions/chi_squared.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace stipple::test {

struct ChiSquareResult {
  double statistic = 0;
  int degreesOfFreedom = 0;
  double pValue = 1;
};

inline ChiSquareResult chiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected) {
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
  if (pooledExpected > 0.0) {  // a leftover pool too small on its own: fold it into the statistic's last cell
    r.statistic += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / std::max(pooledExpected, 5.0);
    ++cells;
  }
  r.degreesOfFreedom = std::max(cells - 1, 1);
  r.pValue = boost::math::cdf(boost::math::complement(boost::math::chi_squared(r.degreesOfFreedom), r.statistic));
  return r;
}

// Sidak: the per-test level that keeps the family-wise level alpha over `tests` tests.
inline double sidak(double alpha, int tests) { return 1.0 - std::pow(1.0 - alpha, 1.0 / tests); }

}  // namespace stipple::test
