// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pointsets_quality_test.cpp — the quality claims of shim/POINTSETS.md on the generators at fixed seeds
// (deterministic, so these are regression bounds on measured values, not hypothesis tests):
//   - poisson 2D: rho >= 0.76 for every N >= 16 of the list, every seed (the dart radius); 3D rho >= 0.72; 1D
//     rho >= 0.2 (N >= 3, the walk's least gap less the cell margin) and one point in each cell [c/N, (c+1)/N);
//     poisson's rho beats poisson-seed's mean at every N >= 16 in 2D and 3D.
//   - poisson-seed (the study's rule): rho >= 0.75^3 * r0/d_max (its radius ends two, at most three shrinks below
//     r0: typically 2D 0.5235, 3D 0.5012, 1D 0.5625).
//   - no clustering: 4096-point sets in 4^dim cells, rms count deviation below half white noise's.
// The spectral claims (no crystal peak, isotropy) are measured on served sets: poisson_serving_test.
#define BOOST_TEST_MODULE pointsets_quality
#include <boost/test/unit_test.hpp>

#include "pointsets/pointsets.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

using namespace stipple::detail::pointsets;

namespace {

const uint32_t kSizes[] = {1, 2, 3, 5, 7, 13, 16, 31, 64, 97, 256, 1000, 1024, 4096};
constexpr int kSeeds = 3;

double seedFloor(int dim) {
    // r_final >= 0.75^3 r0 with r0 = N^(-1/dim); r0 / d_max = 1 (1D), sqrt(sqrt(3)/2) (2D), 2^(-1/6) (3D).
    const double r0OverDmax[] = {1.0, std::sqrt(std::sqrt(3.0) / 2.0), std::pow(2.0, -1.0 / 6.0)};
    return 0.421875 * r0OverDmax[dim - 1] - 1e-4;
}

// One point in each cell [c/n, (c+1)/n) (the stored sets are not shifted).
bool onePointPerCell(const std::vector<float>& pts, uint32_t n) {
    std::vector<uint32_t> count(n, 0);
    for (float v : pts) ++count[std::min<uint32_t>(n - 1, uint32_t(double(v) * n))];
    return std::all_of(count.begin(), count.end(), [](uint32_t c) { return c == 1; });
}

} // namespace

BOOST_AUTO_TEST_CASE(rho_per_n_both_generators) {
    for (int dim = 1; dim <= 3; ++dim)
        for (uint32_t n : kSizes) {
            double minOurs = 1e9, meanSeed = 0.0;
            for (int s = 0; s < kSeeds; ++s) {
                const uint64_t seed = 1000 + 17 * s;
                std::vector<float> ours = generatePoisson(dim, n, seed);
                minOurs = std::min(minOurs, relativeRadius(dim, ours.data(), n));
                if (dim == 1) BOOST_CHECK_MESSAGE(onePointPerCell(ours, n), "1D n " << n << " seed " << seed);
                if (dim == 3 && n == 4096) continue; // the 3D baseline at 4096 is slow; covered at 1024
                std::vector<float> base = generatePoissonSeed(dim, n, seed);
                double rhoSeed = relativeRadius(dim, base.data(), n);
                meanSeed += rhoSeed / kSeeds;
                BOOST_TEST_CONTEXT("poisson-seed dim " << dim << " n " << n << " seed " << seed) {
                    if (n >= 16) BOOST_CHECK_GE(rhoSeed, seedFloor(dim));
                }
            }
            BOOST_TEST_MESSAGE("dim " << dim << " n " << n << ": poisson min rho " << minOurs
                                      << ", poisson-seed mean rho " << (dim == 3 && n == 4096 ? -1.0 : meanSeed));
            BOOST_TEST_CONTEXT("poisson dim " << dim << " n " << n) {
                // 1D: the walk's least gap 0.2, scaled by 1 - 2 n 2^-23 (the cell margin).
                if (dim == 1 && n >= 3) BOOST_CHECK_GE(minOurs, 0.2 * (1.0 - n * 0x1p-22) - 1e-4);
                if (dim >= 2 && n >= 16) BOOST_CHECK_GE(minOurs, poissonRadius(dim) - 1e-4);
                if (dim >= 2 && n >= 16 && !(dim == 3 && n == 4096)) BOOST_CHECK_GT(minOurs, meanSeed);
            }
        }
}

BOOST_AUTO_TEST_CASE(one_dimensional_sets_have_one_point_per_cell_at_large_n) {
    for (uint32_t n : {4096u, 8192u, 65536u})
        for (uint64_t s = 0; s < 8; ++s)
            BOOST_CHECK_MESSAGE(onePointPerCell(generatePoisson(1, n, 0xce11 + s), n), "n " << n << " seed " << s);
}

BOOST_AUTO_TEST_CASE(no_clustering_in_4x4_cells) {
    // 4096 points counted in 4^dim equal cells (256 per cell in 2D, 64 in 3D); white noise has sd 15.5 (2D) / 7.94
    // (3D) per cell. A Poisson-disk set's low-frequency power is a small fraction of white noise's (POINTSETS.md,
    // "Spectra": about 0.07 in 2D), so its rms deviation stays below half white noise's; white noise itself passes
    // with probability 2.4e-3 (2D, 16 cells: chi-square with 15 degrees of freedom below 4) per set, far less in 3D.
    for (int dim = 2; dim <= 3; ++dim) {
        const int cells = dim == 2 ? 16 : 64, mean = 4096 / cells;
        const double whiteSd = std::sqrt(4096.0 * (1.0 / cells) * (1.0 - 1.0 / cells));
        for (uint64_t s = 0; s < 5; ++s) {
            std::vector<float> pts = generatePoisson(dim, 4096, 77 + s);
            int counts[64] = {};
            for (size_t i = 0; i < 4096; ++i) {
                int cell = 0;
                for (int k = dim - 1; k >= 0; --k) cell = 4 * cell + int(pts[dim * i + k] * 4);
                ++counts[cell];
            }
            double sumSquares = 0.0;
            for (int c = 0; c < cells; ++c) sumSquares += double(counts[c] - mean) * (counts[c] - mean);
            BOOST_TEST_CONTEXT("dim " << dim << " seed " << s)
            BOOST_CHECK_LT(std::sqrt(sumSquares / cells), 0.5 * whiteSd);
        }
    }
}
