// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pattern_poisson.cpp — serving Poisson-disk sets: "poisson" from the cache, "poisson-seed" generated fresh.
//
// A stored "poisson" set (pointsets::generatePoisson) is toroidal: it is served moved by a random symmetry of the
// torus (axis permutation and reflections) and a Cranley-Patterson shift, isometries of the torus, so every point is
// uniform on [0,1)^arity and the set's minimum distance is kept (in the unit cube, where the torus' wrap is cut,
// distances only grow). A 1D set's one point per cell becomes one point per cell of the shifted grid.
// Order: "poisson" serves the stored order (made progressive by the cache, progressive_order.h) shuffled only
// within each layer [2^j, 2^(j+1)) (layeredIndex). Every prefix of 2^j points is thus
// exactly the stored prefix, other prefixes add a random part of the next layer; the shuffle keeps two
// dimensions that drew the same stored set and symmetry from pairing their samples point for point.
// "poisson-seed" serves its fresh set in a hashed random order.
#include "batch_isa.h"
#include "error.h"
#include "hash.h"
#include "pattern_registry.h"
#include "poisson_cache.h"
#include "permutation.h"
#include "pointsets/pointsets.h"
#include "simd_avx512.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>
#include <vector>

namespace stipple::detail {

template <BatchIsa Isa>
void fillPoisson(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out);
void pointPoisson(uint64_t key, const Dimension& dim, uint32_t p, float* out);

// poisson-seed generates its set afresh on every call (the study's cost, kept deliberately); random access to
// one point therefore goes through a whole generation.
void fillPoissonSeed(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out);
void pointPoissonSeed(uint64_t key, const Dimension& dim, uint32_t p, float* out);

namespace {

constexpr uint8_t kAxisOrders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

// v in (-1, 2) wrapped into [0, 1) without a data-dependent branch (the wrap is a coin flip per value: a branch
// is mispredicted half the time, which compilers emit for a conditional subtract). r = v - trunc(v) is exact and
// in (-1, 1); a negative r (its sign bit) gets 1.0 added through integer masks. That sum may round up to 1.0 (as
// may -0.0 + 1): the last step maps it to 0, a select that is practically never taken.
[[gnu::always_inline]] inline float wrapUnit(float v) {
    float r = v - static_cast<float>(static_cast<int32_t>(v));
    const uint32_t negative = std::bit_cast<uint32_t>(r) >> 31;
    r += std::bit_cast<float>((0u - negative) & 0x3f800000u);
    return r < 1.0f ? r : 0.0f;
}

// The fields (orderSeed; source[c], the stored axis output axis c reads; sign[c], -1 for a reflected axis; shift[c])
// are the AVX-512 kernel's arguments, passed as they are: a copy would read them back wider than they were written,
// which waits for a failed store forwarding on every call.
struct TorusMap : PoissonKernelArgs {

    // One hash gives the three shifts (21 bits each: multiples of 2^-21), one the symmetry (axis order from its
    // value mod 6, reflections from bits 32..34) and the order seed (bits 35..63).
    TorusMap(uint64_t key, uint32_t arity, bool useSymmetry) : PoissonKernelArgs{0, {0, 1, 2}, {1.0f, 1.0f, 1.0f}, {}} {
        const uint64_t shifts = hashAt(key, 3);
        for (uint32_t c = 0; c < arity; ++c) shift[c] = float((shifts >> (43 - 21 * c)) & 0x1fffffu) * 0x1p-21f;
        const uint64_t symmetry = hashAt(key, 2);
        orderSeed = static_cast<uint32_t>(symmetry >> 35);
        if (!useSymmetry) return;
        const uint32_t axisOrder = arity == 3 ? uint32_t(symmetry % 6) : arity == 2 ? uint32_t(symmetry % 2) * 2 : 0;
        for (uint32_t c = 0; c < arity; ++c) {
            source[c] = kAxisOrders[axisOrder][c];
            // The sign bit set from the hash bit, not a branch (a coin flip per call, mispredicted half the time).
            sign[c] = std::bit_cast<float>(0x3f800000u | (static_cast<uint32_t>(symmetry >> (32 + c)) & 1u) << 31);
        }
    }

    // s + x or s - x, wrapped into [0,1) by wrapUnit.
    template <uint32_t Arity>
    void apply(const float* stored, float* out) const {
        for (uint32_t c = 0; c < Arity; ++c) {
            out[c] = wrapUnit(shift[c] + sign[c] * stored[source[c]]);
        }
    }
    void apply(const float* stored, uint32_t arity, float* out) const {
        switch (arity) {
        case 1: return apply<1>(stored, out);
        case 2: return apply<2>(stored, out);
        default: return apply<3>(stored, out);
        }
    }
};

// Position p of the served order -> stored point: p's layer [2^j, 2^(j+1)) is shuffled by XOR with the seed's low
// j bits (a bijection of a full layer, cheap on the per-value path); a last layer clipped by M (M not a power
// of two) by a hashed permutation.
inline uint32_t layeredIndex(uint32_t p, uint32_t points, uint32_t seed) {
    if (p < 2) return p;
    const uint32_t base = std::bit_floor(p);
    if (points - base >= base) return base + ((p - base) ^ (seed & (base - 1)));
    return base + permuteIndexFast(p - base, points - base, seed ^ base);
}

constexpr uint32_t kSmallServe = 64; // sets this small are served by one loop (their layers are a few points each)

// The batch: layer by layer, with the map's constants in locals (out may alias nothing the compiler can see).
template <uint32_t Arity>
[[gnu::always_inline]] inline void serveLayered(const TorusMap& map, const float* stored, uint32_t points,
                                                uint32_t first, uint32_t count, float* out) {
    uint32_t source[Arity];
    for (uint32_t c = 0; c < Arity; ++c) source[c] = map.source[c];
    // First the stored coordinates, axis-permuted, at their served positions; then the reflection and shift of
    // every value in one contiguous loop (vectorised; the same float operations as TorusMap::apply).
    const auto copy = [&](const float* x, float* o) {
        for (uint32_t c = 0; c < Arity; ++c) o[c] = x[source[c]];
    };
    const uint32_t end = first + count;
    uint32_t p = first;
    if (end <= kSmallServe && std::has_single_bit(points)) {
        // Small power-of-two sets: point p reads stored point p ^ (seed & (layer size - 1)) directly (what the layer
        // walk below computes), one loop instead of a setup per layer.
        for (; p < end; ++p)
            copy(stored + size_t(p ^ (map.orderSeed & (std::bit_floor(p | 1u) - 1u))) * Arity,
                 out + size_t(p - first) * Arity);
    }
    while (p < end) {
        const uint32_t base = p < 2 ? 0 : std::bit_floor(p);
        const uint32_t layerEnd = std::min(end, p < 2 ? 2u : 2 * base);
        if (p >= 2 && points - base < base) {
            // A clipped last layer (layeredIndex's permutation), its walk done 64 points at a time (no branch per
            // point).
            alignas(64) uint32_t index[64];
            while (p < layerEnd) {
                const uint32_t n = std::min(64u, layerEnd - p);
                for (uint32_t k = 0; k < n; ++k) index[k] = p + k - base;
                permuteIndicesFast(index, n, points - base, map.orderSeed ^ base);
                for (uint32_t k = 0; k < n; ++k)
                    copy(stored + size_t(base + index[k]) * Arity, out + size_t(p + k - first) * Arity);
                p += n;
            }
            continue;
        }
        const uint32_t mask = p < 2 ? 0 : (map.orderSeed & (base - 1));
        if (p == base && layerEnd == 2 * base && base >= 2) {
            // A whole layer: XOR is an involution, so walk the stored points in memory order (the family's sets do not
            // stay in cache between pixels) and scatter them to their served positions.
            for (uint32_t j = 0; j < base; ++j)
                copy(stored + size_t(base + j) * Arity, out + size_t(base + (j ^ mask) - first) * Arity);
            p = layerEnd;
            continue;
        }
        for (; p < layerEnd; ++p)
            copy(stored + size_t(base + ((p - base) ^ mask)) * Arity, out + size_t(p - first) * Arity);
    }
    float shift[Arity], sign[Arity];
    for (uint32_t c = 0; c < Arity; ++c) shift[c] = map.shift[c], sign[c] = map.sign[c];
    for (uint32_t i = 0; i < count; ++i)
        for (uint32_t c = 0; c < Arity; ++c) {
            float& v = out[size_t(i) * Arity + c];
            v = wrapUnit(shift[c] + sign[c] * v);
        }
}

// The stored set a key draws from its family.
const float* cachedSet(uint64_t key, const Dimension& dim) {
    const PoissonFamily& family = dim.stateAs<PoissonFamily>();
    return family.set(poissonSetIndex(key, family.setCount()));
}

// A fresh set per call: allocating here is part of the cost the study paid.
std::vector<float> freshSeedSet(uint64_t key, const Dimension& dim) {
    std::vector<float> set = pointsets::generatePoissonSeed(int(dim.arity), dim.setSize, hashAt(key, 6));
    if (set.size() != size_t(dim.setSize) * dim.arity)
        throw Error(STIPPLE_ERROR_INTERNAL, "poisson-seed generator returned " + std::to_string(set.size()) +
                                                " floats; expected " + std::to_string(size_t(dim.setSize) * dim.arity));
    return set;
}

} // namespace

// The batch kernel compiled once per ISA (batch_isa.h).
template <uint32_t Arity>
void serveLayeredBaseline(const TorusMap& map, const float* stored, uint32_t points, uint32_t first, uint32_t count,
                          float* out) {
    serveLayered<Arity>(map, stored, points, first, count, out);
}
#if defined(STIPPLE_BATCH_ISA_CLONES)
template <uint32_t Arity>
[[STIPPLE_TARGET_AVX2]] void serveLayeredAvx2(const TorusMap& map, const float* stored, uint32_t points, uint32_t first,
                                              uint32_t count, float* out) {
    serveLayered<Arity>(map, stored, points, first, count, out);
}
template <uint32_t Arity>
[[STIPPLE_TARGET_AVX512]] void serveLayeredAvx512(const TorusMap& map, const float* stored, uint32_t points,
                                                  uint32_t first, uint32_t count, float* out) {
    serveLayered<Arity>(map, stored, points, first, count, out);
}
#endif

template <BatchIsa Isa, uint32_t Arity>
void serveBatch(const TorusMap& map, const float* stored, uint32_t points, uint32_t first, uint32_t count, float* out) {
#if defined(STIPPLE_BATCH_ISA_CLONES)
    if constexpr (Isa == BatchIsa::Avx512) {
        // Power-of-two sets: hand-written (poisson_avx512.cpp).
        if (poissonLayeredAvx512(map, Arity, stored, points, first, count, out)) return;
        return serveLayeredAvx512<Arity>(map, stored, points, first, count, out);
    }
    if constexpr (Isa == BatchIsa::Avx2) return serveLayeredAvx2<Arity>(map, stored, points, first, count, out);
#endif
    serveLayeredBaseline<Arity>(map, stored, points, first, count, out);
}

template <BatchIsa Isa, uint32_t Arity>
void fillPoissonOf(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
    const TorusMap map(key, Arity, true);
    serveBatch<Isa, Arity>(map, cachedSet(key, dim), dim.setSize, first, count, out);
}

template <BatchIsa Isa>
void fillPoisson(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
    switch (dim.arity) {
    case 1: return fillPoissonOf<Isa, 1>(key, dim, first, count, out);
    case 2: return fillPoissonOf<Isa, 2>(key, dim, first, count, out);
    default: return fillPoissonOf<Isa, 3>(key, dim, first, count, out);
    }
}

void pointPoisson(uint64_t key, const Dimension& dim, uint32_t p, float* out) {
    const TorusMap map(key, dim.arity, true);
    map.apply(cachedSet(key, dim) + size_t(layeredIndex(p, dim.setSize, map.orderSeed)) * dim.arity, dim.arity, out);
}

void fillPoissonSeed(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
    const std::vector<float> set = freshSeedSet(key, dim);
    const TorusMap map(key, dim.arity, false);
    for (uint32_t i = 0; i < count; ++i) {
        const uint32_t q = permuteIndex(first + i, dim.setSize, map.orderSeed);
        map.apply(set.data() + size_t(q) * dim.arity, dim.arity, out + size_t(i) * dim.arity);
    }
}

void pointPoissonSeed(uint64_t key, const Dimension& dim, uint32_t p, float* out) {
    fillPoissonSeed(key, dim, p, 1, out);
}

namespace {
template <BatchIsa Isa>
void fillPoissonSet(const SetKey& set, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
    fillPoisson<Isa>(set.key, dim, first, count, out);
}
void fillPoissonSeedSet(const SetKey& set, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
    fillPoissonSeed(set.key, dim, first, count, out);
}
} // namespace

// The cache's families count against its budget: a stream acquires its family on first use.
extern const PatternOps kPoissonPattern;
constinit const PatternOps kPoissonPattern{
    .name = "poisson",
    .domain = HashDomain::Poisson,
    .blockKeying = BlockKeying::Rekeyed,
    .prepare = [](Dimension& dim) { dim.patternState = PoissonCache::global().acquire(dim.arity, dim.setSize); },
    .prepareStreamsOnFirstUse = true,
    .point = [](const SetKey& set, const Dimension& dim, uint32_t p,
                float* out) { pointPoisson(set.key, dim, p, out); },
    .fill = {fillPoissonSet<BatchIsa::Baseline>, fillPoissonSet<BatchIsa::Avx2>, fillPoissonSet<BatchIsa::Avx512>},
};

// Generated afresh on every call: nothing to prepare, nothing per ISA.
extern const PatternOps kPoissonSeedPattern;
constinit const PatternOps kPoissonSeedPattern{
    .name = "poisson-seed",
    .domain = HashDomain::PoissonSeed,
    .blockKeying = BlockKeying::Rekeyed,
    .point = [](const SetKey& set, const Dimension& dim, uint32_t p,
                float* out) { pointPoissonSeed(set.key, dim, p, out); },
    .fill = {fillPoissonSeedSet, fillPoissonSeedSet, fillPoissonSeedSet},
};

} // namespace stipple::detail
