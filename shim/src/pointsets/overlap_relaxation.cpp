// overlap_relaxation.cpp — see overlap_relaxation.h.
//
// Pairs come from a uniform grid of g^D cells of side >= R, rebuilt by a counting sort before every pass
// (cheap next to the pass, and it keeps points in memory order). Each unordered pair of neighbouring
// cells is visited once through the forward half of the 3^D stencil; g >= 3 makes the 3^D cells around
// a cell distinct on the torus. Smaller sets (g < 3, i.e. N below ~16 in 2D) test all pairs.
//
// Measured alternatives that lost (POINTSETS.md): Verlet neighbour lists with an active set (list
// rebuilds cost more than they save, since points keep moving until the end), uniform random starts
// (need long-range transport: 4x more passes than a jittered start).
#include "overlap_relaxation.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "cell_grid.h"
#include "torus.h"

namespace stipple::pointsets {
namespace {

// Minimum-image difference for |d| < 1.5 (coordinates drift slightly outside [0,1) within a pass).
inline float nearImage(float d) { return d - float(int(d + 2.5f) - 2); }

// The forward half of the 3^D neighbourhood: offsets o > 0 in lexicographic order, last axis major.
template <int D>
constexpr auto halfStencil() {
    std::array<std::array<int, D>, D == 2 ? 4 : 13> out{};
    int count = 0;
    for (int code = 0; code < (D == 2 ? 9 : 27); ++code) {
        std::array<int, D> o{};
        for (int k = 0, rest = code; k < D; ++k, rest /= 3) o[k] = rest % 3 - 1;
        int sign = 0;
        for (int k = D - 1; k >= 0 && sign == 0; --k) sign = o[k];
        if (sign > 0) out[count++] = o;
    }
    return out;
}

template <int D>
struct Pass {
    float R, R2, halfOmega;
    float min2 = 1e30f;

    // Pushes p and q apart by omega * half the overlap each; shift is the periodic image of q to use.
    inline void relaxPair(float *p, float *q, const float *shift) {
        float delta[D], d2 = 0.0f;
        for (int k = 0; k < D; ++k) {
            delta[k] = p[k] - q[k] - shift[k];
            d2 += delta[k] * delta[k];
        }
        min2 = std::min(min2, d2);
        if (d2 >= R2) return;
        float d = std::sqrt(d2);
        // Coincident points (d = 0) are left for a later pass: a neighbour will have moved one of them.
        float s = d > 0.0f ? halfOmega * (R - d) / d : 0.0f;
        for (int k = 0; k < D; ++k) {
            p[k] += s * delta[k];
            q[k] -= s * delta[k];
        }
    }
};

template <int D>
float gridPass(std::vector<float> &pts, uint32_t n, Pass<D> pass, int g, CellGrid<D> &grid) {
    static constexpr auto stencil = halfStencil<D>();
    grid.build(pts.data(), n, g);
    std::swap(pts, grid.sorted);  // work in cell order; the order of a set carries no meaning
    float *P = pts.data();
    const uint32_t *start = grid.cellStart.data();
    const uint32_t cells = uint32_t(grid.cellStart.size() - 1);
    const float noShift[D] = {};
    int c[D] = {};
    for (uint32_t cell = 0; cell < cells; ++cell) {
        const uint32_t begin = start[cell], end = start[cell + 1];
        if (begin != end) {
            for (uint32_t i = begin; i < end; ++i)
                for (uint32_t j = i + 1; j < end; ++j) pass.relaxPair(P + size_t(i) * D, P + size_t(j) * D, noShift);
            for (const auto &o : stencil) {
                int nc[D];
                float shift[D];
                for (int k = 0; k < D; ++k) {
                    nc[k] = c[k] + o[k];
                    shift[k] = nc[k] < 0 ? -1.0f : (nc[k] >= g ? 1.0f : 0.0f);
                    nc[k] -= int(shift[k]) * g;
                }
                const uint32_t other = grid.cellIndex(nc), obegin = start[other], oend = start[other + 1];
                for (uint32_t i = begin; i < end; ++i)
                    for (uint32_t j = obegin; j < oend; ++j) pass.relaxPair(P + size_t(i) * D, P + size_t(j) * D, shift);
            }
        }
        for (int k = 0; k < D && ++c[k] == g; ++k) c[k] = 0;  // next cell, first axis fastest
    }
    return pass.min2;
}

template <int D>
float allPairsPass(std::vector<float> &pts, uint32_t n, Pass<D> pass) {
    for (uint32_t i = 0; i < n; ++i)
        for (uint32_t j = i + 1; j < n; ++j) {
            float *p = &pts[size_t(i) * D], *q = &pts[size_t(j) * D];
            float shift[D];
            for (int k = 0; k < D; ++k) shift[k] = (p[k] - q[k]) - nearImage(p[k] - q[k]);
            pass.relaxPair(p, q, shift);
        }
    return pass.min2;
}

}  // namespace

template <int D>
RelaxStats relaxOverlaps(std::vector<float> &pts, uint32_t n, const RelaxParams &params) {
    RelaxStats stats;
    if (n < 2) {
        stats.verified = true;
        return stats;
    }
    const Pass<D> pass{params.diameter, params.diameter * params.diameter, 0.5f * params.omega};
    const Pass<D> measure{0.0f, 0.0f, 0.0f};  // pushes nothing: the exact minimum pair distance
    const float target2 = params.target * params.target, accept2 = params.accept * params.accept;
    const int g = int(std::floor(1.0 / double(params.diameter)));
    CellGrid<D> grid;
    auto run = [&](const Pass<D> &p) {
        float min2 = g >= 3 ? gridPass<D>(pts, n, p, g, grid) : allPairsPass<D>(pts, n, p);
        for (float &x : pts) x = wrapUnit(x);
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
    stats.minDistance = std::sqrt(run(measure));  // not verified: still report the exact minimum
    return stats;
}

template RelaxStats relaxOverlaps<2>(std::vector<float> &, uint32_t, const RelaxParams &);
template RelaxStats relaxOverlaps<3>(std::vector<float> &, uint32_t, const RelaxParams &);

}  // namespace stipple::pointsets
