// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// A discrete distribution over n items proportional to given weights: used to choose a light by power (the
// "light choice" of every integrator, BDPT included) and a triangle by area inside a mesh light.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace stipple::render {

class DiscreteDistribution {
public:
    DiscreteDistribution() = default;
    // Negative weights count as zero; all-zero weights make a uniform distribution.
    explicit DiscreteDistribution(const std::vector<double>& weights) {
        cdf_.resize(weights.size() + 1, 0.0);
        for (size_t i = 0; i < weights.size(); ++i) cdf_[i + 1] = cdf_[i] + std::max(0.0, weights[i]);
        total_ = cdf_.back();
        if (total_ <= 0) {
            for (size_t i = 0; i <= weights.size(); ++i) cdf_[i] = double(i);
            total_ = double(weights.size());
        }
    }
    size_t size() const { return cdf_.empty() ? 0 : cdf_.size() - 1; }
    float pmf(size_t i) const { return float((cdf_[i + 1] - cdf_[i]) / total_); }

    // Picks an item for u in [0,1); `remapped` is u stretched back to [0,1) within the item's interval, so one
    // number can drive both the choice and a continuous sample.
    size_t sample(float u, float* pmfOut = nullptr, float* remapped = nullptr) const {
        double target = double(u) * total_;
        auto it = std::upper_bound(cdf_.begin(), cdf_.end(), target);
        size_t i = size_t(std::max<std::ptrdiff_t>(0, (it - cdf_.begin()) - 1));
        i = std::min(i, size() - 1);
        while (cdf_[i + 1] - cdf_[i] <= 0 && i + 1 < size()) ++i; // never return an empty item
        double width = cdf_[i + 1] - cdf_[i];
        if (pmfOut) *pmfOut = float(width / total_);
        if (remapped) {
            double r = width > 0 ? (target - cdf_[i]) / width : 0.0;
            *remapped = float(std::min(std::max(r, 0.0), double(0x1.fffffep-1)));
        }
        return i;
    }

private:
    std::vector<double> cdf_;
    double total_ = 0;
};

} // namespace stipple::render
