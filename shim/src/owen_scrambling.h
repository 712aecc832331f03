// owen_scrambling.h — hash-based nested uniform (Owen) scrambling of 32-bit binary fractions.
//
// Burley, "Practical Hash-based Owen Scrambling" (JCGT 9(4), 2020), after Laine & Karras (2011): a hash whose
// every output bit depends only on the input bits below it (multiplication and addition carry upwards) is an
// Owen scramble of the bit-reversed value, because a binary fraction's digit t is then permuted by a function of
// the digits before it. Applied to a coordinate it keeps every elementary-interval stratification; applied to a
// sample index it shuffles the order so that every aligned block of 2^j indices maps onto an aligned block of
// 2^j indices (prefixes of a (0,m,2)-net stay nets).
#pragma once

#include <cstdint>

namespace stipple::detail {

constexpr uint32_t reverseBits32(uint32_t v) {
    v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
    v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
    v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
    v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
    return (v >> 16) | (v << 16);
}

// Burley's improved Laine-Karras permutation (the constants of the paper's listing 3).
constexpr uint32_t laineKarrasPermutation(uint32_t x, uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// Owen scrambling of the binary fraction x / 2^32: output bit t depends on input bits t..31 only.
constexpr uint32_t nestedUniformScramble(uint32_t x, uint32_t seed) {
    return reverseBits32(laineKarrasPermutation(reverseBits32(x), seed));
}

// A 32-bit fixed-point fraction as a float in [0, 1): the top 24 bits, so 1.0 cannot occur.
constexpr float fixedToUnitFloat(uint32_t x) { return static_cast<float>(x >> 8) * 0x1p-24f; }

} // namespace stipple::detail
