// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// relative_radius.cpp — toroidal nearest-neighbour distances and the relative radius rho = d_min / d_max.
//
// Nearest neighbours by a cell grid (about one point per cell) searched in growing rings of cells: after
// ring k every unvisited point is at least k cell widths away, so the search stops as soon as the best
// distance found is within that. O(n) for well-spread sets, still exact for clustered ones.
#include "pointsets.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cell_grid.h"
#include "torus.h"

namespace stipple::detail::pointsets {
namespace {

template <int D>
std::vector<double> nearestNeighbourDistances(const float* points, uint32_t n) {
    std::vector<double> nearest(n, 1.0); // n = 1: the point's own periodic image at distance 1
    if (n < 2) return nearest;
    int g = std::max(1, int(std::floor(std::pow(double(n), 1.0 / D))));
    g = std::min(g, D == 1 ? (1 << 22) : D == 2 ? 2048 : 160);
    CellGrid<D> grid;
    grid.build(points, n, g);
    const double cell = 1.0 / g;
    for (uint32_t slot = 0; slot < n; ++slot) {
        const float* p = &grid.sorted[size_t(slot) * D];
        int home[D];
        for (int k = 0; k < D; ++k) home[k] = CellGrid<D>::cellOf(p[k], g);
        double best2 = std::numeric_limits<double>::infinity();
        for (int ring = 0;; ++ring) {
            // Visit the cells whose Chebyshev offset from home is exactly `ring`.
            int span = 2 * ring + 1;
            int total = 1;
            for (int k = 0; k < D; ++k) total *= span;
            for (int code = 0; code < total; ++code) {
                int offset[D], c[D], cheb = 0;
                for (int k = 0, rest = code; k < D; ++k, rest /= span) {
                    offset[k] = rest % span - ring;
                    cheb = std::max(cheb, std::abs(offset[k]));
                    c[k] = ((home[k] + offset[k]) % g + g) % g;
                }
                if (cheb != ring) continue;
                uint32_t cellIndex = grid.cellIndex(c);
                for (uint32_t other = grid.cellStart[cellIndex]; other < grid.cellStart[cellIndex + 1]; ++other) {
                    if (other == slot) continue;
                    const float* q = &grid.sorted[size_t(other) * D];
                    double d2 = 0.0;
                    for (int k = 0; k < D; ++k) {
                        double d = torusDelta(p[k], q[k]);
                        d2 += d * d;
                    }
                    best2 = std::min(best2, d2);
                }
            }
            if (span >= g) break; // every cell visited
            double reach = ring * cell;
            if (best2 <= reach * reach) break;
        }
        nearest[grid.order[slot]] = std::min(1.0, std::sqrt(best2));
    }
    return nearest;
}

std::vector<double> nearestNeighbourDistances(int dim, const float* points, uint32_t n) {
    switch (dim) {
    case 1: return nearestNeighbourDistances<1>(points, n);
    case 2: return nearestNeighbourDistances<2>(points, n);
    default: return nearestNeighbourDistances<3>(points, n);
    }
}

} // namespace

double maxPackingDistance(int dim, uint32_t n) { return packingDistance(dim, n); }

double relativeRadius(int dim, const float* points, uint32_t n) {
    if (n == 0 || n > kMaxPoints || points == nullptr || dim < 1 || dim > 3) return 0.0;
    std::vector<double> nearest = nearestNeighbourDistances(dim, points, n);
    return *std::min_element(nearest.begin(), nearest.end()) / packingDistance(dim, n);
}

double meanNearestNeighbourRadius(int dim, const float* points, uint32_t n) {
    if (n == 0 || n > kMaxPoints || points == nullptr || dim < 1 || dim > 3) return 0.0;
    std::vector<double> nearest = nearestNeighbourDistances(dim, points, n);
    double sum = 0.0;
    for (double d : nearest) sum += d;
    return sum / double(n) / packingDistance(dim, n);
}

} // namespace stipple::detail::pointsets
