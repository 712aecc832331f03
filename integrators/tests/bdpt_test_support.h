// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Statistics for the BDPT tests. The film's per-pixel variance leaves out splats (light tracing, t = 1), so
// BDPT's uncertainty is measured across K independent renders (seeds): each block's mean over its pixels and
// channels is one observation per render, and two integrators are compared per block by Welch's t-test
// (unequal variances, Welch-Satterthwaite degrees of freedom; Jung et al., JCGT 2020).
#pragma once

#include "test_support.h"

#include <stipple/testing/statistics.h>

#include <chrono>
#include <vector>

namespace stipple::render::test {

struct SeedRenders {
    std::vector<RenderResult> renders;
    double seconds = 0; // summed render seconds (no load, no BVH build)
};

inline SeedRenders renderSeeds(const Scene& scene, RenderOptions o, int k, uint64_t firstSeed) {
    SeedRenders out;
    for (int i = 0; i < k; ++i) {
        o.seed = firstSeed + uint64_t(i);
        out.renders.push_back(scene.render(o));
        out.seconds += out.renders.back().renderSeconds;
    }
    return out;
}

// Mean of a block (over its pixels and channels) across renders, and the variance of that mean.
using BlockEstimate = stipple::statistics::MeanEstimate;
using stipple::testing::sidak;
using stipple::statistics::welchTwoSidedP;

inline BlockEstimate blockEstimate(const SeedRenders& s, int x0, int y0, int w, int h) {
    BlockEstimate e;
    e.count = double(s.renders.size());
    std::vector<double> v;
    for (const RenderResult& r : s.renders) {
        double sum = 0;
        for (int y = y0; y < y0 + h; ++y)
            for (int x = x0; x < x0 + w; ++x)
                for (int c = 0; c < 3; ++c) sum += r.image.pixel(x, y)[c];
        v.push_back(sum / (3.0 * w * h));
    }
    for (double x : v) e.mean += x / e.count;
    double ss = 0;
    for (double x : v) ss += (x - e.mean) * (x - e.mean);
    e.varianceOfMean = e.count > 1 ? ss / (e.count - 1) / e.count : 0;
    return e;
}

// Study RMS (its equation 1: channels summed, pixels averaged) of ONE render, estimated from the spread of K unbiased
// renders: the per-pixel sample variance across renders summed over channels, averaged over pixels, square-rooted (bias
// is zero).
inline double rmsFromSpread(const SeedRenders& s) {
    const RenderResult& r0 = s.renders.front();
    const int k = int(s.renders.size());
    double mse = 0;
    for (size_t i = 0; i < r0.image.rgb.size(); ++i) {
        double m = 0;
        for (const RenderResult& r : s.renders) m += r.image.rgb[i] / k;
        double ss = 0;
        for (const RenderResult& r : s.renders) ss += (r.image.rgb[i] - m) * (r.image.rgb[i] - m);
        mse += ss / (k - 1);
    }
    return std::sqrt(mse / (double(r0.image.width) * r0.image.height));
}

} // namespace stipple::render::test
