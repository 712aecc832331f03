// cell_lattice.cpp — "poisson" in 2D and 3D: Poisson-disk sets aligned with the domain, one point per cell.
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
// = 1, 2, ...): a mode near zero frequency lines the sawtooth up with the integrand's slow variation. A is chosen
// among those reaching the rho floor by a figure of merit that sums those modes' weights (their coherent sums over
// the whole grid, and over a plane of cells for an edge across axis j). One point per cell keeps stratified's
// variance bound; the sawtooth's cancellation is what makes it smaller.
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
constexpr uint32_t kMaxShared = 2;          // cells per offset value that end the search early
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

} // namespace

double cellLatticeRhoFloor(int dim) { return dim == 2 ? 0.805 : 0.70; }

CellLattice generateCellLattice(int dim, uint32_t n, uint64_t seed) {
    CellLattice out;
    if (dim < 2 || dim > 3 || n < 2 || n > kMaxPoints) return out;
    const double dmax = packingDistance(dim, n), floorRho = cellLatticeRhoFloor(dim);
    const double floor2 = floorRho * floorRho * dmax * dmax;
    SplitMix64 rng(deriveSeed(seed, 0xce11u));
    for (const Grid& grid : gridsFor(dim, n)) {
        if (std::min(grid.g[0], grid.g[dim - 1]) < kMinCellsPerAxis) continue;
        Matrix best;
        double bestMerit = 1e300, bestRho = 0.0;
        uint32_t bestShared = ~0u;
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
                if (shared < bestShared || m < bestMerit)
                    bestShared = shared, bestMerit = m, bestRho = std::sqrt(d2) / dmax, best = a;
            }
        }
        if (bestRho == 0.0) continue;
        // Offsets in exact integers: A_jk c_k = z_jk c_k (L / g_k) / L with L the grid's lcm, the second digit the
        // same over L^2, then half its step so that no stored point sits on a cell face.
        const uint64_t lcm = gridLcm(grid);
        out.points.resize(size_t(n) * dim);
        uint32_t c[3] = {0, 0, 0};
        for (uint32_t i = 0; i < n; ++i) {
            uint32_t rest = i;
            for (int k = 0; k < dim; ++k) c[k] = rest % grid.g[k], rest /= grid.g[k];
            for (int j = 0; j < dim; ++j) {
                uint64_t first = 0, second = 0;
                for (int k = 0; k < dim; ++k) {
                    first += uint64_t(best.z[j][k]) * c[k] % grid.g[k] * (lcm / grid.g[k]);
                    second += uint64_t(best.w[j][k]) * c[k] % grid.g[k] * (lcm / grid.g[k]);
                }
                const double offset = (double(first % lcm) + (double(second % lcm) + 0.5) / double(lcm)) / double(lcm);
                out.points[size_t(i) * dim + j] = clampBelowOne((c[j] + offset) / grid.g[j]);
            }
        }
        for (int k = 0; k < dim; ++k) out.cells[k] = grid.g[k];
        out.rho = bestRho;
        out.shared = bestShared;
        return out;
    }
    return out;
}

} // namespace stipple::detail::pointsets
