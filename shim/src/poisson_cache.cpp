// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// poisson_cache.cpp — lazily generated Poisson set families and their bounded cache.
#include "poisson_cache.h"

#include "error.h"
#include "hash.h"
#include "pointsets/pointsets.h"
#include "progressive_order.h"

#include <algorithm>
#include <string>

namespace stipple::detail {

PoissonFamily::PoissonFamily(uint32_t arity, uint32_t points, uint32_t setCount)
    : arity_(arity), points_(points), setCount_(setCount), slots_(new Slot[setCount]) {}

uint64_t PoissonFamily::setSeed(uint32_t arity, uint32_t points, uint32_t j) {
    uint64_t key = mix64(static_cast<uint64_t>(HashDomain::PoissonCache));
    key = hashCombine(key, (uint64_t(arity) << 32) | points);
    return hashCombine(key, j);
}

const float* PoissonFamily::generate(uint32_t j) const {
    Slot& slot = slots_[j];
    std::lock_guard<std::mutex> lock(slot.mutex);
    if (const float* data = slot.ready.load(std::memory_order_relaxed)) return data;
    // 1D: cell sets (pointsets::generateCellSet1D); 2D, 3D: toroidal near-maximal Poisson-disk sets.
    std::vector<float> points = pointsets::generatePoisson(int(arity_), points_, setSeed(arity_, points_, j));
    if (points.size() != size_t(points_) * arity_)
        throw Error(STIPPLE_ERROR_INTERNAL, "poisson generator returned " + std::to_string(points.size()) +
                                                " floats; expected " + std::to_string(size_t(points_) * arity_));
    for (float v : points)
        if (!(v >= 0.0f && v < 1.0f))
            throw Error(STIPPLE_ERROR_INTERNAL,
                        "poisson generator returned a value outside [0,1): " + std::to_string(v));
    orderProgressively(points, arity_); // served in stored order: prefixes stay well spread
    slot.points = std::move(points);
    slot.ready.store(slot.points.data(), std::memory_order_release);
    return slot.points.data();
}

PoissonCache& PoissonCache::global() {
    static PoissonCache cache;
    return cache;
}

uint32_t PoissonCache::setCountFor(uint32_t arity, uint32_t points) {
    const size_t setBytes = size_t(points) * arity * sizeof(float);
    return static_cast<uint32_t>(std::clamp<size_t>(kFamilyBytes / setBytes, 1, kMaxSetsPerFamily));
}

std::shared_ptr<const PoissonFamily> PoissonCache::acquire(uint32_t arity, uint32_t points) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto key = std::make_pair(arity, points);
    ++clock_;
    if (auto it = entries_.find(key); it != entries_.end()) {
        it->second.lastUse = clock_;
        return it->second.family;
    }
    auto family = std::make_shared<const PoissonFamily>(arity, points, setCountFor(arity, points));
    const size_t need = family->byteCapacity();
    while (bytes_ + need > kByteBudget) {
        // Evict the least recently acquired family that no sampler holds.
        auto victim = entries_.end();
        for (auto it = entries_.begin(); it != entries_.end(); ++it)
            if (it->second.family.use_count() == 1 &&
                (victim == entries_.end() || it->second.lastUse < victim->second.lastUse))
                victim = it;
        if (victim == entries_.end()) return family; // does not fit: private to the caller
        bytes_ -= victim->second.family->byteCapacity();
        entries_.erase(victim);
    }
    entries_.emplace(key, Entry{family, clock_});
    bytes_ += need;
    return family;
}

size_t PoissonCache::bytesHeld() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return bytes_;
}

} // namespace stipple::detail
