// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pointsets_quality_test.cpp — the quality claims of shim/POINTSETS.md at fixed seeds (deterministic, so these
// are regression bounds on measured values, not hypothesis tests):
//   - poisson 2D: rho >= 0.85 for every N >= 16 of the list, every seed; 3D rho >= 0.83; 1D rho >= 0.80 from 64
//     points, >= 0.5 from 8 to 63 (every set of the family: its steps q / n >= 1/2, cell_set_1d.cpp).
//   - poisson-seed (the study's rule): rho >= 0.75^3 * r0/d_max (its radius ends two, at most three shrinks below
//     r0: typically 2D 0.5235, 3D 0.5012, 1D 0.5625; three shrinks seen in 1D at N >= 256, 0.42), and poisson's
//     rho beats poisson-seed's mean at every N >= 16 (1D from 64 points: below, the steps near 1/2 that hold
//     against stratified on kinks keep rho >= 0.5, about the study's 0.56).
//   - a reduced version of the 1000-set sweep (tools/pointsets_figure3 runs the full one): 20 sets at N = 256.
//   - no clustering: 4096-point sets in 4^dim cells: every cell within 12 of its mean, rms below half white noise.
//   - isotropy / no lattice: the averaged periodogram has no Bragg peak and a blue-noise low band; it is
//     isotropic off the axes and above the cancelled modes |k| <= 4, and on the axes (stratified projections)
//     nearly empty in the low band.
//   - stratified projections: every 1D projection of a poisson set has one point per stratum [r/N, (r+1)/N).
#define BOOST_TEST_MODULE pointsets_quality
#include <boost/test/unit_test.hpp>

#include "pointsets/pointsets.h"
#include "pointsets/low_frequency.h"
#include "pointsets/spectrum.h"

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

} // namespace

BOOST_AUTO_TEST_CASE(rho_per_n_both_generators) {
    for (int dim = 1; dim <= 3; ++dim)
        for (uint32_t n : kSizes) {
            double minOurs = 1e9, meanSeed = 0.0;
            for (int s = 0; s < kSeeds; ++s) {
                const uint64_t seed = 1000 + 17 * s;
                std::vector<float> ours = generatePoisson(dim, n, seed);
                double rho = relativeRadius(dim, ours.data(), n);
                minOurs = std::min(minOurs, rho);
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
                // 1D: the lattice below 8 points; from 64, the Weyl step's 1 - beta = 0.809 less one sub-cell; between,
                // the family's steps, q / n >= 1/2 (or q = 0: rho 1).
                if (dim == 1) BOOST_CHECK_GE(minOurs, n < 8 ? 0.999 : n < 64 ? 0.5 - 1e-4 : 0.80);
                if (dim == 2 && n >= 16) BOOST_CHECK_GE(minOurs, 0.85);
                if (dim == 3 && n >= 16) BOOST_CHECK_GE(minOurs, 0.83);
                // Small N (POINTSETS.md): 2D n = 2: >= 0.86 (optimum 0.931), 3: >= 0.80 (optimum 0.834), 5..13:
                // >= 0.86; 3D n = 2..13: >= 0.82.
                if (dim >= 2 && n >= 2 && n < 16) BOOST_CHECK_GE(minOurs, dim == 2 ? 0.78 : 0.80);
                if (n >= 16 && !(dim == 3 && n == 4096) && !(dim == 1 && n < 64)) BOOST_CHECK_GT(minOurs, meanSeed);
            }
        }
}

BOOST_AUTO_TEST_CASE(twenty_sets_at_256_all_above_085) {
    double worst = 1.0;
    for (uint64_t s = 0; s < 20; ++s) {
        std::vector<float> pts = generatePoisson(2, 256, 0xabc0 + s);
        worst = std::min(worst, relativeRadius(2, pts.data(), 256));
    }
    BOOST_TEST_MESSAGE("min rho over 20 sets at N = 256: " << worst);
    BOOST_CHECK_GE(worst, 0.85);
}

BOOST_AUTO_TEST_CASE(no_clustering_in_4x4_cells) {
    // 4096 points counted in 4^dim equal cells (256 per cell in 2D, 64 in 3D). A well-spread set deviates only
    // along cell borders; white noise has sd 15.5 (2D) / 7.94 (3D) per cell. Two bounds per set, each of
    // which white noise passes with probability < 2e-4: every cell within 12 of its mean (2D: P(|Z| <= 0.77)^16
    // = 1e-4; 3D: P(|Z| <= 1.51)^64 = 1.3e-4), and the rms deviation below half white noise's sd. Measured
    // over 40 seeds: rms 2.7 (2D) and 2.9 (3D), worst single cell 10 and 12.
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
            for (int c = 0; c < cells; ++c) {
                BOOST_CHECK_LE(std::abs(counts[c] - mean), 12);
                sumSquares += double(counts[c] - mean) * (counts[c] - mean);
            }
            BOOST_TEST_CONTEXT("dim " << dim << " seed " << s)
            BOOST_CHECK_LT(std::sqrt(sumSquares / cells), 0.5 * whiteSd);
        }
    }
}

BOOST_AUTO_TEST_CASE(isotropic_blue_noise_spectrum) {
    // 10 sets of 256 points, frequencies |k| <= 2 sqrt(N) = 32. A lattice (or crystallised domains) shows Bragg
    // peaks of height ~N; the relaxed sets peak near 2.5 on the ring |k| ~ 1.1 sqrt(N).
    const uint32_t n = 256;
    PowerSpectrum2D spectrum(32);
    for (uint64_t s = 0; s < 10; ++s) {
        std::vector<float> pts = generatePoisson(2, n, 900 + s);
        spectrum.add(pts.data(), n);
    }
    double peak = 0.0, low = 0.0;
    int lowCount = 0;
    for (int ky = -32; ky <= 32; ++ky)
        for (int kx = -32; kx <= 32; ++kx) {
            if (kx == 0 && ky == 0) continue;
            peak = std::max(peak, spectrum.at(kx, ky));
            if (std::hypot(kx, ky) <= 0.5 * std::sqrt(double(n))) {
                low += spectrum.at(kx, ky);
                ++lowCount;
            }
        }
    low /= lowCount;
    BOOST_TEST_MESSAGE("periodogram peak " << peak << ", mean power for |k| <= sqrt(N)/2: " << low);
    BOOST_CHECK_LT(peak, 12.0);
    BOOST_CHECK_LT(low, 0.1); // white noise: 1
    // Anisotropy per ring within 3 dB of the isotropic floor 10 log10(1/10) = -10 dB (rings with >= 24 cells),
    // off the axes, where the stratified projections change the power by design, and above the cancelled modes
    // |k| <= 4 (near zero by design: the ring of radius 4 mixes them with uncancelled ones). The ring at the
    // start's grid frequency sqrt(N) = 16 keeps a weak imprint of the jittered start: within 4 dB there.
    for (const auto& ring : spectrum.rings(true))
        if (ring.count >= 24 && ring.radius >= 5)
            BOOST_CHECK_LT(ring.anisotropy, std::abs(ring.radius - 16.0) < 0.5 ? -6.0 : -7.0);
    // On the axes, the low band |k| <= sqrt(N)/2: a stratified projection of a well-spread set leaves almost
    // nothing (measured <= 0.01; an unstratified relaxed set has the low band's ~0.03 there).
    double axisLow = 0.0;
    for (int k = 1; k <= 8; ++k) axisLow = std::max({axisLow, spectrum.at(k, 0), spectrum.at(0, k)});
    BOOST_TEST_MESSAGE("largest power on the axes for |k| <= sqrt(N)/2: " << axisLow);
    BOOST_CHECK_LT(axisLow, 0.02);
}

BOOST_AUTO_TEST_CASE(stratified_projections) {
    // Every axis of every set: exactly one point in each stratum [r/N, (r+1)/N). (The generator serves an
    // unstratified set only if no attempt reaches the rho target stratified; never at these seeds.)
    for (int dim = 2; dim <= 3; ++dim)
        for (uint32_t n : {16u, 31u, 64u, 97u, 256u, 1000u, 1024u, 4096u})
            for (uint64_t s = 0; s < 4; ++s) {
                const std::vector<float> pts = generatePoisson(dim, n, 0x1a7 + s);
                for (int k = 0; k < dim; ++k) {
                    std::vector<int> count(n, 0);
                    for (uint32_t i = 0; i < n; ++i) ++count[std::min(n - 1, uint32_t(double(pts[i * dim + k]) * n))];
                    BOOST_TEST_CONTEXT("dim " << dim << " n " << n << " seed " << s << " axis " << k)
                    BOOST_CHECK(std::all_of(count.begin(), count.end(), [](int c) { return c == 1; }));
                }
            }
}

BOOST_AUTO_TEST_CASE(lowest_modes_cancelled) {
    // The lowest modes of poisson sets, 0 < |k| <= 4 in 2D (24 modes) and <= 2 in 3D (16; the generator cancels
    // |k| <= 3 there, of which the outer ring keeps more): periodogram sums measured 0.002-0.004 (2D) and 0.006-0.011
    // (3D) at N = 1024, against 0.20 and 0.11 for relaxed sets without the stratifying passes (white noise: 1 per
    // mode).
    for (uint64_t s = 0; s < 4; ++s) {
        const std::vector<float> p2 = generatePoisson(2, 1024, 0x10f + s), p3 = generatePoisson(3, 1024, 0x10f + s);
        const double e2 = lowFrequencyEnergy<2>(p2, 1024, 4), e3 = lowFrequencyEnergy<3>(p3, 1024, 2);
        BOOST_TEST_MESSAGE("seed " << s << ": low-mode energy 2D " << e2 << ", 3D " << e3);
        BOOST_CHECK_LT(e2, 0.03);
        BOOST_CHECK_LT(e3, 0.03);
    }
    // The displacement alone, on a white-noise set (power ~1 per mode): the modes fall by more than 100x in three
    // steps (measured 1.5e7x) and no point moves by more than the spacing 1 / sqrt(N) (measured 0.94 of it:
    // white noise needs large moves; poisson sets' low modes are ~1000x weaker).
    std::vector<float> white(2 * 4096);
    uint64_t state = 0x5eed;
    for (float& v : white) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        v = float(state >> 40) * 0x1p-24f;
    }
    const std::vector<float> before = white;
    const double e0 = lowFrequencyEnergy<2>(white, 4096, 4);
    cancelLowFrequencies<2>(white, 4096, 4, 3);
    const double e1 = lowFrequencyEnergy<2>(white, 4096, 4);
    double maxMove = 0.0;
    for (size_t i = 0; i < white.size(); ++i) {
        double d = std::abs(double(white[i]) - before[i]);
        maxMove = std::max(maxMove, std::min(d, 1.0 - d));
    }
    BOOST_TEST_MESSAGE("white noise: low-mode energy " << e0 << " -> " << e1 << ", largest move " << maxMove);
    BOOST_CHECK_LT(e1, 0.01 * e0);
    BOOST_CHECK_LT(maxMove, 1.0 / std::sqrt(4096.0));
}

// The layout the 1D serving relies on (pattern_poisson.cpp): one point in each cell [c/n, (c+1)/n), at the centre of
// one of the cell's m sub-cells, the sub-cell index stepping by cellStep1D(n, j) modulo n from cell to cell, so that
// the served set (any common rotation of the offsets) keeps neighbours q / n of a cell apart: rho = q / n >= 1/2 below
// 64 points (q = 0: 1), the Weyl step ~0.81 from 64 on. Every set index of a family (32 sets; below 64 points they
// mix steps). Served points are uniform whatever the sub-cells used: the serving's rotation spans the whole cell.
BOOST_AUTO_TEST_CASE(one_dimensional_cells_and_steps) {
    for (uint32_t n : {2u, 7u, 8u, 13u, 16u, 24u, 31u, 32u, 63u, 64u, 97u, 1000u, 4096u, 6000u})
        for (uint32_t j = 0; j < 32; ++j) {
            const uint32_t m = cellSubdivision1D(n), q = cellStep1D(n, j);
            BOOST_TEST_CONTEXT("n " << n << " m " << m << " set " << j << " q " << q) {
                BOOST_REQUIRE(m >= 1 && n % m == 0 && double(n) * m <= double(1u << 23));
                BOOST_REQUIRE(q < n);
                if (m > 1) BOOST_CHECK(q == 0 || 2 * q >= n);
                const std::vector<float> pts = generateCellSet1D(n, j, 1000 + j);
                BOOST_REQUIRE_EQUAL(pts.size(), size_t(n));
                std::vector<int64_t> sub(n, -1);
                for (float x : pts) {
                    // A sub-cell centre: fine = c m + s + 1/2, to the float rounding of x (2^-25 relative).
                    const double fine = double(x) * n * m - 0.5, index = std::nearbyint(fine);
                    BOOST_CHECK_SMALL(fine - index, double(n) * m * 0x1p-25 + 1e-9);
                    const uint64_t f = uint64_t(index);
                    BOOST_REQUIRE_LT(f / m, n);
                    BOOST_CHECK_EQUAL(sub[f / m], -1); // one point per cell
                    sub[f / m] = int64_t(f % m);
                }
                for (uint32_t c = 0; c + 1 < n && m > 1; ++c) // sigma(c) = floor(((c q) mod n) m / n), up to a shift
                    BOOST_CHECK_EQUAL((sub[c + 1] - sub[c] + int64_t(m)) % int64_t(m),
                                      (int64_t((uint64_t(c + 1) * q % n) * m / n) - int64_t((uint64_t(c) * q % n) * m / n) +
                                       int64_t(m)) % int64_t(m));
                const double rho = relativeRadius(1, pts.data(), n);
                BOOST_CHECK_GE(rho, n < 8 ? 0.999 : n < 64 ? 0.5 - 1e-4 : 0.80);
            }
            if (n >= 64 && j > 1) break; // one step for every set from 64 points on
        }
    // Below 64 points the family mixes steps; from 64 on every set has the same.
    BOOST_CHECK(cellStep1D(16, 0) != cellStep1D(16, 31));
    BOOST_CHECK_EQUAL(cellStep1D(64, 0), cellStep1D(64, 31));
}
