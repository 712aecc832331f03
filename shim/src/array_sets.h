// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// array_sets.h — a sampler's lazily made set states of its array streams, one per (arity, k) asked.
//
// Lookups are lock-free after the first use of an (arity, k): a table of atomic pointers, filled under a mutex.
// Entries live as long as the sampler.
#pragma once

#include "dimension.h"

#include <stipple/stipple.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>

namespace stipple::detail {

class ArraySets {
public:
    ArraySets() = default;
    ArraySets(const ArraySets&) = delete;
    ArraySets& operator=(const ArraySets&) = delete;
    ~ArraySets() {
        if (Slots* slots = slots_.load(std::memory_order_acquire))
            for (auto& slot : slots->entries) delete slot.load(std::memory_order_relaxed);
        delete slots_.load(std::memory_order_relaxed);
    }

    // The set state of (arity, k), made by make() under the lock on first use. arity 1..3, k 1..max.
    template <typename Make>
    const Dimension& get(uint32_t arity, uint32_t k, Make&& make) {
        Slots* slots = slots_.load(std::memory_order_acquire);
        if (slots) {
            if (const Dimension* d = slots->at(arity, k).load(std::memory_order_acquire)) return *d;
        }
        std::lock_guard<std::mutex> lock(mutex_);
        slots = slots_.load(std::memory_order_relaxed);
        if (!slots) {
            slots = new Slots();
            slots_.store(slots, std::memory_order_release);
        }
        std::atomic<const Dimension*>& slot = slots->at(arity, k);
        if (const Dimension* d = slot.load(std::memory_order_relaxed)) return *d;
        auto made = std::make_unique<const Dimension>(make());
        slot.store(made.get(), std::memory_order_release);
        return *made.release();
    }

private:
    struct Slots {
        std::atomic<const Dimension*> entries[3 * STIPPLE_MAX_VALUES_PER_SAMPLE] = {};
        std::atomic<const Dimension*>& at(uint32_t arity, uint32_t k) {
            return entries[(arity - 1) * STIPPLE_MAX_VALUES_PER_SAMPLE + (k - 1)];
        }
    };
    std::atomic<Slots*> slots_{nullptr};
    std::mutex mutex_;
};

} // namespace stipple::detail
