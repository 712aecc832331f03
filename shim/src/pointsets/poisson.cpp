// poisson.cpp — "poisson": high-quality toroidal Poisson-disk sets of exactly N points, fast.
//
// Method (see shim/POINTSETS.md for the measurements behind each choice):
//  1. Start: uniform random points stratified in coarse cells of ~4 points (8 in 3D): the right density
//     everywhere without imprinting a lattice (one point per stratum does imprint one).
//  2. Overlap removal (overlap_relaxation.h): soft disks of diameter R = 0.89 d_max (3D: 0.88) pushed
//     apart pairwise in Gauss-Seidel passes over a uniform grid, over-relaxed (omega = 1.6). R lies at the
//     edge of the dense-fluid regime of hard disks (packing fraction 0.72 < hexagonal 0.907), so ~13 passes
//     converge and leave an amorphous, isotropic packing rather than a crystal.
//  3. Stop once a pass meets no pair closer than 0.86 d_max and an exact measurement confirms
//     rho >= 0.855 (3D: 0.84 / 0.835). A set that misses within maxPasses is redrawn from a derived
//     seed, each retry aiming 1.5% lower (at most maxAttempts(n), best kept): in practice only tiny N,
//     where the torus cannot hold the target packing (N = 3: the optimum is rho = 0.834).
//  4. Shuffle the order (the relaxation leaves points in cell order).
//
// 1D is different: the maximin optimum is the equidistant lattice (rho = 1), unique up to a shift, so we
// serve it with a random (Cranley-Patterson) shift; see POINTSETS.md for why that is the right answer.
#include "pointsets.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "overlap_relaxation.h"
#include "random.h"
#include "torus.h"

namespace stipple::pointsets {
namespace {

// Relaxation diameter and stopping target, as fractions of d_max (measured in POINTSETS.md).
struct Tuning {
    double diameter, target, accept;
    float omega;
    int maxPasses;
    double perCell; // points per coarse stratum of the start
};
Tuning tuningFor(int dim) {
    if (dim == 2) return {0.89, 0.86, 0.855, 1.6f, 100, 4.0};
    return {0.88, 0.84, 0.835, 1.5f, 100, 8.0};
}

// Retries of a set that misses `accept`; tiny sets cost nothing, so they get more tries at their optimum.
inline int maxAttempts(uint32_t n) { return n < 16 ? 32 : 4; }

// Fisher-Yates: the relaxation leaves points in cell order; hosts get no spatial order to trip on.
template <int D>
void shuffle(std::vector<float>& pts, uint32_t n, uint64_t seed) {
    SplitMix64 rng(seed);
    for (uint32_t i = n; i > 1; --i) {
        uint32_t j = rng.uniformBelow(i);
        for (int k = 0; k < D; ++k) std::swap(pts[size_t(i - 1) * D + k], pts[size_t(j) * D + k]);
    }
}

// The start: uniform random points, but stratified in coarse cells of about `perCell` points (counts
// differing by at most one). Coarse strata fix the density at a scale of a few spacings, so the
// relaxation needs no long-range transport (white noise needs ~4x more passes); inside a stratum the points
// are free, so no lattice is imprinted. (One point per stratum, i.e. jittering, imprints its grid: the
// relaxed sets then show Bragg peaks at the stratum frequency; see POINTSETS.md.)
template <int D>
void stratifiedStart(std::vector<float>& pts, uint32_t n, double perCell, SplitMix64& rng) {
    const uint32_t g = std::max(1u, uint32_t(std::lround(std::pow(double(n) / perCell, 1.0 / D))));
    uint32_t cells = 1;
    for (int k = 0; k < D; ++k) cells *= g;
    uint32_t written = 0;
    for (uint32_t c = 0; c < cells; ++c) {
        const uint32_t count = uint32_t(uint64_t(n) * (c + 1) / cells - uint64_t(n) * c / cells);
        uint32_t cell[D];
        for (int k = 0, rest = int(c); k < D; ++k, rest /= int(g)) cell[k] = uint32_t(rest) % g;
        for (uint32_t i = 0; i < count; ++i, ++written)
            for (int k = 0; k < D; ++k)
                pts[size_t(written) * D + k] = clampBelowOne((cell[k] + rng.uniformDouble()) / g);
    }
}

template <int D>
std::vector<float> relaxedSet(uint32_t n, uint64_t seed, const Tuning& tuning) {
    const double dmax = packingDistance(D, n);
    std::vector<float> best;
    float bestDistance = -1.0f;
    // Deterministic retries: a set that misses `accept` within maxPasses is redrawn from a derived seed, each
    // retry aiming 1.5% lower; the best is kept. Only tiny N get here, where the torus cannot hold the target
    // packing (N = 3: the optimum is rho = 0.834, below R = 0.89, so the first attempt can only jam).
    for (int attempt = 0; attempt < maxAttempts(n); ++attempt) {
        const double scale = dmax * std::pow(0.985, attempt);
        const RelaxParams params{float(tuning.diameter * scale), float(tuning.target * scale),
                                 float(tuning.accept * scale), tuning.omega, tuning.maxPasses};
        SplitMix64 rng(deriveSeed(seed, uint64_t(attempt)));
        std::vector<float> pts(size_t(n) * D);
        stratifiedStart<D>(pts, n, tuning.perCell, rng);
        RelaxStats stats = relaxOverlaps<D>(pts, n, params);
        if (stats.minDistance > bestDistance) {
            bestDistance = stats.minDistance;
            best.swap(pts);
        }
        if (stats.verified) break;
    }
    shuffle<D>(best, n, deriveSeed(seed, 0x5a0ffu));
    return best;
}

std::vector<float> shiftedLattice1D(uint32_t n, uint64_t seed) {
    SplitMix64 rng(seed);
    double shift = rng.uniformDouble();
    std::vector<float> pts(n);
    for (uint32_t i = 0; i < n; ++i) {
        double x = (double(i) + shift) / double(n);
        pts[i] = clampBelowOne(x);
    }
    shuffle<1>(pts, n, deriveSeed(seed, 0x5a0ffu));
    return pts;
}

} // namespace

std::vector<float> generatePoisson(int dim, uint32_t n, uint64_t seed) {
    if (n == 0 || n > kMaxPoints || dim < 1 || dim > 3) return {};
    uint64_t stream = deriveSeed(seed, 0x9015500u + uint64_t(dim));
    if (dim == 1) return shiftedLattice1D(n, stream);
    Tuning tuning = tuningFor(dim);
    return dim == 2 ? relaxedSet<2>(n, stream, tuning) : relaxedSet<3>(n, stream, tuning);
}

} // namespace stipple::pointsets
