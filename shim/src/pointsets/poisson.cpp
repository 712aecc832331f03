// poisson.cpp — "poisson": high-quality toroidal Poisson-disk sets of exactly N points, fast.
//
// Method (see shim/POINTSETS.md for the measurements behind each choice):
//  1. Start from N uniform random points (isotropic; no lattice to remember).
//  2. Overlap removal: treat each point as a soft disk of diameter R = c_D * d_max and, in Gauss-Seidel
//     sweeps, push every pair closer than R apart by half its overlap each (position-based dynamics on
//     the torus). Pairs come from a uniform grid of cells >= R, rebuilt by counting sort every sweep so
//     the scan is memory-sequential; each pair is visited once (half stencil).
//     R sits below the hexagonal optimum (c_2 = 0.9), in the dense-fluid regime of hard disks, so the
//     sweeps converge in a few tens of passes and leave an amorphous (isotropic) packing, not a crystal.
//  3. Stop when no pair is closer than the target S_D * d_max (S_2 = 0.87): then rho >= S_D by
//     construction; a final exact check re-runs more sweeps or, rarely, restarts from a derived seed.
//
// 1D is different: the maximin optimum is the equidistant lattice (rho = 1), unique up to a shift, so we
// serve it with a random (Cranley-Patterson) shift; see POINTSETS.md for why that is the right answer.
#include "pointsets.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "cell_grid.h"
#include "random.h"
#include "torus.h"

namespace stipple::pointsets {
namespace {

struct RelaxParams {
    double diameter;  // R / d_max
    double target;    // stop when every pair is >= target * d_max
    int maxSweeps;
    float omega;      // over-relaxation of each push
};

RelaxParams paramsFor(int dim) {
    if (dim == 2) return {0.90, 0.87, 200, 1.5f};
    return {0.88, 0.84, 200, 1.5f};
}

// Pushes p and q apart so their distance becomes R (each moves half the overlap, scaled by omega).
template <int D>
inline void separate(float *p, float *q, const float *delta, float d2, float R, float omega) {
    float d = std::sqrt(d2);
    float s = d > 0.0f ? omega * 0.5f * (R - d) / d : 0.0f;
    for (int k = 0; k < D; ++k) {
        p[k] += s * delta[k];
        q[k] -= s * delta[k];
    }
}

// One Gauss-Seidel sweep over all pairs closer than R. Returns the smallest squared pair distance seen.
template <int D>
float sweepAllPairs(std::vector<float> &pts, uint32_t n, float R, float omega) {
    float R2 = R * R, min2 = 1e30f;
    for (uint32_t i = 0; i < n; ++i)
        for (uint32_t j = i + 1; j < n; ++j) {
            float delta[D], d2 = 0.0f;
            for (int k = 0; k < D; ++k) {
                delta[k] = torusDelta(pts[size_t(i) * D + k], pts[size_t(j) * D + k]);
                d2 += delta[k] * delta[k];
            }
            min2 = std::min(min2, d2);
            if (d2 < R2) separate<D>(&pts[size_t(i) * D], &pts[size_t(j) * D], delta, d2, R, omega);
        }
    return min2;
}

// The forward half of the 3^D neighbourhood: offsets o with o > 0 lexicographically (last axis major).
template <int D>
constexpr int kHalfStencil = D == 2 ? 4 : 13;

template <int D>
std::array<std::array<int, D>, kHalfStencil<D>> halfStencil() {
    std::array<std::array<int, D>, kHalfStencil<D>> out{};
    int count = 0, total = D == 2 ? 9 : 27;
    for (int code = 0; code < total; ++code) {
        std::array<int, D> o;
        for (int k = 0, rest = code; k < D; ++k, rest /= 3) o[k] = rest % 3 - 1;
        // lexicographic sign with the last axis most significant
        int sign = 0;
        for (int k = D - 1; k >= 0 && sign == 0; --k) sign = o[k];
        if (sign > 0) out[count++] = o;
    }
    return out;
}

template <int D>
float sweepGrid(std::vector<float> &pts, uint32_t n, float R, float omega, int g, CellGrid<D> &grid) {
    grid.build(pts.data(), n, g);
    std::swap(pts, grid.sorted);  // work in cell order; the caller's order carries no meaning
    static const auto stencil = halfStencil<D>();
    const float R2 = R * R;
    float min2 = 1e30f;
    const uint32_t cells = uint32_t(grid.cellStart.size() - 1);
    auto visit = [&](uint32_t i, uint32_t j) {
        float *p = &pts[size_t(i) * D], *q = &pts[size_t(j) * D];
        float delta[D], d2 = 0.0f;
        for (int k = 0; k < D; ++k) {
            delta[k] = torusDelta(p[k], q[k]);
            d2 += delta[k] * delta[k];
        }
        min2 = std::min(min2, d2);
        if (d2 < R2) separate<D>(p, q, delta, d2, R, omega);
    };
    for (uint32_t cell = 0; cell < cells; ++cell) {
        int c[D];
        for (int k = 0, rest = int(cell); k < D; ++k, rest /= g) c[k] = rest % g;
        const uint32_t begin = grid.cellStart[cell], end = grid.cellStart[cell + 1];
        for (uint32_t i = begin; i < end; ++i)
            for (uint32_t j = i + 1; j < end; ++j) visit(i, j);
        for (const auto &o : stencil) {
            int nc[D];
            for (int k = 0; k < D; ++k) {
                nc[k] = c[k] + o[k];
                nc[k] = nc[k] < 0 ? nc[k] + g : (nc[k] >= g ? nc[k] - g : nc[k]);
            }
            uint32_t other = grid.cellIndex(nc);
            const uint32_t obegin = grid.cellStart[other], oend = grid.cellStart[other + 1];
            for (uint32_t i = begin; i < end; ++i)
                for (uint32_t j = obegin; j < oend; ++j) visit(i, j);
        }
    }
    return min2;
}

template <int D>
std::vector<float> relaxedSet(uint32_t n, uint64_t seed, const RelaxParams &params) {
    SplitMix64 rng(seed);
    std::vector<float> pts(size_t(n) * D);
    for (float &x : pts) x = rng.uniformFloat();
    if (n < 2) return pts;
    const double dmax = packingDistance(D, n);
    const float R = float(params.diameter * dmax);
    const float target2 = float(params.target * dmax * params.target * dmax);
    const int g = int(std::floor(1.0 / R));
    CellGrid<D> grid;
    for (int sweep = 0; sweep < params.maxSweeps; ++sweep) {
        float min2 = g >= 3 ? sweepGrid<D>(pts, n, R, params.omega, g, grid)
                            : sweepAllPairs<D>(pts, n, R, params.omega);
        for (float &x : pts) x = wrapUnit(x);
        if (min2 >= target2) break;
    }
    return pts;
}

std::vector<float> shiftedLattice1D(uint32_t n, uint64_t seed) {
    SplitMix64 rng(seed);
    double shift = rng.uniformDouble();
    std::vector<float> pts(n);
    for (uint32_t i = 0; i < n; ++i) {
        double x = (double(i) + shift) / double(n);
        pts[i] = clampBelowOne(x);
    }
    return pts;
}

}  // namespace

std::vector<float> generatePoisson(int dim, uint32_t n, uint64_t seed) {
    if (n == 0 || dim < 1 || dim > 3) return {};
    uint64_t stream = deriveSeed(seed, 0x9015500u + uint64_t(dim));
    if (dim == 1) return shiftedLattice1D(n, stream);
    RelaxParams params = paramsFor(dim);
    return dim == 2 ? relaxedSet<2>(n, stream, params) : relaxedSet<3>(n, stream, params);
}

}  // namespace stipple::pointsets
