// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pattern_independent.cpp — independent uniform values: value (p, c) is the hash of (set key, p * arity + c).
// The blue-noise flag is refused (pattern_registry.h: kIndependentPattern's blueNoiseRefusal says why).
#include "batch_isa.h"
#include "hash.h"
#include "pattern_registry.h"

namespace stipple::detail {

void pointIndependent(uint64_t key, const Dimension& dim, uint32_t p, float* out) {
    const uint64_t first = uint64_t(p) * dim.arity;
    for (uint32_t c = 0; c < dim.arity; ++c) out[c] = unitFloat(hashAt(key, first + c));
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
void fillIndependent(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
    const uint64_t begin = uint64_t(first) * dim.arity;
    const uint64_t n = uint64_t(count) * dim.arity;
#if defined(STIPPLE_BATCH_ISA_CLONES)
    if constexpr (Isa == BatchIsa::Avx512) return hashedFloatsAvx512(key, begin, n, out);
    if constexpr (Isa == BatchIsa::Avx2) return hashedFloatsAvx2(key, begin, n, out);
#endif
    return hashedFloatsBaseline(key, begin, n, out);
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
    // Measured with a lattice map of the unit square per point index (the stratified map with one stratum): 2.2-2.4x
    // the plain pattern's low-band error on an 8 x 8 checkerboard at N = 16-256; a hashed choice among 16 maps
    // still left gratings |k| <= 32 with a predicted 0.78x gain (shim/bench/lattice_search.py --family square).
    .blueNoiseRefusal = "its point sets have no strata to share across pixels, and a lattice map of the unit square "
                        "put the error of checkerboards and gratings into the low band (2.2-2.4 times the plain "
                        "pattern's low-frequency error on an 8 x 8 checkerboard at N = 16-256)",
    .point = [](const SetKey& set, const Dimension& dim, uint32_t p,
                float* out) { pointIndependent(set.key, dim, p, out); },
    .fill = {fillSet<BatchIsa::Baseline>, fillSet<BatchIsa::Avx2>, fillSet<BatchIsa::Avx512>},
};

} // namespace stipple::detail
