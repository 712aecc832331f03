// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// dart_grid.h — the neighbour search of the study's dart throwing (poisson_seed.cpp), in 1D, 2D and 3D.
//
// A uniform grid on the torus whose cells are no smaller than the starting radius: the radius only shrinks, so
// every accepted point closer than r to a dart lies in the dart's cell or one of its 3^D - 1 neighbours. Accepted
// points are chained per cell (a head per cell, a next per point): no allocation after construction.
//
// The test is the one the study's quadtree made, float for float: a stored point s is closer than r to p when,
// for some periodic image q = p + shift (shift in {-1, 0, 1}^D, q[k] = p[k] + shift[k] in float), the sum over k
// in order of (s[k] - q[k])^2 is below r^2. The image with the least term on each axis has the least sum (float
// addition is monotonic), so taking the least term per axis answers "some image is closer" exactly, and the
// answers, and so the sets, are those of the tree this grid replaced, for every seed. In 1D the test is
// |torusDelta(p, s)| < r, exact on the 2^-24 grid the darts lie on, as the sorted set it replaced made it.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace stipple::detail::pointsets {

template <int D>
class DartGrid {
public:
    using Point = std::array<float, D>;

    // capacity: the points that will be inserted; startRadius: the largest radius that will be queried.
    DartGrid(uint32_t capacity, float startRadius) {
        side_ = std::max(1, int(std::floor(1.0 / double(startRadius))));
        size_t cells = 1;
        for (int k = 0; k < D; ++k) cells *= size_t(side_);
        head_.assign(cells, kNone);
        next_.reserve(capacity);
        points_.reserve(capacity);
    }

    void insert(const Point& p) {
        const size_t cell = cellOf(p);
        next_.push_back(head_[cell]);
        head_[cell] = uint32_t(points_.size());
        points_.push_back(p);
    }

    // True if a stored point lies at toroidal distance < r from p (r <= startRadius <= 0.5).
    bool anyWithin(const Point& p, float r) const {
        const float r2 = r * r;
        if (side_ < 3) { // the neighbourhood would wrap onto itself: every point is a neighbour
            for (const Point& s : points_)
                if (closer(s, p, r, r2)) return true;
            return false;
        }
        // The dart's cell and its neighbours on each axis, wrapped.
        std::array<std::array<uint32_t, 3>, D> axis;
        for (int k = 0; k < D; ++k) {
            const int c = axisCell(p[k]);
            axis[k] = {uint32_t(c == 0 ? side_ - 1 : c - 1), uint32_t(c), uint32_t(c == side_ - 1 ? 0 : c + 1)};
        }
        const uint32_t side = uint32_t(side_);
        if constexpr (D == 1) {
            for (uint32_t x : axis[0])
                if (anyInCell(x, p, r, r2)) return true;
        } else if constexpr (D == 2) {
            for (uint32_t y : axis[1])
                for (uint32_t x : axis[0])
                    if (anyInCell(y * side + x, p, r, r2)) return true;
        } else {
            for (uint32_t z : axis[2])
                for (uint32_t y : axis[1])
                    for (uint32_t x : axis[0])
                        if (anyInCell((size_t(z) * side + y) * side + x, p, r, r2)) return true;
        }
        return false;
    }

    const std::vector<Point>& points() const { return points_; }

private:
    static constexpr uint32_t kNone = UINT32_MAX;

    bool anyInCell(size_t cell, const Point& p, float r, float r2) const {
        for (uint32_t i = head_[cell]; i != kNone; i = next_[i])
            if (closer(points_[i], p, r, r2)) return true;
        return false;
    }

    // The least-distance periodic image's squared distance below r2, in the tree's arithmetic (see above).
    static bool closer(const Point& s, const Point& p, float r, float r2) {
        if constexpr (D == 1) {
            // torusDelta(p, s) without its call to nearbyint: d lies in (-1, 1), so rounding it to the nearest
            // integer (ties to even, 0) is these two comparisons.
            const float d = p[0] - s[0];
            return std::fabs(d > 0.5f ? d - 1.0f : (d < -0.5f ? d + 1.0f : d)) < r;
        }
        float e2 = 0.0f;
        for (int k = 0; k < D; ++k) {
            const float t = std::min({std::fabs(s[k] - p[k]), std::fabs(s[k] - (p[k] - 1.0f)),
                                      std::fabs(s[k] - (p[k] + 1.0f))});
            e2 += t * t;
        }
        return e2 < r2;
    }

    int axisCell(float x) const { return std::min(side_ - 1, int(x * float(side_))); }

    size_t cellOf(const Point& p) const {
        size_t cell = 0;
        for (int k = D - 1; k >= 0; --k) cell = cell * size_t(side_) + size_t(axisCell(p[k]));
        return cell;
    }

    int side_ = 1;
    std::vector<uint32_t> head_; // per cell: the last point inserted into it, kNone if empty
    std::vector<uint32_t> next_; // per point: the point inserted into its cell before it
    std::vector<Point> points_;  // in insertion order
};

} // namespace stipple::detail::pointsets
