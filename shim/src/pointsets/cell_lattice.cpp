// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// cell_lattice.cpp — "poisson" in 2D (the generator works in 3D too): Poisson-disk sets aligned with the domain,
// one point per cell.
//
// The domain [0,1)^D is cut into a grid of g_0 x ... x g_{D-1} = n cells; cell c holds one point at the offset
// o(c) = frac(A c) inside it, A a D x D matrix whose column k is a multiple of 1/g_k (so o is periodic over the
// grid: the cells form a torus). The serving (pattern_poisson.cpp) moves the set by a whole number of cells per axis
// (cyclically), reflects axes and shifts every offset by one common tau inside its cell (frac(o + tau)). The
// domain's faces stay cell faces (a non-periodic integrand sees no seam), and a whole-cell shift uniform over the
// grid with tau uniform over the cell makes every point uniform on the domain.
//
// Minimum distance under every tau: two points whose cells differ by delta have offsets differing by
// d = frac(A delta) (the same for every pair with that delta: A is linear), and after the common shift their
// separation along axis j is delta_j + d_j or delta_j + d_j - 1 (the second when only one of the two wraps), each
// attained for some tau. The set's worst-case rho is the least over small delta and both choices per axis; it is
// what a served set measures (its many pairs per delta see both choices at almost every tau).
//
// Error: on a smooth integrand a cell's error is the gradient times its offset's deviation from the centre, and
// frac(A c + tau) - 1/2 is a sawtooth over the grid whose Fourier modes sit at the frequencies h A_j (row j, h
// = 1, 2, ...): a mode near zero frequency lines the sawtooth up with the integrand's slow variation. The search
// (random matrices from the set's seed) keeps those reaching the rho floor; prefers those whose n offsets along
// each axis are all different (the two digits, see Matrix); ranks them by a figure of merit that sums the modes'
// weights; and picks among the best kProbeCandidates by their measured error on smooth probe functions. One point
// per cell keeps stratified's variance bound; the sawtooth's cancellation is what makes it smaller.
//
// Limits (measured, shim/POINTSETS.md): the floor makes neighbouring offsets nearly equal, so the sawtooth's
// fundamental spans about 7 cells: grids under 16 cells a side are not used (the cache serves its toroidal set).
// And every lattice that reaches the floor is a near-hexagonal one of much the same orientation, coherent along
// its rows: a straight edge near a row's direction has up to about 2x jittered sampling's error.
#include "pointsets.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "random.h"
#include "torus.h"

namespace stipple::detail::pointsets {
namespace {

constexpr uint32_t kSearchBudget = 20000;   // random first digits tried per round
constexpr uint32_t kSearchRounds = 8;       // rounds at most, per grid
constexpr uint32_t kMaxShared = 2;
constexpr int kAttempts = 12;
constexpr uint32_t kProbeCandidates = 24; // finalists measured (probeError)
// Counting shared offsets and measuring finalists cost O(n) each, and the search makes thousands of them: about
// 0.1 s per set at n = 4096, 1.5 s at 2^16, 50 s at 2^18. Larger sets are toroidal.
constexpr uint32_t kMaxLatticePoints = 1u << 16;          // cells per offset value that end the search early
constexpr uint32_t kSecondDigitTrials = 64; // second digits tried per first digit that reaches the floor
constexpr double kMaxAspect = 2.5;        // grids with a longer side over shorter side are not tried
// The rho floor makes neighbouring offsets nearly equal (a step of about -0.14 of a cell): the sawtooth's
// fundamental has a period of about 7 cells, so on a grid of fewer than 16 cells per side it is a wave across the
// whole domain. Measured in 2D (shim_battery, 200 sets): 8 x 8 cells up to 7.9x stratified's MSE on the Genz
// smooth families, where the toroidal set has 3.6x at worst; 16 x 16 and finer beat the toroidal set on every
// class.
constexpr uint32_t kMinCellsPerAxis = 16;

struct Grid {
    int dim;
    uint32_t g[3];
};

// Factorisations of n into dim counts, most cubic first (largest over smallest at most kMaxAspect).
std::vector<Grid> gridsFor(int dim, uint32_t n) {
    std::vector<std::pair<double, Grid>> found;
    for (uint32_t a = 1; a <= n; ++a) {
        if (n % a) continue;
        if (dim == 2) {
            const uint32_t b = n / a;
            if (a >= b && double(a) / b <= kMaxAspect) found.push_back({double(a) / b, Grid{2, {a, b, 1}}});
            continue;
        }
        for (uint32_t b = 1; b <= a; ++b) {
            if ((n / a) % b) continue;
            const uint32_t c = n / a / b;
            if (c <= b && double(a) / c <= kMaxAspect) found.push_back({double(a) / c, Grid{3, {a, b, c}}});
        }
    }
    std::stable_sort(found.begin(), found.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<Grid> grids;
    for (const auto& f : found) grids.push_back(f.second);
    return grids;
}

// Two digits per offset: offset_j(c) = frac(sum_k z_jk c_k / g_k) + frac(sum_k w_jk c_k / g_k) / L, L the lcm of
// the grid's counts. The first digit alone takes only L values, each shared by n / L cells, whose errors then add
// up coherently (measured: 2-3x stratified's MSE on the ramp x + y at N = 1024-4096); the second spreads every
// such group over its 1/L step, so that in 2D the n offsets along each axis are all different.
struct Matrix {
    uint32_t z[3][3] = {}; // first digit: A[j][k] = z[j][k] / g_k
    uint32_t w[3][3] = {}; // second digit, the same form
};

uint64_t gridLcm(const Grid& grid) {
    uint64_t lcm = 1;
    for (int k = 0; k < grid.dim; ++k) lcm = std::lcm(lcm, uint64_t(grid.g[k]));
    return lcm;
}

inline double fracOf(double v) { return v - std::floor(v); }
inline double torusNorm(double v) {
    v = fracOf(v);
    return std::min(v, 1.0 - v);
}

// Worst-case squared minimum distance in the domain over every within-cell shift; stops early (returns a value
// below floor2) once a pair is closer than floor2.
double worstDistance2(const Grid& grid, const Matrix& a, double floor2) {
    const int D = grid.dim;
    const double lcm = double(gridLcm(grid));
    int range[3] = {0, 0, 0};
    for (int k = 0; k < D; ++k) range[k] = int(std::min<uint32_t>(2, grid.g[k] / 2));
    double best = 1e300;
    int delta[3];
    for (delta[0] = -range[0]; delta[0] <= range[0]; ++delta[0])
        for (delta[1] = -range[1]; delta[1] <= range[1]; ++delta[1])
            for (delta[2] = -range[2]; delta[2] <= range[2]; ++delta[2]) {
                if (delta[0] == 0 && delta[1] == 0 && delta[2] == 0) continue;
                // Per axis the offset difference is d = frac(first digit's difference + second's / L), the second's
                // being f or f - 1 (a carry, depending on the pair; f = 0: none); each d gives the separations delta + d - 1 and
                // delta + d. The axes' worst choices combine independently (conservative).
                double s2 = 0.0;
                for (int j = 0; j < D; ++j) {
                    double first = 0.0, second = 0.0;
                    for (int k = 0; k < D; ++k) {
                        first += double(a.z[j][k]) * delta[k] / grid.g[k];
                        second += double(a.w[j][k]) * delta[k] / grid.g[k];
                    }
                    const double f = fracOf(second);
                    double least = 1e300;
                    for (double carry : {0.0, 1.0}) {
                        if (carry > 0.0 && f == 0.0) break; // equal second digits: no carry
                        const double d = fracOf(first + (f - carry) / lcm);
                        for (double s : {delta[j] + d - 1.0, delta[j] + d}) least = std::min(least, s * s);
                    }
                    s2 += least / (double(grid.g[j]) * grid.g[j]);
                }
                best = std::min(best, s2);
                if (best < floor2) return best;
            }
    return best;
}

// The weight of the sawtooth's modes near zero frequency (smaller is better; see the file comment): for row j and
// harmonic h, the coherent sum over the grid is about prod_k min(g_k, 1 / |h A_jk|) / h, over a plane of cells
// across axis j the same product without k = j.
double merit(const Grid& grid, const Matrix& a) {
    const double lcm = double(gridLcm(grid));
    double sum = 0.0;
    for (int j = 0; j < grid.dim; ++j)
        for (int h : {1, 2, 3, 4, 5, 6, 7, 8, int(lcm), 2 * int(lcm)}) { // h = L: where one digit alone is coherent
            double whole = 1.0, plane = 1.0;
            for (int k = 0; k < grid.dim; ++k) {
                const double rate = (a.z[j][k] + double(a.w[j][k]) / lcm) / grid.g[k]; // both digits, as one
                const double t = 1.0 / std::max(1.0 / grid.g[k], torusNorm(h * rate));
                whole *= t;
                if (k != j) plane *= t;
            }
            sum += (whole * whole + plane * plane) / (double(h) * h);
        }
    return sum;
}

// How many cells share their offset with cell 0 along the worst axis (the kernel of c -> both digits, a group
// homomorphism, so every offset value is shared by as many cells): 1 when the n offsets along every axis are all
// different. Stops counting past `enough`.
uint32_t sharedOffsets(const Grid& grid, const Matrix& a, uint32_t enough) {
    const uint64_t lcm = gridLcm(grid);
    uint32_t worst = 0;
    for (int j = 0; j < grid.dim; ++j) {
        uint32_t count = 0, c[3] = {0, 0, 0};
        const uint32_t n = grid.g[0] * grid.g[1] * (grid.dim == 3 ? grid.g[2] : 1);
        for (uint32_t i = 0; i < n && count <= enough; ++i) {
            uint32_t rest = i;
            for (int k = 0; k < grid.dim; ++k) c[k] = rest % grid.g[k], rest /= grid.g[k];
            uint64_t first = 0, second = 0;
            for (int k = 0; k < grid.dim; ++k) {
                first += uint64_t(a.z[j][k]) * c[k] % grid.g[k] * (lcm / grid.g[k]);
                second += uint64_t(a.w[j][k]) * c[k] % grid.g[k] * (lcm / grid.g[k]);
            }
            count += first % lcm == 0 && second % lcm == 0;
        }
        worst = std::max(worst, count);
    }
    return worst;
}

// The set's points for a first-digit/second-digit matrix, in cell order: cell c's offset along axis j is
// frac(A_j c) + frac(B_j c) / L, in exact integers, plus half a step of 1/L^2, then mapped into [m, 1 - m] with
// m = kFaceMargin. The serving decides in float which points its rotation carried across a cell face; a stored
// offset closer to a face than float resolves (1/L^2 is 3e-6 of a cell for a 75 x 40 grid) could be put in the
// wrong cell. The map moves differences by at most 2m of a cell: rho by at most 0.003 below the search's floor.
constexpr double kFaceMargin = 0x1p-10;
std::vector<float> latticePoints(const Grid& grid, const Matrix& a, uint32_t n) {
    const int dim = grid.dim;
    const uint64_t lcm = gridLcm(grid);
    std::vector<float> points(size_t(n) * dim);
    uint32_t c[3] = {0, 0, 0};
    for (uint32_t i = 0; i < n; ++i) {
        uint32_t rest = i;
        for (int k = 0; k < dim; ++k) c[k] = rest % grid.g[k], rest /= grid.g[k];
        for (int j = 0; j < dim; ++j) {
            uint64_t first = 0, second = 0;
            for (int k = 0; k < dim; ++k) {
                first += uint64_t(a.z[j][k]) * c[k] % grid.g[k] * (lcm / grid.g[k]);
                second += uint64_t(a.w[j][k]) * c[k] % grid.g[k] * (lcm / grid.g[k]);
            }
            const double offset = (double(first % lcm) + (double(second % lcm) + 0.5) / double(lcm)) / double(lcm);
            points[size_t(i) * dim + j] = clampBelowOne((c[j] + kFaceMargin + (1.0 - 2.0 * kFaceMargin) * offset) / grid.g[j]);
        }
    }
    return points;
}

// The figure of merit is a proxy; the final choice among the best candidates measures the error itself: the mean
// squared error over kProbeShifts within-cell rotations on a few smooth non-periodic functions, each over jittered
// sampling's variance on the same grid (sum over cells of |grad f . cell|^2 / 12, over n^2). Measured in 2D, sets
// with close merits differ 3x-100x on these (the merit misses how the two digits' modes mix).
constexpr int kProbeShifts = 8;
// A grid whose best finalist's summed ratio exceeds this (a mean of 1/3 of jittered's MSE per function) is not
// used (the search then tries again). Measured: most 2:1 searches at N = 512 (32 x 16) reach only 3.4, square
// grids 0.01-0.1.
constexpr double kProbeLimit = 1.0;
// The probe functions' integrals over [0,1)^dim (closed forms; see probeError).
double probeIntegral(int dim, int which) {
    const double sqrtPi = 1.7724538509055160, twoPi = 6.283185307179586;
    if (which == 0) return std::pow(sqrtPi / 2.0 * std::erf(1.0), dim);
    if (which == 1) {
        double product = 1.0, s = std::sqrt(8.0);
        for (int k = 0; k < dim; ++k) {
            const double c = 0.35 + 0.25 * k;
            product *= sqrtPi / (2.0 * s) * (std::erf(s * (1.0 - c)) + std::erf(s * c));
        }
        return product;
    }
    // Re(e^{i 0.4} prod_k (e^{i a_k} - 1) / (i a_k)), a_k = 2 pi (1.3 - 0.6 k).
    double re = std::cos(0.4), im = std::sin(0.4);
    for (int k = 0; k < dim; ++k) {
        const double a = twoPi * (1.3 - 0.6 * k);
        const double fr = std::sin(a) / a, fi = (1.0 - std::cos(a)) / a; // (e^{ia} - 1) / (ia)
        const double r = re * fr - im * fi, i = re * fi + im * fr;
        re = r, im = i;
    }
    return re;
}

double probeError(const Grid& grid, const std::vector<float>& points, uint32_t n) {
    const int dim = grid.dim;
    // f and its gradient at p (dim 2 or 3; the third axis, if any, enters only the first two functions).
    const auto eval = [dim](const double* p, int which, double* grad) {
        double r2 = 0.0, v = 0.0;
        switch (which) {
        case 0: // exp(-|p|^2)
            for (int k = 0; k < dim; ++k) r2 += p[k] * p[k];
            v = std::exp(-r2);
            for (int k = 0; k < dim; ++k) grad[k] = -2.0 * p[k] * v;
            return v;
        case 1: // an off-centre Gaussian
            for (int k = 0; k < dim; ++k) r2 += (p[k] - 0.35 - 0.25 * k) * (p[k] - 0.35 - 0.25 * k);
            v = std::exp(-8.0 * r2);
            for (int k = 0; k < dim; ++k) grad[k] = -16.0 * (p[k] - 0.35 - 0.25 * k) * v;
            return v;
        default: { // an oblique oscillation
            double phase = 0.4;
            for (int k = 0; k < dim; ++k) phase += 2.0 * 3.141592653589793 * (1.3 - 0.6 * k) * p[k];
            for (int k = 0; k < dim; ++k) grad[k] = -std::sin(phase) * 2.0 * 3.141592653589793 * (1.3 - 0.6 * k);
            return std::cos(phase);
        }
        }
    };
    double total = 0.0;
    for (int which = 0; which < 3; ++which) {
        double jitter = 0.0, grad[3], p[3];
        for (uint32_t i = 0; i < n; ++i) {
            for (int k = 0; k < dim; ++k) {
                const double cell = std::floor(double(points[size_t(i) * dim + k]) * grid.g[k]);
                p[k] = (cell + 0.5) / grid.g[k];
            }
            eval(p, which, grad);
            for (int k = 0; k < dim; ++k) jitter += grad[k] * grad[k] / (12.0 * grid.g[k] * grid.g[k]);
        }
        jitter /= double(n) * n;
        double mse = 0.0;
        for (int t = 0; t < kProbeShifts; ++t) {
            const double tau[3] = {(t + 0.5) / kProbeShifts, fracOf(0.25 + t * 0.6180339887),
                                   fracOf(0.75 + t * 0.7548776662)};
            double sum = 0.0;
            for (uint32_t i = 0; i < n; ++i) {
                for (int k = 0; k < dim; ++k) {
                    const double x = double(points[size_t(i) * dim + k]) * grid.g[k];
                    const double cell = std::floor(x);
                    p[k] = (cell + fracOf(x - cell + tau[k])) / grid.g[k];
                }
                sum += eval(p, which, grad);
            }
            const double e = sum / n - probeIntegral(dim, which);
            mse += e * e / kProbeShifts;
        }
        total += mse / jitter;
    }
    return total;
}

} // namespace

double cellLatticeRhoFloor(int dim) { return dim == 2 ? 0.805 : 0.70; }

CellLattice generateCellLattice(int dim, uint32_t n, uint64_t seed) {
    CellLattice out;
    if (dim < 2 || dim > 3 || n < 2 || n > kMaxLatticePoints) return out;
    const double dmax = packingDistance(dim, n), floorRho = cellLatticeRhoFloor(dim);
    const double floor2 = floorRho * floorRho * dmax * dmax;
    // Every grid, up to kAttempts times (a search that misses may find on a fresh stream).
    SplitMix64 rng(deriveSeed(seed, 0xce11u));
    const std::vector<Grid> grids = gridsFor(dim, n);
    for (int attempt = 0; attempt < kAttempts; ++attempt)
    for (const Grid& grid : grids) {
        if (std::min(grid.g[0], grid.g[dim - 1]) < kMinCellsPerAxis) continue;
        Matrix best;
        double bestMerit = 1e300, bestRho = 0.0;
        uint32_t bestShared = ~0u;
        std::vector<std::pair<double, Matrix>> finalists; // (merit, matrix) with bestShared cells per offset
        // A first digit that reaches the floor alone, then second digits for it (none is a candidate too). Rounds of
        // kSearchBudget until every offset is shared by at most kMaxShared cells (or kSearchRounds are spent).
        for (uint32_t t = 0; t < kSearchBudget * kSearchRounds; ++t) {
            if (t > 0 && t % kSearchBudget == 0 && bestShared <= kMaxShared) break;
            Matrix a;
            for (int j = 0; j < dim; ++j)
                for (int k = 0; k < dim; ++k) a.z[j][k] = rng.uniformBelow(grid.g[k]);
            for (uint32_t trial = 0; trial <= kSecondDigitTrials; ++trial) {
                if (trial > 0)
                    for (int j = 0; j < dim; ++j)
                        for (int k = 0; k < dim; ++k) a.w[j][k] = rng.uniformBelow(grid.g[k]);
                const double d2 = worstDistance2(grid, a, floor2);
                if (d2 < floor2) {
                    if (trial == 0) break;
                    continue;
                }
                // Fewest cells sharing an offset first, then the merit (the cheaper test first once none can be
                // fewer).
                const double m = merit(grid, a);
                if (bestShared == 1 && m >= bestMerit) continue;
                const uint32_t shared = sharedOffsets(grid, a, bestShared);
                if (shared > bestShared) continue;
                if (shared < bestShared) finalists.clear();
                if (shared < bestShared || m < bestMerit)
                    bestShared = shared, bestMerit = m, bestRho = std::sqrt(d2) / dmax, best = a;
                finalists.push_back({m, a});
            }
        }
        if (bestRho == 0.0) continue;
        // The finalists with the best merits, by their measured error.
        std::stable_sort(finalists.begin(), finalists.end(),
                         [](const auto& x, const auto& y) { return x.first < y.first; });
        finalists.resize(std::min<size_t>(finalists.size(), kProbeCandidates));
        // The finalist with the least measured error (drawing one at random among those within kProbeLimit, for a
        // family of more varied lattices, measured no better on the battery's edges: the rho floor leaves every
        // lattice's rows at much the same angles).
        double bestProbe = 1e300;
        for (const auto& finalist : finalists) {
            const double probe = probeError(grid, latticePoints(grid, finalist.second, n), n);
            if (probe < bestProbe) bestProbe = probe, best = finalist.second;
        }
        if (bestProbe > kProbeLimit) continue; // not better than jittered on smooth functions: try again
        bestRho = std::sqrt(worstDistance2(grid, best, 0.0)) / dmax;
        out.points = latticePoints(grid, best, n);
        for (int k = 0; k < dim; ++k) out.cells[k] = grid.g[k];
        out.rho = bestRho;
        out.shared = bestShared;
        return out;
    }
    return out;
}

} // namespace stipple::detail::pointsets
