// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// sequence_generation.h — where the 32-bit sequence index of sobol, lattice and halton runs out.
//
// These patterns number the points of a set's sequence with a 32-bit index: block b of a set starts at sequence
// index b * L (sobol, lattice: L = 2^m >= M, the set padded to a power of two; halton: L = M). Only
// G = floor(2^32 / L) blocks fit, so the sample indices a set serves from one sequence, its period, are N * G.
// Past it the index would wrap and repeat earlier samples exactly (sample i would equal sample i + N * G). Instead,
// block b is block b mod G of generation b / G, and generation g > 0 is the same sequence under a fresh
// randomisation (its set key hashed with g): an independent replicate, never a repeat. Generation 0 keeps the set
// key, so every index below the period keeps its value.
#pragma once

#include "pattern_registry.h"

#include <cstdint>

namespace stipple::detail {

// The blocks of one generation for sets padded to 2^log2Length points (sobol, lattice): 2^(32 - log2Length).
constexpr uint64_t blocksPerGenerationPadded(uint32_t log2Length) {
    return log2Length >= 32 ? 1u : uint64_t(1) << (32 - log2Length);
}

// The set key and block within its generation of `set` (a BlockKeying::Sequence key: the set key and block b),
// for sequences of `blocksPerGeneration` blocks.
constexpr SetKey sequenceGeneration(const SetKey& set, uint64_t blocksPerGeneration) {
    constexpr uint64_t kGenerationWord = 0x6e4e7a7100000000ull;
    if (set.block < blocksPerGeneration) [[likely]]
        return set;
    const uint32_t generation = static_cast<uint32_t>(set.block / blocksPerGeneration);
    return {hashCombine(set.key, kGenerationWord | generation),
            static_cast<uint32_t>(set.block - generation * blocksPerGeneration)};
}

// For unpadded sets of `setSize` points (halton): floor(2^32 / setSize) blocks per generation. A block below the
// period costs a multiply and a comparison, no division.
constexpr SetKey sequenceGenerationUnpadded(const SetKey& set, uint32_t setSize) {
    constexpr uint64_t kIndexSpace = uint64_t(1) << 32;
    if ((uint64_t(set.block) + 1) * setSize <= kIndexSpace) [[likely]]
        return set;
    return sequenceGeneration(set, kIndexSpace / setSize);
}

} // namespace stipple::detail
