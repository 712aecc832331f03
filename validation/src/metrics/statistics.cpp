// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "metrics/statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace stipple::validation {

double mean(const std::vector<double>& values) {
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    double sum = 0;
    for (double v : values) sum += v;
    return sum / double(values.size());
}

double sampleVariance(const std::vector<double>& values) {
    if (values.size() < 2) return 0;
    double m = mean(values), sum = 0;
    for (double v : values) sum += (v - m) * (v - m);
    return sum / double(values.size() - 1);
}

double median(std::vector<double> values) {
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::sort(values.begin(), values.end());
    size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

Interval meanInterval(const std::vector<double>& values, double confidence) {
    Interval r;
    r.count = values.size();
    r.mean = mean(values);
    if (values.size() < 2) {
        r.halfWidth = std::numeric_limits<double>::quiet_NaN();
        return r;
    }
    double t = studentTQuantile(0.5 + 0.5 * confidence, double(values.size() - 1));
    r.halfWidth = t * std::sqrt(sampleVariance(values) / double(values.size()));
    return r;
}

SampleSummary summarize(const std::vector<double>& values) {
    return {mean(values), sampleVariance(values), values.size()};
}

Interval welchDifference(const SampleSummary& a, const SampleSummary& b, double confidence) {
    Interval r;
    r.mean = a.mean - b.mean;
    r.count = a.count + b.count;
    if (a.count < 2 || b.count < 2) {
        r.halfWidth = std::numeric_limits<double>::quiet_NaN();
        return r;
    }
    const statistics::WelchDifference welch = statistics::welchDifference(
        {a.mean, a.variance / double(a.count), double(a.count)}, {b.mean, b.variance / double(b.count), double(b.count)});
    if (!(welch.standardError > 0)) { // both samples constant: the difference is exact
        r.halfWidth = 0;
        return r;
    }
    r.halfWidth = studentTQuantile(0.5 + 0.5 * confidence, welch.degreesOfFreedom) * welch.standardError;
    return r;
}

LineFit fitLine(const std::vector<double>& x, const std::vector<double>& y, double confidence) {
    if (x.size() != y.size()) throw std::invalid_argument("fitLine: x and y differ in length");
    LineFit f;
    f.count = x.size();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (x.size() < 2) {
        f.slope = f.intercept = f.slopeHalfWidth = nan;
        return f;
    }
    double mx = mean(x), my = mean(y), sxx = 0, sxy = 0;
    for (size_t i = 0; i < x.size(); ++i) {
        sxx += (x[i] - mx) * (x[i] - mx);
        sxy += (x[i] - mx) * (y[i] - my);
    }
    if (sxx <= 0) {
        f.slope = f.intercept = f.slopeHalfWidth = nan;
        return f;
    }
    f.slope = sxy / sxx;
    f.intercept = my - f.slope * mx;
    if (x.size() < 3) {
        f.slopeHalfWidth = nan;
        return f;
    }
    double rss = 0;
    for (size_t i = 0; i < x.size(); ++i) {
        double r = y[i] - (f.intercept + f.slope * x[i]);
        rss += r * r;
    }
    double dof = double(x.size() - 2);
    double se = std::sqrt(rss / dof / sxx);
    f.slopeHalfWidth = studentTQuantile(0.5 + 0.5 * confidence, dof) * se;
    return f;
}

} // namespace stipple::validation
