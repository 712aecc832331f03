// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pattern_halton.cpp — a scrambled Halton sequence: bases 2, 3 and 5 for the axes of one set.
//
// Point j of the sequence is (x_2(j), x_3(j), x_5(j)) up to the set's arity: x_2 is the base-2 radical inverse of j
// Owen-scrambled as sobol's coordinates are (owen_scrambling.h): the Laine-Karras hash (Vegdahl's) for every digit,
// completed below the set's level (ceil(log2 M): the M consecutive indices of a block have an interval of their own
// there) by deepOwenScrambleReversed, so that each point is uniform in its interval, independently (nested
// uniform); x_3 and x_5 are radical inverses with random
// digit permutations (pbrt-v4's default Halton randomisation): digit t of the fraction is sigma_t(digit t of j),
// sigma_t a permutation of the base's digits drawn per set and digit position, for every position down to float
// precision (base 3: 16 digits, base 5: 11), and the rest of the fraction a uniform jitter per point. Each digit of
// a coordinate is then uniform and independent of the others, so every point is uniform on the unit cube, and the
// first b^k points of the sequence keep one point in each 1/b^k interval of their base-b axis.
//
// Sets and sample order: the set of M points of one (pixel, dimension, block) is sequence points
// [b * M, (b + 1) * M) of block b, visited in a hashed order (permuteIndexFast), so the first B blocks together are
// the first B * M points of the sequence (progressive) while the sample order decorrelates the dimensions of a
// pixel (padding). Dimension limits: none. Each set uses only the bases 2, 3 and 5 (arity <= 3), and sets are
// decorrelated by their own scrambles and orders, so a host may ask for any number of dimensions — unlike a
// Halton sampler whose dimension d takes the d-th prime (pbrt-v4: 1000 primes), nothing runs out.
// The sequence index is 32-bit: a set's sequence holds G = floor(2^32 / M) blocks, its period N * G sample indices;
// block b past them is block b mod G of a freshly scrambled and ordered sequence, generation b / G
// (sequence_generation.h).
#include "owen_scrambling.h"
#include "pattern_registry.h"
#include "permutation.h"
#include "sequence_generation.h"

#include <array>
#include <bit>

namespace stipple::detail {

namespace {

// Base b's digit permutations, all of them, so a hash picks one by a multiply.
template <uint32_t B, uint32_t Count>
constexpr std::array<std::array<uint8_t, B>, Count> allPermutations() {
    std::array<std::array<uint8_t, B>, Count> table{};
    std::array<uint8_t, B> p{};
    for (uint32_t i = 0; i < B; ++i) p[i] = static_cast<uint8_t>(i);
    for (uint32_t n = 0; n < Count; ++n) {
        table[n] = p;
        // next lexicographic permutation
        int i = int(B) - 2;
        while (i >= 0 && p[i] >= p[i + 1]) --i;
        if (i < 0) break;
        int j = int(B) - 1;
        while (p[j] <= p[i]) --j;
        std::swap(p[i], p[j]);
        for (int a = i + 1, b = int(B) - 1; a < b; ++a, --b) std::swap(p[a], p[b]);
    }
    return table;
}
constexpr auto kPermutations3 = allPermutations<3, 6>();
constexpr auto kPermutations5 = allPermutations<5, 120>();

// floor(2^64 / b^(t+1)): digit t's weight in 64-bit fixed point.
template <uint32_t B, uint32_t Digits>
constexpr std::array<uint64_t, Digits + 1> digitWeights() {
    std::array<uint64_t, Digits + 1> w{};
    unsigned __int128 power = B;
    for (uint32_t t = 0; t <= Digits; ++t, power *= B)
        w[t] = static_cast<uint64_t>((static_cast<unsigned __int128>(1) << 64) / power);
    return w;
}

// One base's scramble of a set: the digit values' weights per position and the weight of the all-zero suffix
// from each position on (digits past an index's last non-zero one are zeros: their permuted values are constant).
template <uint32_t B, uint32_t Digits>
struct DigitScramble {
    static constexpr auto kWeights = digitWeights<B, Digits>();
    uint64_t contribution[Digits][B]; // sigma_t(d) * weight_t
    uint64_t zeroSuffix[Digits + 1];  // sum over positions u >= t of contribution[u][0]

    explicit DigitScramble(uint64_t key) {
        for (uint32_t t = 0; t < Digits; ++t) {
            const uint32_t h = static_cast<uint32_t>(hashAt(key, t) >> 32);
            for (uint32_t d = 0; d < B; ++d) {
                const uint32_t permuted = B == 3 ? kPermutations3[(uint64_t(h) * 6) >> 32][d]
                                                 : kPermutations5[(uint64_t(h) * 120) >> 32][d];
                contribution[t][d] = permuted * kWeights[t];
            }
        }
        zeroSuffix[Digits] = 0;
        for (uint32_t t = Digits; t-- > 0;) zeroSuffix[t] = zeroSuffix[t + 1] + contribution[t][0];
    }

    // The coordinate of sequence index j as a 32-bit fraction; jitter fills the bits below the last digit.
    uint32_t operator()(uint32_t j, uint32_t jitter) const {
        uint64_t x = 0;
        uint32_t t = 0;
        for (; j != 0 && t < Digits; ++t) {
            const uint32_t q = j / B;
            x += contribution[t][j - q * B];
            j = q;
        }
        x += zeroSuffix[t];
        x += static_cast<uint64_t>((static_cast<unsigned __int128>(kWeights[Digits - 1]) * jitter) >> 32);
        return static_cast<uint32_t>(x >> 32);
    }
};
// Float precision (24 bits) needs b^-Digits < 2^-24: 3^-16 ~ 2.3e-8, 5^-11 ~ 2.0e-8.
using Base3 = DigitScramble<3, 16>;
using Base5 = DigitScramble<5, 11>;

struct HaltonSet {
    uint32_t orderSeed, owenSeed, deepSeed, level;
    uint64_t jitterKey;
    uint32_t blockStart; // block * M: the block's first sequence index
    uint32_t size;       // M
};

HaltonSet haltonSet(const SetKey& set, const Dimension& dim) {
    const uint64_t h = hashAt(set.key, 0);
    const uint32_t owenSeed = static_cast<uint32_t>(h >> 32);
    return HaltonSet{static_cast<uint32_t>(h),
                     owenSeed,
                     mixBits32(owenSeed ^ 0x5b0b01deu),
                     static_cast<uint32_t>(std::bit_width(dim.setSize - 1)),
                     hashCombine(set.key, 0x7a11u),
                     set.block * dim.setSize,
                     dim.setSize};
}

template <uint32_t Arity>
[[gnu::always_inline]] inline void haltonPoint(const HaltonSet& s, const Base3* b3, const Base5* b5, uint32_t p,
                                               float* out) {
    const uint32_t j = s.blockStart + permuteIndexFast(p, s.size, s.orderSeed);
    // The base-2 fraction's digits reversed are j itself.
    const uint32_t scrambled = deepOwenScrambleReversed(vegdahlPermutation(j, s.owenSeed), s.level, s.deepSeed);
    out[0] = fixedToUnitFloat(reverseBits32(scrambled));
    if constexpr (Arity >= 2) {
        const uint64_t jitter = hashAt(s.jitterKey, j);
        out[1] = fixedToUnitFloat((*b3)(j, static_cast<uint32_t>(jitter)));
        if constexpr (Arity >= 3) out[2] = fixedToUnitFloat((*b5)(j, static_cast<uint32_t>(jitter >> 32)));
    }
}

template <uint32_t Arity>
void haltonPoints(const SetKey& set, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
    const HaltonSet s = haltonSet(set, dim);
    // The digit tables cost ~16 hashes per base: built once per call, shared by its points.
    const Base3 b3(Arity >= 2 ? hashCombine(set.key, 3) : 0);
    const Base5 b5(Arity >= 3 ? hashCombine(set.key, 5) : 0);
    for (uint32_t i = 0; i < count; ++i) haltonPoint<Arity>(s, &b3, &b5, first + i, out + size_t(i) * Arity);
}

void fillHalton(const SetKey& blockKey, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
    const SetKey set = sequenceGenerationUnpadded(blockKey, dim.setSize);
    switch (dim.arity) {
    case 1: return haltonPoints<1>(set, dim, first, count, out);
    case 2: return haltonPoints<2>(set, dim, first, count, out);
    default: return haltonPoints<3>(set, dim, first, count, out);
    }
}

void pointHalton(const SetKey& set, const Dimension& dim, uint32_t p, float* out) { fillHalton(set, dim, p, 1, out); }

} // namespace

// Blocks continue the sequence (SetKey::block), a fresh one per period. The blue-noise flag is refused: its only
// mechanism for a set that is not strata, a per-pixel toroidal shift of a tile's set, adds a seam on non-periodic
// integrands (as for sobol).
extern const PatternOps kHaltonPattern;
constinit const PatternOps kHaltonPattern{
    .name = "halton",
    .domain = HashDomain::Halton,
    .blockKeying = BlockKeying::Sequence,
    .point = pointHalton,
    .fill = {fillHalton, fillHalton, fillHalton},
};

} // namespace stipple::detail
