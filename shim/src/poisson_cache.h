// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// poisson_cache.h — amortised Poisson-disk sets: a bounded, thread-safe cache of toroidal sets per (arity, M).
//
// A family holds setCount sets of M points for one arity. Set j is generated lazily, on first use, by
// pointsets::generatePoisson with a seed derived from (arity, M, j) only: the content of the cache is a pure
// function of its key, so results never depend on which thread generated a set first.
//
// Bound: the families held by the cache total at most kByteBudget (64 MiB) of point storage, counted at full
// capacity before generation. Acquiring a family that does not fit evicts least-recently acquired families no
// sampler uses any more; if it still does not fit, the sampler gets a private family (same content, freed with
// the sampler) instead of the cache growing.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace stipple::detail {

class PoissonFamily {
public:
    PoissonFamily(uint32_t arity, uint32_t points, uint32_t setCount);

    uint32_t arity() const { return arity_; }
    uint32_t points() const { return points_; }
    uint32_t setCount() const { return setCount_; }
    size_t byteCapacity() const { return size_t(setCount_) * points_ * arity_ * sizeof(float); }

    // Set j (0 <= j < setCount), M*arity floats in [0,1). Generates it on first use; safe from any thread. The
    // generated case is inline: it is part of every poisson call.
    const float* set(uint32_t j) const {
        if (const float* data = slots_[j].ready.load(std::memory_order_acquire)) return data;
        return generate(j);
    }
    bool generated(uint32_t j) const { return slots_[j].ready.load(std::memory_order_acquire) != nullptr; }

    // The seed set j is generated from: a function of (arity, M, j) only.
    static uint64_t setSeed(uint32_t arity, uint32_t points, uint32_t j);

private:
    const float* generate(uint32_t j) const;
    struct Slot {
        std::mutex mutex;
        std::atomic<const float*> ready{nullptr};
        std::vector<float> points;
    };
    uint32_t arity_, points_, setCount_;
    std::unique_ptr<Slot[]> slots_;
};

class PoissonCache {
public:
    static constexpr size_t kByteBudget = size_t(64) << 20;
    // Sets per family: as many as fit in 2 MiB, at least 1, at most 256 (pixels that share a set share its
    // periodogram: more sets average its noise away sooner).
    static constexpr size_t kFamilyBytes = size_t(2) << 20;
    static constexpr uint32_t kMaxSetsPerFamily = 256;

    static PoissonCache& global();
    static uint32_t setCountFor(uint32_t arity, uint32_t points);

    std::shared_ptr<const PoissonFamily> acquire(uint32_t arity, uint32_t points);
    size_t bytesHeld() const;

private:
    struct Entry {
        std::shared_ptr<const PoissonFamily> family;
        uint64_t lastUse = 0;
    };
    mutable std::mutex mutex_;
    std::map<std::pair<uint32_t, uint32_t>, Entry> entries_;
    size_t bytes_ = 0;
    uint64_t clock_ = 0;
};

// The stored set a "poisson" set key serves: its top 32 bits scaled to [0, setCount) (no division per value).
constexpr uint32_t poissonSetIndex(uint64_t key, uint32_t setCount) {
    return static_cast<uint32_t>(((key >> 32) * setCount) >> 32);
}

} // namespace stipple::detail
