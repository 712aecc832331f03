// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pmj02_family.h — the cached pmj02 sequences of one length, shared by every sampler that serves them.
//
// A family serves sets of up to 2^log2Length points. It holds setCount sequences of 2^storedLog2Length points,
// up to 8 times longer (at most 2^kMaxLog2Length), so that the blocks of a sampler past N continue one sequence
// (pmj02 sequences are progressive: every prefix of a power-of-two length is itself a pmj02 set). Sequence j is
// generated lazily on first use from a seed that depends on j only, so the content never depends on which thread
// generated it, and sequence j of every family is a prefix of sequence j of every longer family (the generator
// grows a sequence level by level from per-level seeds, and z does not depend on the length): the first 4N
// samples of an N-sample set are the points of a fresh 4N-sample set that drew the same j. Each sequence has its
// depth coordinate z (generatePmj02Depth) for 3D sets beside it.
// Families live as long as a sampler holds them (the registry keeps weak references).
#pragma once

#include "pmj02_generator.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace stipple::detail {

class Pmj02Family {
public:
    // Longest sequence served: generation is ~0.2 s at 2^16 points and grows faster than linearly.
    static constexpr uint32_t kMaxLog2Length = 16;
    // Doublings stored past a set's length, for the blocks past N (8 blocks of a power-of-two set).
    static constexpr uint32_t kContinuationDoublings = 3;
    // Sequences per family: as many (x, y) tables as fit in 2 MiB (3 MiB with z), between 2 and 32.
    static uint32_t setCountFor(uint32_t log2Length);

    Pmj02Family(uint32_t log2Length, uint32_t setCount);

    uint32_t log2Length() const { return log2Length_; }
    uint32_t storedLog2Length() const { return storedLog2Length_; }
    uint32_t setCount() const { return setCount_; }
    // Sequence j with each coordinate's bits reversed (the digit order the Laine-Karras scramble takes).
    const FixedPoint2* sequence(uint32_t j) const;
    // The z of sequence j's points, bits reversed likewise.
    const uint32_t* depth(uint32_t j) const {
        sequence(j); // generates the slot
        return slots_[j].depth.data();
    }

    // The shared family for this length (created on first request).
    static std::shared_ptr<const Pmj02Family> acquire(uint32_t log2Length);

private:
    struct Slot {
        std::mutex mutex;
        std::atomic<const FixedPoint2*> ready{nullptr};
        std::vector<FixedPoint2> points;
        std::vector<uint32_t> depth;
    };
    uint32_t log2Length_, storedLog2Length_, setCount_;
    std::unique_ptr<Slot[]> slots_;
};

} // namespace stipple::detail
