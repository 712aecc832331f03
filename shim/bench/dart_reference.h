// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// dart_reference.h — plain dart throwing on the unit torus at a given radius, written independently of the library
// (its own RNG, grid and region bookkeeping) so that shim_spectrum can set the library's served sets beside fresh
// sets of the same process: a reference, not a sampler.
//
// Random sequential adsorption until n points are accepted: uniform candidates, rejected when closer than r (toroidal)
// to an accepted point. Candidates are drawn uniformly from a set of active squares (cubes) that always covers the
// uncovered region: a grid of cells of side <= r / sqrt(D) to start with; a candidate rejected inside a region
// splits it into 2^D children, and a child whose corners all lie within r of one accepted point (so all of it does)
// is dropped. Drawing uniformly over the active union and rejecting covered points is exactly uniform over the
// uncovered region, as plain throwing is. A run that jams before n points starts again from the next seed.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace stipple::bench {

template <int D>
class DartThrowing {
public:
    // n points at radius r; returns false if the torus jammed first.
    DartThrowing(uint32_t n, double r, uint64_t seed) : n_(n), r_(r), rng_(seed) {
        g_ = std::max(1, int(std::floor(std::sqrt(double(D)) / r)));   // region side 1/g <= r / sqrt(D)
        lookup_ = std::max(1, int(std::floor(1 / r)));                  // neighbour cells of side >= r
        cells_.assign(size_t(std::pow(double(lookup_), D)), {});
        levels_.assign(1, {});
        std::array<int64_t, D> c{};
        const size_t count = size_t(std::pow(double(g_), D));
        levels_[0].reserve(count);
        for (size_t i = 0; i < count; ++i) {
            size_t rest = i;
            for (int k = 0; k < D; ++k) {
                c[k] = int64_t(rest % size_t(g_));
                rest /= size_t(g_);
            }
            levels_[0].push_back(c);
        }
    }

    bool run() {
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        uint64_t rejections = 0;
        while (points_.size() < size_t(n_) * D) {
            if (rejections > kMaxRejections) return false; // jammed, up to regions too small to matter
            // A level with probability proportional to its active volume, then a region of it uniformly.
            double total = 0;
            for (size_t l = 0; l < levels_.size(); ++l) total += double(levels_[l].size()) * volume(int(l));
            if (total <= 0) return false;
            double pick = unit(rng_) * total;
            size_t level = 0;
            for (; level + 1 < levels_.size(); ++level) {
                pick -= double(levels_[level].size()) * volume(int(level));
                if (pick < 0) break;
            }
            if (levels_[level].empty()) continue;
            std::uniform_int_distribution<size_t> which(0, levels_[level].size() - 1);
            const size_t index = which(rng_);
            const std::array<int64_t, D> region = levels_[level][index];
            const double side = 1.0 / (double(g_) * double(int64_t(1) << level));
            std::array<double, D> x;
            for (int k = 0; k < D; ++k) x[k] = std::min((double(region[k]) + unit(rng_)) * side, std::nextafter(1.0, 0.0));
            if (!covered(x)) {
                accept(x);
                continue;
            }
            ++rejections;
            // Rejected: split the region, keeping the children not wholly covered by one point's disk.
            levels_[level][index] = levels_[level].back();
            levels_[level].pop_back();
            if (level + 1 >= kMaxLevels) {
                levels_[level].push_back(region); // keep it whole: tiny, exact either way
                continue;
            }
            if (levels_.size() <= level + 1) levels_.resize(level + 2);
            for (int child = 0; child < (1 << D); ++child) {
                std::array<int64_t, D> c;
                for (int k = 0; k < D; ++k) c[k] = 2 * region[k] + ((child >> k) & 1);
                if (!wholly(c, int(level + 1))) levels_[level + 1].push_back(c);
            }
        }
        return true;
    }

    const std::vector<float>& points() const { return points_; }

private:
    static constexpr size_t kMaxLevels = 16;
    static constexpr uint64_t kMaxRejections = 50'000'000;

    double volume(int level) const { return std::pow(1.0 / (double(g_) * double(int64_t(1) << level)), D); }

    static double wrap(double d) { return d - std::round(d); }

    int cellOf(double v) const { return std::min(lookup_ - 1, int(v * lookup_)); }

    // Calls f(point index) for the points in the 3^D lookup cells round x.
    template <class F>
    bool anyNear(const std::array<double, D>& x, F f) const {
        std::array<int, D> c;
        for (int k = 0; k < D; ++k) c[k] = cellOf(x[k]);
        const int span = lookup_ < 3 ? lookup_ : 3;
        for (int o = 0; o < int(std::pow(double(span), D)); ++o) {
            size_t cell = 0, stride = 1;
            int rest = o;
            for (int k = 0; k < D; ++k) {
                const int d = rest % span - (span == 3 ? 1 : 0);
                rest /= span;
                cell += size_t(((c[k] + d) % lookup_ + lookup_) % lookup_) * stride;
                stride *= size_t(lookup_);
            }
            for (uint32_t i : cells_[cell])
                if (f(i)) return true;
        }
        return false;
    }

    double distance2(const std::array<double, D>& x, uint32_t i) const {
        double s = 0;
        for (int k = 0; k < D; ++k) {
            const double d = wrap(x[k] - double(points_[size_t(i) * D + k]));
            s += d * d;
        }
        return s;
    }

    bool covered(const std::array<double, D>& x) const {
        return anyNear(x, [&](uint32_t i) { return distance2(x, i) < r_ * r_; });
    }

    // Every corner of region c (at `level`) within r of one point: the convex region lies in that point's disk.
    bool wholly(const std::array<int64_t, D>& c, int level) const {
        const double side = 1.0 / (double(g_) * double(int64_t(1) << level));
        std::array<double, D> centre;
        for (int k = 0; k < D; ++k) centre[k] = (double(c[k]) + 0.5) * side;
        return anyNear(centre, [&](uint32_t i) {
            for (int corner = 0; corner < (1 << D); ++corner) {
                std::array<double, D> q;
                for (int k = 0; k < D; ++k) q[k] = (double(c[k]) + ((corner >> k) & 1)) * side;
                if (distance2(q, i) >= r_ * r_) return false;
            }
            return true;
        });
    }

    void accept(const std::array<double, D>& x) {
        const uint32_t index = uint32_t(points_.size() / D);
        size_t cell = 0, stride = 1;
        for (int k = 0; k < D; ++k) {
            points_.push_back(std::min(float(x[k]), std::nextafter(1.0f, 0.0f)));
            cell += size_t(cellOf(x[k])) * stride;
            stride *= size_t(lookup_);
        }
        cells_[cell].push_back(index);
    }

    uint32_t n_;
    double r_;
    std::mt19937_64 rng_;
    int g_ = 1, lookup_ = 1;
    std::vector<std::vector<uint32_t>> cells_;
    std::vector<std::vector<std::array<int64_t, D>>> levels_;
    std::vector<float> points_;
};

// n points of dart throwing at radius r on the D-torus, fresh from `seed` (the next seeds if a run jams); empty if
// 64 runs jam in a row (r beyond what the torus holds n of: 1D jams at 0.7476 / n, Renyi's constant).
template <int D>
std::vector<float> dartThrowing(uint32_t n, double r, uint64_t seed) {
    for (uint64_t attempt = 0; attempt < 64; ++attempt) {
        DartThrowing<D> run(n, r, seed * 0x9e3779b97f4a7c15ull + attempt);
        if (run.run()) return run.points();
    }
    return {};
}

} // namespace stipple::bench
