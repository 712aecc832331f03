// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// hash.h — the counter-based hashing every stream is built from.
//
// All randomness in libstipple is a pure function of its inputs: a key is derived by chaining a strong 64-bit
// mixer over (seed, pixel, dimension, ...), and values are the mixer applied to key ^ counter. No RNG state is
// ever shared, which is what makes results independent of thread count and call order.
#pragma once

#include <cstdint>

namespace stipple::detail {

// SplitMix64's finaliser (Stafford's "Mix13"): a bijection on 64 bits with full avalanche.
constexpr uint64_t mix64(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

constexpr uint64_t kGolden64 = 0x9e3779b97f4a7c15ull;

// Folds one more word into a key. The word is mixed on its own first so that keys differing in one input never
// cancel out by XOR structure.
constexpr uint64_t hashCombine(uint64_t key, uint64_t word) { return mix64(key ^ mix64(word + kGolden64)); }

// The counter-th hash of a stream keyed by key. XOR (not addition) with the scaled counter keeps two different
// keys from producing shifted copies of the same stream.
constexpr uint64_t hashAt(uint64_t key, uint64_t counter) { return mix64(key ^ ((counter + 1) * kGolden64)); }

// Domain tags keep the keys of different uses of the same (seed, pixel, dimension) apart.
enum class HashDomain : uint64_t {
    Independent = 0x1d3e9a57c0ffee01ull,
    Stratified = 0x5a7f1ed0c0ffee02ull,
    Poisson = 0x9015507dc0ffee03ull,
    PoissonSeed = 0x5eed5eedc0ffee04ull,
    PastLayout = 0x9a57a1e0c0ffee05ull,
    PoissonCache = 0xcac4e5e7c0ffee06ull,
    Sobol = 0x50b01000c0ffee09ull,
    Pmj02 = 0x9a1020c0c0ffee0aull,
    Lattice = 0x1a771ce0c0ffee0cull,
    Halton = 0x4a170700c0ffee0dull,
    BlueNoiseTile = 0xb1e7111ec0ffee0bull, // XORed onto a pattern's domain for the keys of blue-noise tiles
};

// Key of one (pixel, dimension) set for one pattern domain. seedKey(seed, domain) is constant per sampler (a
// sampler keeps it; the per-value path then starts from it).
constexpr uint64_t seedKey(uint64_t seed, HashDomain domain) { return mix64(seed ^ static_cast<uint64_t>(domain)); }
constexpr uint64_t setKeyFrom(uint64_t seedKey, uint32_t pixelX, uint32_t pixelY, uint32_t dimension) {
    return hashCombine(hashCombine(seedKey, (uint64_t(pixelY) << 32) | pixelX), dimension);
}
constexpr uint64_t setKey(uint64_t seed, HashDomain domain, uint32_t pixelX, uint32_t pixelY, uint32_t dimension) {
    return setKeyFrom(seedKey(seed, domain), pixelX, pixelY, dimension);
}

// A float in [0, 1) from the top 24 bits: every value is an exact multiple of 2^-24, so 1.0 cannot occur.
constexpr float unitFloat(uint64_t bits) { return static_cast<float>(bits >> 40) * 0x1p-24f; }

} // namespace stipple::detail
