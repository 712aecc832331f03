// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// overlap_relaxation.cpp — see overlap_relaxation.h.
//
// Pairs come from a uniform grid of g^D cells of side >= R, rebuilt by a counting sort before every pass
// (cheap next to the pass, and it keeps points in memory order). Each unordered pair of neighbouring
// cells is visited once through the forward half of the 3^D stencil, walked as runs of consecutive slots
// (three cells of a row are adjacent in memory), so each point meets a handful of runs rather than 13 (3D)
// cell look-ups; g >= 3 makes the 3^D cells around a cell distinct on the torus. Smaller sets (g < 3, i.e.
// N below ~16 in 2D) test all pairs.
//
// Measured alternatives that lost (POINTSETS.md): Verlet neighbour lists with an active set (list
// rebuilds cost more than they save, since points keep moving until the end), uniform random starts
// (need long-range transport: 4x more passes than a jittered start), branch-free pushes (slower: every
// pair then pays the square root and division).
#include "overlap_relaxation.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "cell_grid.h"
#include "torus.h"

namespace stipple::detail::pointsets {
namespace {

// Minimum-image difference for |d| < 1.5 (coordinates drift slightly outside [0,1) within a pass).
inline float nearImage(float d) { return d - float(int(d + 2.5f) - 2); }

template <int D>
struct Pass {
    float R, R2, halfOmega;
    float min2 = 1e30f;

    // Point i against the points of slots [begin, end), all seen through the same periodic image `shift`
    // of theirs: every pair closer than R is pushed apart by omega * half its overlap at each end. Each
    // q moves at once, but p's pushes are summed and applied after the run: the pairs of one run then
    // share no dependency chain (the sqrt and division of one pair no longer wait for the last), which
    // is most of a pass's time. Each q still sees every earlier push, so the pass stays Gauss-Seidel
    // between runs.
    inline void relaxRange(float* P, uint32_t i, uint32_t begin, uint32_t end, const float* shift) {
        float* p = P + size_t(i) * D;
        float base[D], push[D] = {};
        for (int k = 0; k < D; ++k) base[k] = p[k] - shift[k];
        for (uint32_t j = begin; j < end; ++j) {
            float* q = P + size_t(j) * D;
            float delta[D], d2 = 0.0f;
            for (int k = 0; k < D; ++k) {
                delta[k] = base[k] - q[k];
                d2 += delta[k] * delta[k];
            }
            min2 = std::min(min2, d2);
            if (d2 >= R2 || d2 == 0.0f) continue; // coincident points: a neighbour's push separates them
            const float s = halfOmega * (R / std::sqrt(d2) - 1.0f);
            for (int k = 0; k < D; ++k) {
                push[k] += s * delta[k];
                q[k] -= s * delta[k];
            }
        }
        for (int k = 0; k < D; ++k) p[k] += push[k];
    }
};

// The forward half of the 3^D stencil as rows along the first axis: the rest of the own row (cell x+1,
// after the point itself) and, for each forward row offset, the three cells x-1..x+1 of that row. Cells
// are stored first axis fastest, so away from the seam each of these is one contiguous run of slots.
template <int D>
constexpr auto forwardRows() {
    std::array<std::array<int, D - 1>, D == 2 ? 1 : 4> out{};
    int count = 0;
    for (int code = 0; code < (D == 2 ? 3 : 9); ++code) {
        std::array<int, D - 1> o{};
        for (int k = 0, rest = code; k < D - 1; ++k, rest /= 3) o[k] = rest % 3 - 1;
        int sign = 0;
        for (int k = D - 2; k >= 0 && sign == 0; --k) sign = o[k];
        if (sign > 0) out[count++] = o;
    }
    return out;
}

template <int D>
float gridPass(std::vector<float>& pts, uint32_t n, Pass<D> pass, int g, CellGrid<D>& grid) {
    static constexpr auto rows = forwardRows<D>();
    grid.build(pts.data(), n, g);
    std::swap(pts, grid.sorted); // work in cell order; the order of a set carries no meaning
    float* P = pts.data();
    const uint32_t* start = grid.cellStart.data();
    const float noShift[D] = {};
    int c[D] = {}; // the current cell; c[0] is x
    const uint32_t cells = uint32_t(grid.cellStart.size() - 1);
    for (uint32_t cell = 0; cell < cells; ++cell) {
        const uint32_t begin = start[cell], end = start[cell + 1];
        if (begin != end) {
            const int x = c[0];
            // The rest of the own row: cell x+1 is the next cell in memory unless x is the last column.
            if (x + 1 < g) {
                const uint32_t rowEnd = start[cell + 2];
                for (uint32_t i = begin; i < end; ++i) pass.relaxRange(P, i, i + 1, rowEnd, noShift);
            } else {
                float shift[D] = {1.0f};
                const uint32_t first = cell + 1 - uint32_t(g), fb = start[first], fe = start[first + 1];
                for (uint32_t i = begin; i < end; ++i) {
                    pass.relaxRange(P, i, i + 1, end, noShift);
                    pass.relaxRange(P, i, fb, fe, shift);
                }
            }
            for (const auto& o : rows) {
                int nc[D];
                float shift[D] = {};
                nc[0] = x;
                for (int k = 1; k < D; ++k) {
                    nc[k] = c[k] + o[k - 1];
                    shift[k] = nc[k] < 0 ? -1.0f : (nc[k] >= g ? 1.0f : 0.0f);
                    nc[k] -= int(shift[k]) * g;
                }
                const uint32_t mid = grid.cellIndex(nc); // cell x of the neighbouring row
                if (x >= 1 && x + 1 < g) {
                    const uint32_t rb = start[mid - 1], re = start[mid + 2];
                    for (uint32_t i = begin; i < end; ++i) pass.relaxRange(P, i, rb, re, shift);
                    continue;
                }
                for (int dx = -1; dx <= 1; ++dx) { // at the seam, cell by cell with its own image
                    int nx = x + dx;
                    shift[0] = nx < 0 ? -1.0f : (nx >= g ? 1.0f : 0.0f);
                    nx -= int(shift[0]) * g;
                    const uint32_t other = mid - uint32_t(x) + uint32_t(nx);
                    for (uint32_t i = begin; i < end; ++i) pass.relaxRange(P, i, start[other], start[other + 1], shift);
                }
            }
        }
        for (int k = 0; k < D && ++c[k] == g; ++k) c[k] = 0; // next cell, first axis fastest
    }
    return pass.min2;
}

template <int D>
float allPairsPass(std::vector<float>& pts, uint32_t n, Pass<D> pass) {
    float* P = pts.data();
    for (uint32_t i = 0; i < n; ++i)
        for (uint32_t j = i + 1; j < n; ++j) {
            float shift[D];
            for (int k = 0; k < D; ++k) {
                const float d = P[size_t(i) * D + k] - P[size_t(j) * D + k];
                shift[k] = d - nearImage(d);
            }
            pass.relaxRange(P, i, j, j + 1, shift);
        }
    return pass.min2;
}

} // namespace

template <int D>
RelaxStats relaxOverlaps(std::vector<float>& pts, uint32_t n, const RelaxParams& params) {
    RelaxStats stats;
    if (n < 2) {
        stats.verified = true;
        return stats;
    }
    const Pass<D> pass{params.diameter, params.diameter * params.diameter, 0.5f * params.omega};
    const Pass<D> measure{0.0f, 0.0f, 0.0f}; // pushes nothing: the exact minimum pair distance
    const float target2 = params.target * params.target, accept2 = params.accept * params.accept;
    const int g = int(std::floor(1.0 / double(params.diameter)));
    CellGrid<D> grid;
    auto run = [&](const Pass<D>& p) {
        float min2 = g >= 3 ? gridPass<D>(pts, n, p, g, grid) : allPairsPass<D>(pts, n, p);
        for (float& x : pts) x = wrapUnit(x);
        return min2;
    };
    while (stats.passes < params.maxPasses) {
        ++stats.passes;
        float min2 = run(pass);
        stats.minDistance = std::sqrt(min2);
        if (min2 < target2) continue;
        // A pass measures each pair before later pushes in the same pass move it: confirm exactly.
        min2 = run(measure);
        stats.minDistance = std::sqrt(min2);
        if (min2 >= accept2) {
            stats.verified = true;
            return stats;
        }
    }
    if (params.measureUnverified) stats.minDistance = std::sqrt(run(measure)); // the exact minimum, unverified
    return stats;
}

template RelaxStats relaxOverlaps<2>(std::vector<float>&, uint32_t, const RelaxParams&);
template RelaxStats relaxOverlaps<3>(std::vector<float>&, uint32_t, const RelaxParams&);

} // namespace stipple::detail::pointsets
