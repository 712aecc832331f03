// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pattern_independent.cpp — independent uniform values: value (p, c) is the hash of (set key, p * arity + c).
// With the blue-noise flag, point p of the pixels of a tile is stratified across them (blue_noise.h): the top
// digits of its coordinates come from the pixel's sub-cell, the rest from the same hash as without.
#include "batch_isa.h"
#include "blue_noise.h"
#include "hash.h"
#include "pattern_registry.h"
#include "simd_avx512.h"

namespace stipple::detail {

template <BatchIsa Isa>
void fillIndependent(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out,
                     const CrossPixelStrata* blue = nullptr);
void pointIndependent(uint64_t key, const Dimension& dim, uint32_t p, float* out,
                      const CrossPixelStrata* blue = nullptr);


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

// The blue-noise batch: pointIndependent's values with the flag, a chunk of points at a time in loops the compiler
// vectorises (per axis the value hash and its move into the sub-cell, then the interleaved stores); the offsets'
// hash is one per point, shared by the axes.
template <uint32_t Arity>
[[gnu::always_inline]] inline void blueHashedFloats(uint64_t key, uint32_t first, uint32_t count, float* out,
                                                    const CrossPixelStrata& blue) {
    constexpr uint32_t kChunk = 64;
    const uint64_t offsetKey = blue.offsetKey();
    uint32_t lattice[Arity];
    for (uint32_t c = 0; c < Arity; ++c) lattice[c] = blue.lattice.c[c];
    alignas(64) uint64_t offsets[kChunk];
    alignas(64) uint32_t bits[Arity][kChunk];
    for (uint32_t base = 0; base < count; base += kChunk) {
        const uint32_t n = count - base < kChunk ? count - base : kChunk;
        const uint64_t p0 = uint64_t(first) + base;
        for (uint32_t i = 0; i < n; ++i) offsets[i] = hashAt(offsetKey, p0 + i);
        for (uint32_t c = 0; c < Arity; ++c)
            for (uint32_t i = 0; i < n; ++i)
                bits[c][i] = jitterInSubCell<Arity>(lattice[c], offsets[i], c,
                                                    static_cast<uint32_t>(hashAt(key, (p0 + i) * Arity + c) >> 32));
        float* o = out + size_t(base) * Arity;
        for (uint32_t i = 0; i < n; ++i)
            for (uint32_t c = 0; c < Arity; ++c)
                o[size_t(i) * Arity + c] = static_cast<float>(bits[c][i] >> 8) * 0x1p-24f;
    }
}

template <uint32_t Arity>
void blueFloatsBaseline(uint64_t key, uint32_t first, uint32_t count, float* out, const CrossPixelStrata& blue) {
    blueHashedFloats<Arity>(key, first, count, out, blue);
}

void hashedFloatsBaseline(uint64_t key, uint64_t begin, uint64_t n, float* out) { hashedFloats(key, begin, n, out); }
#if defined(STIPPLE_BATCH_ISA_CLONES)
[[STIPPLE_TARGET_AVX2]] void hashedFloatsAvx2(uint64_t key, uint64_t begin, uint64_t n, float* out) {
    hashedFloats(key, begin, n, out);
}
[[STIPPLE_TARGET_AVX512]] void hashedFloatsAvx512(uint64_t key, uint64_t begin, uint64_t n, float* out) {
    hashedFloats(key, begin, n, out);
}
template <uint32_t Arity>
[[STIPPLE_TARGET_AVX2]] void blueFloatsAvx2(uint64_t key, uint32_t first, uint32_t count, float* out,
                                            const CrossPixelStrata& blue) {
    blueHashedFloats<Arity>(key, first, count, out, blue);
}
// AVX-512: hand-written (independent_avx512.cpp).
template <uint32_t Arity>
void blueFloatsAvx512(uint64_t key, uint32_t first, uint32_t count, float* out, const CrossPixelStrata& blue) {
    independentBlueAvx512(key, blue, Arity, first, count, out);
}
#endif

template <BatchIsa Isa, uint32_t Arity>
void blueFloats(uint64_t key, uint32_t first, uint32_t count, float* out, const CrossPixelStrata& blue) {
#if defined(STIPPLE_BATCH_ISA_CLONES)
    if constexpr (Isa == BatchIsa::Avx512) return blueFloatsAvx512<Arity>(key, first, count, out, blue);
    if constexpr (Isa == BatchIsa::Avx2) return blueFloatsAvx2<Arity>(key, first, count, out, blue);
#endif
    return blueFloatsBaseline<Arity>(key, first, count, out, blue);
}

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
    switch (dim.arity) {
    case 1: return blueFloats<Isa, 1>(key, first, count, out, *blue);
    case 2: return blueFloats<Isa, 2>(key, first, count, out, *blue);
    default: return blueFloats<Isa, 3>(key, first, count, out, *blue);
    }
}

namespace {
template <BatchIsa Isa>
void fillSet(const SetKey& set, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
    fillIndependent<Isa>(set.key, dim, first, count, out);
}

template <BatchIsa Isa>
void blueFillSet(const SetKey& set, const Dimension& dim, uint32_t first, uint32_t count, float* out,
                 const CrossPixelStrata& strata) {
    fillIndependent<Isa>(set.key, dim, first, count, out, &strata);
}
} // namespace

extern const PatternOps kIndependentPattern;
constinit const PatternOps kIndependentPattern{
    .name = "independent",
    .domain = HashDomain::Independent,
    .blockKeying = BlockKeying::Rekeyed,
    .blueNoise = BlueNoiseMode::CrossPixelStrata,
    .latticeUse = LatticeUse::Square,
    .point = [](const SetKey& set, const Dimension& dim, uint32_t p,
                float* out) { pointIndependent(set.key, dim, p, out); },
    .fill = {fillSet<BatchIsa::Baseline>, fillSet<BatchIsa::Avx2>, fillSet<BatchIsa::Avx512>},
    .fillStrata = {blueFillSet<BatchIsa::Baseline>, blueFillSet<BatchIsa::Avx2>, blueFillSet<BatchIsa::Avx512>},
};

} // namespace stipple::detail
