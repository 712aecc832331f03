// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pattern_independent.cpp — independent uniform values: value (p, c) is the hash of (set key, p * arity + c).
// With the blue-noise flag, point p of the pixels of a tile is stratified across them (blue_noise.h): the top
// digits of its coordinates come from the pixel's sub-cell, the rest from the same hash as without.
#include "batch_isa.h"
#include "blue_noise.h"
#include "hash.h"
#include "pattern_registry.h"
#include "patterns.h"

namespace stipple::detail {

void pointIndependent(uint64_t key, const Dimension& dim, uint32_t p, float* out, const CrossPixelStrata* blue) {
    const uint64_t first = uint64_t(p) * dim.arity;
    if (!blue) {
        for (uint32_t c = 0; c < dim.arity; ++c) out[c] = unitFloat(hashAt(key, first + c));
        return;
    }
    uint32_t bits[3];
    for (uint32_t c = 0; c < dim.arity; ++c) bits[c] = static_cast<uint32_t>(hashAt(key, first + c) >> 32);
    blue->place(p, dim.arity, bits);
    for (uint32_t c = 0; c < dim.arity; ++c) out[c] = static_cast<float>(bits[c] >> 8) * 0x1p-24f;
}

namespace {

// The batch kernel, compiled once per ISA like the other patterns' (batch_isa.h), so that cost ratios against
// independent compare like with like.
[[gnu::always_inline]] inline void hashedFloats(uint64_t key, uint64_t begin, uint64_t n, float* out) {
    for (uint64_t i = 0; i < n; ++i) out[i] = unitFloat(hashAt(key, begin + i));
}

void hashedFloatsBaseline(uint64_t key, uint64_t begin, uint64_t n, float* out) { hashedFloats(key, begin, n, out); }
#if defined(STIPPLE_BATCH_ISA_CLONES)
[[STIPPLE_TARGET_AVX2]] void hashedFloatsAvx2(uint64_t key, uint64_t begin, uint64_t n, float* out) {
    hashedFloats(key, begin, n, out);
}
[[STIPPLE_TARGET_AVX512]] void hashedFloatsAvx512(uint64_t key, uint64_t begin, uint64_t n, float* out) {
    hashedFloats(key, begin, n, out);
}
#endif

} // namespace

template <BatchIsa Isa>
void fillIndependent(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out,
                     const CrossPixelStrata* blue) {
    if (!blue) {
        const uint64_t begin = uint64_t(first) * dim.arity;
        const uint64_t n = uint64_t(count) * dim.arity;
#if defined(STIPPLE_BATCH_ISA_CLONES)
        if constexpr (Isa == BatchIsa::Avx512) return hashedFloatsAvx512(key, begin, n, out);
        if constexpr (Isa == BatchIsa::Avx2) return hashedFloatsAvx2(key, begin, n, out);
#endif
        return hashedFloatsBaseline(key, begin, n, out);
    }
    for (uint32_t i = 0; i < count; ++i) pointIndependent(key, dim, first + i, out + size_t(i) * dim.arity, blue);
}

namespace {
template <BatchIsa Isa>
void fillSet(const SetKey& set, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
    fillIndependent<Isa>(set.key, dim, first, count, out);
}
} // namespace

extern const PatternOps kIndependentPattern;
constinit const PatternOps kIndependentPattern{
    .name = "independent",
    .domain = HashDomain::Independent,
    .blockKeying = BlockKeying::Rekeyed,
    .blueNoise = BlueNoiseMode::CrossPixelStrata,
    .latticeUse = LatticeUse::Square,
    .limits = {},
    .prepare = nullptr,
    .prepareStreamsOnFirstUse = false,
    .strata = nullptr,
    .point = [](const SetKey& set, const Dimension& dim, uint32_t p,
                float* out) { pointIndependent(set.key, dim, p, out); },
    .fill = {fillSet<BatchIsa::Baseline>, fillSet<BatchIsa::Avx2>, fillSet<BatchIsa::Avx512>},
    .fillStrata =
        [](const SetKey& set, const Dimension& dim, uint32_t first, uint32_t count, float* out,
           const CrossPixelStrata& strata) {
            fillIndependent<BatchIsa::Baseline>(set.key, dim, first, count, out, &strata); // per point: no ISA
        },
};

} // namespace stipple::detail
