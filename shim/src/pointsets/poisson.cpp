// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// poisson.cpp — "poisson" in 2D and 3D: near-maximal Poisson-disk sets of exactly N points on the unit torus.
//
// Random sequential adsorption (dart throwing at a fixed radius r, Lagae & Dutre 2008) run until N points are
// accepted. Jammed dart throwing (a maximal Poisson-disk set, Gamito & Maddock 2009) covers 0.547 of the square and
// 0.384 of the cube with its disks of diameter r; N points at r = 0.76 d_max (2D) cover 0.524, at 0.72 d_max (3D)
// 0.276, so a run reaches N before it jams (a finite torus sometimes does not: the run is redrawn). The darts are
// uniform over the cells of a grid of side r / sqrt(D) that hold no point yet and are not covered by a single disk
// (a cell holding a point is covered by it); when misses pile up, the remaining cells are halved and the halves a
// single disk covers dropped (Ebeida et al. 2011). Every dart is thus uniform over a region containing all the free
// space: the process is exactly dart throwing, only without most of the misses. The result has a blue-noise spectrum
// with a low, broad ring and no preferred direction (POINTSETS.md, "Spectra"); nothing relaxes it towards order.
//
// 1D is different (cell_set_1d.cpp): one point per cell, served with whole-cell shifts.
#include "pointsets.h"

#include <algorithm>
#include <cmath>

#include "random.h"
#include "torus.h"

namespace stipple::detail::pointsets {

double poissonRadius(int dim) { return dim == 2 ? 0.76 : dim == 3 ? 0.72 : 0.2; }

namespace {

constexpr uint32_t kNoPoint = 0xffffffffu;

template <int D>
class Adsorption {
public:
    Adsorption(uint32_t n, double r) : n_(n), r2_(float(r * r)) {
        g_ = std::max(1, int(std::ceil(std::sqrt(double(D)) / r)));
        // A cell of side 1/g <= r / sqrt(D) holds at most one point; its neighbours within r lie at most
        // `reach` cells away on each axis (at most g / 2: then the scan already wraps over every cell).
        reach_ = std::min(int(std::ceil(r * g_)), g_ / 2);
        size_t cells = 1;
        for (int k = 0; k < D; ++k) cells *= size_t(g_);
        owner_.assign(cells, kNoPoint);
        free_.resize(cells * D);
        for (size_t c = 0; c < cells; ++c) {
            size_t rest = c;
            for (int k = 0; k < D; ++k, rest /= size_t(g_)) free_[c * D + k] = uint32_t(rest % size_t(g_));
        }
        points_.reserve(size_t(n) * D);
    }

    // Throws darts until n points (true) or until no candidate region is left (jammed, false).
    bool run(SplitMix64& rng) {
        uint64_t missesSinceRefinement = 0;
        while (points_.size() < size_t(n_) * D) {
            const size_t regions = free_.size() / D;
            if (regions == 0) return false; // jammed
            // Misses outnumber the regions: most of them are covered by several disks together, which the
            // single-disk test below cannot see. Halving them (dropping the halves one disk covers) finds them.
            if (missesSinceRefinement > 2 * regions + 64) {
                if (level_ == kMaxLevel) return false; // regions 2^-10 of a cell and still missing: jammed
                refine();
                missesSinceRefinement = 0;
                continue;
            }
            const size_t slot = rng.uniformBelow(uint32_t(regions));
            const uint32_t* region = free_.data() + slot * D;
            const double side = 1.0 / (double(g_) * double(1u << level_));
            float p[D];
            int cell[D];
            for (int k = 0; k < D; ++k) {
                p[k] = clampBelowOne((region[k] + rng.uniformDouble()) * side);
                cell[k] = int(region[k] >> level_);
            }
            if (!conflicts(p, cell)) {
                owner_[encode(cell)] = uint32_t(points_.size() / D);
                points_.insert(points_.end(), p, p + D);
                dropRegion(slot); // the other regions of its cell lie within r of it: they go at their next miss
                continue;
            }
            ++missesSinceRefinement;
            if (covered(region, level_)) dropRegion(slot);
        }
        return true;
    }

    std::vector<float>& points() { return points_; }

private:
    static constexpr int kMaxLevel = 10;

    uint32_t encode(const int* c) const {
        uint32_t index = 0;
        for (int k = D - 1; k >= 0; --k) index = index * uint32_t(g_) + uint32_t(c[k]);
        return index;
    }
    void dropRegion(size_t slot) {
        for (int k = 0; k < D; ++k) free_[slot * D + k] = free_[free_.size() - D + k];
        free_.resize(free_.size() - D);
    }
    // Every region split into its 2^D halves, keeping those no single disk covers.
    void refine() {
        std::vector<uint32_t> next;
        next.reserve(free_.size() * 2);
        ++level_;
        for (size_t i = 0; i < free_.size(); i += D)
            for (int child = 0; child < (1 << D); ++child) {
                uint32_t q[D];
                for (int k = 0; k < D; ++k) q[k] = 2 * free_[i + k] + ((child >> k) & 1);
                if (!covered(q, level_)) next.insert(next.end(), q, q + D);
            }
        free_.swap(next);
    }
    // True if f(point index) holds for a point in the cells within reach of cell c (toroidal).
    template <class F>
    bool anyNear(const int* c, F&& f) const {
        const int span = 2 * reach_ + 1;
        int total = 1;
        for (int k = 0; k < D; ++k) total *= span;
        for (int t = 0; t < total; ++t) {
            int q[D], rest = t;
            for (int k = 0; k < D; ++k, rest /= span) {
                q[k] = c[k] + rest % span - reach_;
                q[k] = q[k] < 0 ? q[k] + g_ : q[k] >= g_ ? q[k] - g_ : q[k];
            }
            const uint32_t owner = owner_[encode(q)];
            if (owner != kNoPoint && f(owner)) return true;
        }
        return false;
    }
    float distance2(const float* a, const float* b) const {
        float d2 = 0.0f;
        for (int k = 0; k < D; ++k) {
            const float d = torusDelta(a[k], b[k]);
            d2 += d * d;
        }
        return d2;
    }
    bool conflicts(const float* p, const int* c) const {
        return anyNear(c, [&](uint32_t i) { return distance2(p, points_.data() + size_t(i) * D) < r2_; });
    }
    // True if one accepted point is within r of every corner of the region (a disk is convex: the region is inside
    // it). Regions of a cell at any level lie in that cell, so the cell's neighbourhood holds every such point.
    bool covered(const uint32_t* region, int level) const {
        int cell[D];
        for (int k = 0; k < D; ++k) cell[k] = int(region[k] >> level);
        const double side = 1.0 / (double(g_) * double(1u << level));
        return anyNear(cell, [&](uint32_t i) {
            for (int corner = 0; corner < (1 << D); ++corner) {
                float q[D];
                for (int k = 0; k < D; ++k) q[k] = float(double(region[k] + ((corner >> k) & 1)) * side);
                if (distance2(q, points_.data() + size_t(i) * D) >= r2_) return false;
            }
            return true;
        });
    }

    uint32_t n_;
    float r2_;
    int g_ = 1, reach_ = 1, level_ = 0;
    std::vector<uint32_t> owner_; // per cell: its point, or kNoPoint
    std::vector<uint32_t> free_;  // regions (D coordinates each, at level_) that may still take a point
    std::vector<float> points_;
};

template <int D>
std::vector<float> adsorbedSet(uint32_t n, uint64_t seed) {
    // A run that jams (or refines its regions kMaxLevel times, which near jamming means the same) is redrawn from
    // a derived seed; every fourth failure lowers the radius by 1% (tiny tori, where N disks of the nominal radius
    // barely fit, e.g. N = 2..4).
    double r = poissonRadius(D) * packingDistance(D, n);
    for (uint64_t attempt = 0;; ++attempt) {
        if (attempt > 0 && attempt % 4 == 0) r *= 0.99;
        SplitMix64 rng(deriveSeed(seed, attempt));
        Adsorption<D> run(n, r);
        if (run.run(rng)) return std::move(run.points());
    }
}

} // namespace

std::vector<float> generatePoisson(int dim, uint32_t n, uint64_t seed) {
    if (n == 0 || n > kMaxPoints || dim < 1 || dim > 3) return {};
    if (dim == 1) return generateCellSet1D(n, seed);
    const uint64_t stream = deriveSeed(seed, 0x9015500u + uint64_t(dim));
    return dim == 2 ? adsorbedSet<2>(n, stream) : adsorbedSet<3>(n, stream);
}

} // namespace stipple::detail::pointsets
