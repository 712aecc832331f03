// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// poisson_seed.cpp — the study's Algorithm 1 (dart throwing with a shrinking radius), kept faithfully as
// the baseline every Poisson claim is measured against.
//
//   r <- r0;  failures <- 0
//   while fewer than N points:
//       p <- uniform random point
//       if no accepted point within r of p (toroidal):  accept p; failures <- 0
//       else if ++failures == TRY_LIMIT (100):          r <- 0.75 r; failures <- 0
//
// r0 = 1/sqrt(N) in 2D (the study's value). Its analogues: 1/N in 1D and N^(-1/3) in 3D, i.e. the spacing
// of a regular grid of N points, which is what 1/sqrt(N) is in 2D. Neighbour search: a grid of cells no smaller
// than r0 (dart_grid.h). Terminates for every N: r shrinks geometrically, so
// the acceptance probability tends to 1. The cost that matters is the algorithm's: its darts, most of them
// misses (100 per radius it gives up), not the neighbour search.
#include "pointsets.h"

#include <cmath>

#include "dart_grid.h"
#include "random.h"
#include "torus.h"

namespace stipple::detail::pointsets {
namespace {

constexpr int kTryLimit = 100;
constexpr float kShrink = 0.75f;

template <int D>
std::vector<float> dartThrowing(uint32_t n, SplitMix64& rng) {
    float r = D == 1 ? 1.0f / float(n) : float(std::pow(double(n), -1.0 / D));
    DartGrid<D> grid(n, r);
    int failures = 0;
    while (grid.points().size() < n) {
        typename DartGrid<D>::Point p;
        for (int k = 0; k < D; ++k) p[k] = rng.uniformFloat();
        if (!grid.anyWithin(p, r)) {
            grid.insert(p);
            failures = 0;
        } else if (++failures == kTryLimit) {
            r *= kShrink;
            failures = 0;
        }
    }
    std::vector<float> out;
    out.reserve(size_t(n) * D);
    for (const auto& p : grid.points()) out.insert(out.end(), p.begin(), p.end());
    return out;
}

} // namespace

std::vector<float> generatePoissonSeed(int dim, uint32_t n, uint64_t seed) {
    if (n == 0 || n > kMaxPoints || dim < 1 || dim > 3) return {};
    SplitMix64 rng(deriveSeed(seed, 0x5eed0000u + uint64_t(dim)));
    switch (dim) {
    case 1: return dartThrowing<1>(n, rng);
    case 2: return dartThrowing<2>(n, rng);
    default: return dartThrowing<3>(n, rng);
    }
}

} // namespace stipple::detail::pointsets
