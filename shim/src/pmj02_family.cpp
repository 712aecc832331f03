// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pmj02_family.cpp — lazily generated pmj02 sequences and the registry of live families.
#include "pmj02_family.h"

#include "hash.h"
#include "owen_scrambling.h"

#include <algorithm>
#include <map>

namespace stipple::detail {

namespace {
constexpr uint64_t kPmj02FamilyDomain = 0x9a102fa0c0ffee07ull;
}

uint32_t Pmj02Family::setCountFor(uint32_t log2Length) {
    const size_t bytes = sizeof(FixedPoint2) << log2Length;
    return static_cast<uint32_t>(std::clamp<size_t>((size_t(2) << 20) / bytes, 2, 32));
}

Pmj02Family::Pmj02Family(uint32_t log2Length, uint32_t setCount)
    : log2Length_(log2Length), storedLog2Length_(std::min(kMaxLog2Length, log2Length + kContinuationDoublings)),
      setCount_(setCount), slots_(new Slot[setCount]) {}

const FixedPoint2* Pmj02Family::sequence(uint32_t j) const {
    Slot& slot = slots_[j];
    if (const FixedPoint2* data = slot.ready.load(std::memory_order_acquire)) return data;
    std::lock_guard<std::mutex> lock(slot.mutex);
    if (const FixedPoint2* data = slot.ready.load(std::memory_order_relaxed)) return data;
    const uint64_t seed = hashCombine(mix64(kPmj02FamilyDomain), j);
    slot.points = generatePmj02(storedLog2Length_, seed);
    slot.depth = generatePmj02Depth(slot.points, seed);
    for (FixedPoint2& p : slot.points) p = {reverseBits32(p.x), reverseBits32(p.y)}; // the order the scramble takes
    for (uint32_t& z : slot.depth) z = reverseBits32(z);
    slot.ready.store(slot.points.data(), std::memory_order_release);
    return slot.points.data();
}

std::shared_ptr<const Pmj02Family> Pmj02Family::acquire(uint32_t log2Length) {
    static std::mutex mutex;
    static std::map<uint32_t, std::weak_ptr<const Pmj02Family>> families;
    std::lock_guard<std::mutex> lock(mutex);
    if (auto family = families[log2Length].lock()) return family;
    auto family = std::make_shared<const Pmj02Family>(
        log2Length, setCountFor(std::min(kMaxLog2Length, log2Length + kContinuationDoublings)));
    families[log2Length] = family;
    return family;
}

} // namespace stipple::detail
