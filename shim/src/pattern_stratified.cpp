// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pattern_stratified.cpp — jittered strata: one sample per used cell of the dimension's StrataGrid.
//
// Order of the set's points (what a prefix of the set is worth):
//  - progressive grids (exact, every axis a power of two; M = 2^m): point p sits in the cell whose coordinates,
//    read as bits interleaved axis by axis (x, y, z, x, ...) from each axis' most significant bit, spell the
//    bit-reversal of q = V(S(p)):
//      S, the index shuffle: a nested uniform scramble from the top bit down (bit k of S(p) is bit k of p flipped
//        by a hash of p's bits above k; reverse(LK(reverse(p))) with the Laine-Karras hash LK, Burley 2020).
//        p < 2^j gives every value of S(p)'s low j bits, and because a flip depends on the higher bits, two
//        dimensions pair their coarse cells anew in every pair of samples.
//      V, the value scramble: LK itself (bit k flipped by a hash of the bits below k), a bijection of the low j
//        bits for every j: Owen scrambling of the cell tree, so the sub-cell a prefix point takes inside its
//        coarse cell is random per coarse cell (without it, every point of a prefix would sit in the same corner
//        of its coarse cell).
//    Hence every prefix of 2^j points (and every aligned block of 2^j) holds one point in each cell of the coarse
//    2^j-cell grid of the first j interleaved bits, uniformly placed in it (progressive jittered sampling). Both
//    seeds come from the (pixel, dimension, block) key.
//    The jitter (a value's 24 - axisBits bits below its cell) is a function of the cell alone, so it does not
//    depend on the order: in 1D the value scramble's own bits above pointBits (V's output before masking: Owen
//    scrambling's jitter, at no cost), in 2D and 3D a 32-bit finaliser per axis of (S(p), axis), S(p) being the
//    cell's q before V (axisJitter). Both are 32-bit integer work, which every vector ISA does in one instruction
//    per step (a 64-bit hash did not).
//  - other grids (non-power-of-two axes, padded grids): a hashed random permutation of the points (Kensler 2013):
//    a prefix is a uniformly random subset of the strata.
// Per (pixel, dimension, block) the key gives the order (rotation or permutation), the padded lines and hole
// offset, and the jitter of every point.
// With the blue-noise flag, the jitter of a point is moved into the pixel's sub-cell of its stratum (named by its
// cell, the same in every pixel; blue_noise.h), so the pixels of a tile stratify each stratum among themselves.
#include "batch_isa.h"
#include "hash.h"
#include "pattern_registry.h"
#include "blue_noise.h"
#include "permutation.h"
#include "progressive_strata.h"
#include "simd_avx512.h"
#include "strata_grid.h"

#include <bit>
#include <memory>

namespace stipple::detail {

template <BatchIsa Isa>
void fillStratified(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out,
                    const CrossPixelStrata* blue = nullptr);
void pointStratified(uint64_t key, const Dimension& dim, uint32_t p, float* out,
                     const CrossPixelStrata* blue = nullptr);

namespace {

struct StratifiedSet {
    uint32_t orderSeed; // index shuffle seed (progressive) or permutation seed
    uint32_t valueSeed; // progressive: the value scramble's seed
    uint64_t jitterKey;
    uint32_t jitterSeed;                   // progressive 2D and 3D: seed of the per-axis 32-bit jitter hash
    uint32_t lineSeed = 0, holeOffset = 0; // padded grids only

    StratifiedSet(uint64_t key, const StrataGrid& grid)
        : orderSeed(static_cast<uint32_t>(key >> 32)), valueSeed(static_cast<uint32_t>(key)),
          jitterKey(key ^ 0x6a09e667f3bcc909ull),
          // The high half of a 64-bit product depends on every bit of the key, not just on one of the two seeds.
          jitterSeed(static_cast<uint32_t>((jitterKey * 0xd1342543de82ef95ull) >> 32)) {
        if (!grid.padded()) return;
        lineSeed = static_cast<uint32_t>(hashAt(key, 1) >> 32);
        holeOffset = static_cast<uint32_t>((hashAt(key, 2) >> 32) % grid.lineLength);
    }
};

// ---- progressive grids ---------------------------------------------------------------------------------------

// Burley, "Practical Hash-based Owen Scrambling" (JCGT 2020), the improved Laine-Karras hash: each step only
// carries information from low bits to high bits, so q mod 2^j is a bijection of p mod 2^j for every j.
constexpr uint32_t laineKarras(uint32_t x, uint32_t seed) {
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

// The 32-bit jitter word of axis c in 2D and 3D: lowbias32 (Wellons' two-multiply finaliser) of (s, c) keyed by
// the set's jitter seed, s = S(p) < 2^pointBits the shuffled index (V maps it to the cell's q one to one). 32-bit
// lane multiplies are one instruction in every vector ISA, the 64-bit finaliser the jitter used before took three
// 64-bit ones; the value keeps the word's top 24 - axisBits bits, so the cell bits plus the jitter still fill all 24
// bits of the float. lowbias32's first step, x ^= x >> 16, is the same for every axis (c < 4 has no bits at 16 and
// up): axisJitter takes its result for c = 0, u = jitterBase(s, seed).
constexpr uint32_t jitterBase(uint32_t s, uint32_t seed) {
    const uint32_t t = (s << 2) ^ seed;
    return t ^ (t >> 16);
}
constexpr uint32_t axisJitter(uint32_t u, uint32_t c) {
    uint32_t x = u ^ c;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    return x ^ (x >> 16);
}

// Blue is a template parameter so that the flagless loop is exactly the plain one (no blue-noise code in it).
template <uint32_t Arity, bool Blue>
[[gnu::always_inline]] inline void progressivePoint(const StratifiedSet& set, const StrataGrid& grid, uint32_t p,
                                                    float* out, const CrossPixelStrata* blue) {
    const uint32_t mask = (1u << grid.pointBits) - 1u;
    // Index shuffle (top-down nested scramble of p), then value scramble (bottom-up: a coarse cell's sub-cell is a
    // hash of the coarse bits), then the cell of q from the table.
    const uint32_t shuffled =
        grid.pointBits <= 16
            ? reverseBits16(laineKarras(reverseBits16(p, grid.pointBits), set.orderSeed) & mask, grid.pointBits)
            : reverseBits(laineKarras(reverseBits(p, grid.pointBits), set.orderSeed) & mask, grid.pointBits);
    const uint32_t scrambled = laineKarras(shuffled, set.valueSeed);
    const uint32_t q = scrambled & mask;
    // The jitter words (a value takes the top 24 - axisBits bits of its axis' word), functions of the cell alone:
    // 1D: the value scramble's bits at and above pointBits, a hash of q's bits (Owen scrambling's own jitter; LK
    // carries low bits up, so the top bits mix most): 32 - pointBits >= 24 - axisBits of them, for free. 2D and 3D:
    // axisJitter per axis of S(p), which V maps to q one to one (the same cell), so the hash does not wait for V.
    uint32_t jitter[3] = {scrambled, 0, 0};
    if constexpr (Arity >= 2)
        for (uint32_t c = 0; c < Arity; ++c) jitter[c] = axisJitter(jitterBase(shuffled, set.jitterSeed), c);
    uint32_t top[3]; // cell[c] << (24 - axisBits[c])
    if (grid.cellTable) {
        const uint32_t* words = grid.cellTable->data() + size_t(q) * Arity;
        for (uint32_t c = 0; c < Arity; ++c) top[c] = words[c];
    } else {
        uint32_t cell[3];
        progressiveCell(q, Arity, grid.axisBits, cell);
        for (uint32_t c = 0; c < Arity; ++c) top[c] = cell[c] << (24 - grid.axisBits[c]);
    }
    const auto value = [](uint32_t topBits, uint32_t axisBits, uint32_t jitter) {
        // < 2^24, so the signed conversion is exact.
        return static_cast<float>(static_cast<int32_t>(topBits | (jitter >> (8 + axisBits)))) * 0x1p-24f;
    };
    if constexpr (Blue) {
        uint32_t cell[3] = {0, 0, 0};
        for (uint32_t c = 0; c < Arity; ++c) cell[c] = top[c] >> (24 - grid.axisBits[c]);
        blue->place((uint64_t(cell[2]) << 42) ^ (uint64_t(cell[1]) << 21) ^ cell[0], Arity, jitter);
        for (uint32_t c = 0; c < Arity; ++c) out[c] = value(top[c], grid.axisBits[c], jitter[c]);
        return;
    }
    for (uint32_t c = 0; c < Arity; ++c) out[c] = value(top[c], grid.axisBits[c], jitter[c]);
}

// ---- progressive grids, the batch path ----------------------------------------------------------------------
//
// The same values as progressivePoint, computed a chunk of points at a time in three loops the compiler vectorises:
// 32-bit scrambles (bit reversal by shifts instead of the byte table, the cell by bit compaction instead of the
// cell table: the same functions), the 32-bit jitter hashes, then the floats. Compiled for AVX2 and AVX-512
// (batch_isa.h); the baseline ISA runs the per-point code.

[[gnu::always_inline]] inline uint32_t reverse32(uint32_t v) {
    v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
    v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
    v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
    v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
    return (v >> 16) | (v << 16);
}

// reverseBits without the bits == 0 branch (two shifts: v >> 32 is undefined, (v >> 31) >> 1 is 0).
[[gnu::always_inline]] inline uint32_t reverseLow(uint32_t v, uint32_t bits) {
    return (reverse32(v) >> (31 - bits)) >> 1;
}

// reverseBits(i, 32) for the 64 lanes of a chunk.
struct ReversedLanes {
    uint32_t word[64];
    constexpr ReversedLanes() : word() {
        for (uint32_t i = 0; i < 64; ++i) word[i] = reverseBits(i, 32);
    }
};
inline constexpr ReversedLanes kReversedLanes{};

// With Blue, the jitters are moved into the pixel's sub-cells as progressivePoint<Arity, true> does (blue_noise.h):
// one 64-bit offsets hash per point, of its cell.
template <uint32_t Arity, bool Blue = false>
[[gnu::always_inline]] inline void progressiveChunks(const StratifiedSet& set, const StrataGrid& grid, uint32_t first,
                                                     uint32_t count, float* out,
                                                     const CrossPixelStrata* blue = nullptr) {
    constexpr uint32_t kChunk = 64;
    const uint32_t bits = grid.pointBits;
    const uint32_t mask = (1u << bits) - 1u;
    const uint32_t orderSeed = set.orderSeed, valueSeed = set.valueSeed;
    const uint32_t jitterSeed = set.jitterSeed;
    uint32_t axisBits[3] = {0, 0, 0}, topShift[3] = {0, 0, 0}, jitterShift[3] = {0, 0, 0};
    for (uint32_t c = 0; c < Arity; ++c) {
        axisBits[c] = grid.axisBits[c];
        topShift[c] = 24 - axisBits[c];
        jitterShift[c] = 8 + axisBits[c];
    }
    uint64_t offsetKey = 0;
    uint32_t lattice[3] = {0, 0, 0};
    if constexpr (Blue) {
        offsetKey = blue->offsetKey();
        for (uint32_t c = 0; c < Arity; ++c) lattice[c] = blue->lattice.c[c];
    }
    alignas(64) uint32_t q[kChunk], cellKey[kChunk]; // cellKey: S(p), what 2D and 3D hash for the jitter
    alignas(64) uint32_t jitter[3][kChunk];
    for (uint32_t base = 0; base < count; base += kChunk) {
        const uint32_t n = count - base < kChunk ? count - base : kChunk;
        const uint32_t chunkFirst = first + base;
        if (n == kChunk && chunkFirst % kChunk == 0) {
            // An aligned chunk: chunkFirst and i < 64 have disjoint bits, so reverse(chunkFirst + i) is
            // reverse(chunkFirst) | reverse(i), the latter from a table of 64 words read in order.
            const uint32_t reversedFirst = reverseBits(chunkFirst, 32);
            for (uint32_t i = 0; i < kChunk; ++i) {
                const uint32_t reversed = ((reversedFirst | kReversedLanes.word[i]) >> (31 - bits)) >> 1;
                const uint32_t shuffled = reverseLow(laineKarras(reversed, orderSeed) & mask, bits);
                cellKey[i] = shuffled;
                jitter[0][i] = laineKarras(shuffled, valueSeed); // 1D's jitter word (progressivePoint)
                q[i] = jitter[0][i] & mask;
            }
        } else {
            for (uint32_t i = 0; i < n; ++i) {
                const uint32_t shuffled =
                    reverseLow(laineKarras(reverseLow(chunkFirst + i, bits), orderSeed) & mask, bits);
                cellKey[i] = shuffled;
                jitter[0][i] = laineKarras(shuffled, valueSeed);
                q[i] = jitter[0][i] & mask;
            }
        }
        if constexpr (Arity >= 2)
            for (uint32_t c = 0; c < Arity; ++c)
                for (uint32_t i = 0; i < n; ++i) jitter[c][i] = axisJitter(jitterBase(cellKey[i], jitterSeed), c);
        float* o = out + size_t(base) * Arity;
        // progressiveCell with one reversal of q for all axes: q's bit a * t + c (axis c's bit t from the top) is bit
        // 31 - a * t - c of r, so compacting r's bits of the right residue mod a lists axis c's bits from the top,
        // and a shift drops the unused low ones (q's bits past pointBits are zero).
        const auto cellsOf = [&](uint32_t qi, uint32_t* cell) {
            const uint32_t r = reverse32(qi);
            if constexpr (Arity == 1) {
                cell[0] = (r >> (31 - axisBits[0])) >> 1;
            } else if constexpr (Arity == 2) {
                cell[0] = compactEvery2(r >> 1) >> (16 - axisBits[0]);
                cell[1] = compactEvery2(r) >> (16 - axisBits[1]);
            } else {
                cell[0] = compactEvery3(r >> 4) >> (10 - axisBits[0]); // compactEvery3 keeps 10 bits
                cell[1] = compactEvery3(r >> 3) >> (10 - axisBits[1]);
                cell[2] = compactEvery3(r >> 2) >> (10 - axisBits[2]);
            }
        };
        if constexpr (Blue) {
            // The cells, the offsets' 64-bit hashes in a loop of their own (the compiler vectorises it as it does
            // independent's), then the moves into the sub-cells and the floats.
            alignas(64) uint32_t cells[3][kChunk];
            alignas(64) uint64_t stratum[kChunk];
            alignas(64) uint32_t offsets[kChunk];
            for (uint32_t i = 0; i < n; ++i) {
                uint32_t cell[3];
                cellsOf(q[i], cell);
                for (uint32_t c = 0; c < Arity; ++c) cells[c][i] = cell[c];
                stratum[i] = cell[0];
                if constexpr (Arity >= 2) stratum[i] ^= uint64_t(cell[1]) << 21;
                if constexpr (Arity == 3) stratum[i] ^= uint64_t(cell[2]) << 42;
            }
            for (uint32_t i = 0; i < n; ++i) offsets[i] = static_cast<uint32_t>(hashAt(offsetKey, stratum[i]));
            for (uint32_t c = 0; c < Arity; ++c)
                for (uint32_t i = 0; i < n; ++i)
                    jitter[c][i] = (cells[c][i] << topShift[c]) |
                                   (jitterInSubCell<Arity>(lattice[c], offsets[i], c, jitter[c][i]) >> jitterShift[c]);
            for (uint32_t i = 0; i < n; ++i)
                for (uint32_t c = 0; c < Arity; ++c)
                    o[size_t(i) * Arity + c] = static_cast<float>(static_cast<int32_t>(jitter[c][i])) * 0x1p-24f;
            continue;
        }
        for (uint32_t i = 0; i < n; ++i) {
            uint32_t cell[3];
            cellsOf(q[i], cell);
            for (uint32_t c = 0; c < Arity; ++c)
                o[size_t(i) * Arity + c] = static_cast<float>(static_cast<int32_t>((cell[c] << topShift[c]) |
                                                                                   (jitter[c][i] >> jitterShift[c]))) *
                                           0x1p-24f;
        }
    }
}

#if defined(STIPPLE_BATCH_ISA_CLONES)
template <uint32_t Arity>
[[STIPPLE_TARGET_AVX2]] void progressiveBatchAvx2(const StratifiedSet& set, const StrataGrid& grid, uint32_t first,
                                                  uint32_t count, float* out) {
    progressiveChunks<Arity>(set, grid, first, count, out);
}
template <uint32_t Arity>
[[STIPPLE_TARGET_AVX2]] void progressiveBlueAvx2(const StratifiedSet& set, const StrataGrid& grid, uint32_t first,
                                                 uint32_t count, float* out, const CrossPixelStrata* blue) {
    progressiveChunks<Arity, true>(set, grid, first, count, out, blue);
}
// AVX-512: hand-written (stratified_avx512.cpp), with and without the blue-noise flag.
template <uint32_t Arity>
void progressiveBatchAvx512(const StratifiedSet& set, const StrataGrid& grid, uint32_t first, uint32_t count,
                            float* out) {
    const ProgressiveKernelArgs args{set.orderSeed,
                                     set.valueSeed,
                                     set.jitterSeed,
                                     grid.pointBits,
                                     {grid.axisBits[0], grid.axisBits[1], grid.axisBits[2]}};
    progressiveAvx512(args, Arity, first, count, out);
}
template <uint32_t Arity>
void progressiveBlueAvx512(const StratifiedSet& set, const StrataGrid& grid, uint32_t first, uint32_t count, float* out,
                           const CrossPixelStrata* blue) {
    const ProgressiveKernelArgs args{set.orderSeed,
                                     set.valueSeed,
                                     set.jitterSeed,
                                     grid.pointBits,
                                     {grid.axisBits[0], grid.axisBits[1], grid.axisBits[2]}};
    progressiveBlueAvx512(args, *blue, Arity, first, count, out);
}
#endif

template <BatchIsa Isa, uint32_t Arity>
void fillProgressive(const StratifiedSet& set, const StrataGrid& grid, uint32_t first, uint32_t count, float* out,
                     const CrossPixelStrata* blue) {
    if (blue) {
#if defined(STIPPLE_BATCH_ISA_CLONES)
        if constexpr (Isa == BatchIsa::Avx512) return progressiveBlueAvx512<Arity>(set, grid, first, count, out, blue);
        if constexpr (Isa == BatchIsa::Avx2) return progressiveBlueAvx2<Arity>(set, grid, first, count, out, blue);
#endif
        for (uint32_t i = 0; i < count; ++i)
            progressivePoint<Arity, true>(set, grid, first + i, out + size_t(i) * Arity, blue);
        return;
    }
#if defined(STIPPLE_BATCH_ISA_CLONES)
    if constexpr (Isa == BatchIsa::Avx512) return progressiveBatchAvx512<Arity>(set, grid, first, count, out);
    if constexpr (Isa == BatchIsa::Avx2) return progressiveBatchAvx2<Arity>(set, grid, first, count, out);
#endif
    // Without wide vectors the per-point code (byte and cell tables) is the faster one: 4.4 against 6.8 ns per
    // value for 1D N = 4096 (SSE2 has no 32-bit lane multiply).
    for (uint32_t i = 0; i < count; ++i)
        progressivePoint<Arity, false>(set, grid, first + i, out + size_t(i) * Arity, nullptr);
}

// ---- other grids ---------------------------------------------------------------------------------------------

// (cell + u) / strata with a 32-bit jitter u, rounded to float, then moved by one ulp if rounding crossed the
// stratum's border, so floor(value * strata) == cell holds exactly and 1.0 never occurs. Rounding moves the
// value by less than one ulp and a stratum spans at least 2 ulps (strata <= 2^22), so one step suffices; the two
// corrections exclude each other and are added as 0 or 1, without a branch, so that a loop of them vectorises.
[[gnu::always_inline]] inline float jittered(uint32_t cell, uint32_t strata, double inverseStrata, uint32_t jitter) {
    const float value = static_cast<float>((double(cell) + double(jitter) * 0x1p-32) * inverseStrata);
    const double scaled = double(value) * strata; // exact: 24-bit mantissa times <= 2^22
    const uint32_t above = scaled >= double(cell) + 1.0, below = scaled < double(cell);
    return std::bit_cast<float>(std::bit_cast<uint32_t>(value) - above + below);
}

// The value of set point q, whose cell is known: the jitter of each axis, moved into the pixel's sub-cell with the
// blue-noise flag, inside the cell.
[[gnu::always_inline]] inline void permutedValue(const StratifiedSet& set, const StrataGrid& grid, uint32_t q,
                                                 uint32_t cell[3], float* out, const CrossPixelStrata* blue) {
    // One 64-bit hash jitters two axes (32 bits each).
    const uint64_t bits01 = hashAt(set.jitterKey, uint64_t(q) * 2);
    uint32_t jitter[3] = {static_cast<uint32_t>(bits01 >> 32), static_cast<uint32_t>(bits01), 0};
    if (grid.arity == 3) jitter[2] = static_cast<uint32_t>(hashAt(set.jitterKey, uint64_t(q) * 2 + 1) >> 32);
    // Blue noise: the stratum (named by its cell, the same in every pixel) is shared with the tile's pixels.
    if (blue) blue->place((uint64_t(cell[2]) << 42) ^ (uint64_t(cell[1]) << 21) ^ cell[0], grid.arity, jitter);
    for (uint32_t c = 0; c < grid.arity; ++c) out[c] = jittered(cell[c], grid.axis[c], grid.inverseAxis[c], jitter[c]);
}

inline void permutedPoint(const StratifiedSet& set, const StrataGrid& grid, uint32_t p, float* out,
                          const CrossPixelStrata* blue) {
    const uint32_t q = permuteIndex(p, grid.points, set.orderSeed);
    uint32_t cell[3] = {0, 0, 0};
    grid.cellOf(q, set.lineSeed, set.holeOffset, cell);
    permutedValue(set, grid, q, cell, out, blue);
}

// The same values as permutedPoint, a chunk of points at a time, in loops the compiler vectorises: the
// permutation's walk for the whole chunk (permuteIndices), the cells, the jitter hashes, then the values axis by
// axis. Per point, the walk's random number of steps cost more than everything else (23 ns per 1D value at
// M = 36, against 0.7 ns for M = 32's progressive grid). With the blue-noise flag the values are placed point by
// point (CrossPixelStrata::place).
template <uint32_t Arity>
[[gnu::always_inline]] inline void permutedChunks(const StratifiedSet& set, const StrataGrid& grid, uint32_t first,
                                                  uint32_t count, float* out, const CrossPixelStrata* blue) {
    constexpr uint32_t kChunk = 64;
    alignas(64) uint32_t q[kChunk], line[kChunk], position[kChunk];
    alignas(64) uint32_t cells[3][kChunk], jitter[3][kChunk];
    for (uint32_t base = 0; base < count; base += kChunk) {
        const uint32_t n = count - base < kChunk ? count - base : kChunk;
        float* o = out + size_t(base) * Arity;
        for (uint32_t i = 0; i < n; ++i) q[i] = first + base + i;
        permuteIndices(q, n, grid.points, set.orderSeed);
        grid.linesOf(q, n, set.lineSeed, set.holeOffset, line, position);
        if (blue) {
            for (uint32_t i = 0; i < n; ++i) {
                uint32_t cell[3] = {0, 0, 0};
                grid.splitLine(line[i], position[i], cell);
                permutedValue(set, grid, q[i], cell, o + size_t(i) * Arity, blue);
            }
            continue;
        }
        for (uint32_t i = 0; i < n; ++i) {
            uint32_t cell[3] = {0, 0, 0};
            grid.splitLine(line[i], position[i], cell);
            for (uint32_t c = 0; c < Arity; ++c) cells[c][i] = cell[c];
        }
        for (uint32_t i = 0; i < n; ++i) {
            const uint64_t bits01 = hashAt(set.jitterKey, uint64_t(q[i]) * 2);
            jitter[0][i] = static_cast<uint32_t>(bits01 >> 32);
            jitter[1][i] = static_cast<uint32_t>(bits01);
        }
        if constexpr (Arity == 3)
            for (uint32_t i = 0; i < n; ++i)
                jitter[2][i] = static_cast<uint32_t>(hashAt(set.jitterKey, uint64_t(q[i]) * 2 + 1) >> 32);
        for (uint32_t c = 0; c < Arity; ++c) {
            const uint32_t strata = grid.axis[c];
            const double inverse = grid.inverseAxis[c];
            for (uint32_t i = 0; i < n; ++i)
                o[size_t(i) * Arity + c] = jittered(cells[c][i], strata, inverse, jitter[c][i]);
        }
    }
}

#if defined(STIPPLE_BATCH_ISA_CLONES)
template <uint32_t Arity>
[[STIPPLE_TARGET_AVX2]] void permutedBatchAvx2(const StratifiedSet& set, const StrataGrid& grid, uint32_t first,
                                               uint32_t count, float* out, const CrossPixelStrata* blue) {
    permutedChunks<Arity>(set, grid, first, count, out, blue);
}
template <uint32_t Arity>
[[STIPPLE_TARGET_AVX512]] void permutedBatchAvx512(const StratifiedSet& set, const StrataGrid& grid, uint32_t first,
                                                   uint32_t count, float* out, const CrossPixelStrata* blue) {
    permutedChunks<Arity>(set, grid, first, count, out, blue);
}
#endif

template <BatchIsa Isa, uint32_t Arity>
void fillPermuted(const StratifiedSet& set, const StrataGrid& grid, uint32_t first, uint32_t count, float* out,
                  const CrossPixelStrata* blue) {
#if defined(STIPPLE_BATCH_ISA_CLONES)
    if constexpr (Isa == BatchIsa::Avx512) return permutedBatchAvx512<Arity>(set, grid, first, count, out, blue);
    if constexpr (Isa == BatchIsa::Avx2) return permutedBatchAvx2<Arity>(set, grid, first, count, out, blue);
#endif
    // Without 32-bit lane multiplies (SSE2) the walk does not vectorise: the per-point code.
    for (uint32_t i = 0; i < count; ++i) permutedPoint(set, grid, first + i, out + size_t(i) * Arity, blue);
}

} // namespace

template <BatchIsa Isa>
void fillStratified(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out,
                    const CrossPixelStrata* blue) {
    const StrataGrid& grid = dim.stateAs<StrataGrid>();
    const StratifiedSet set(key, grid);
    if (grid.progressive) {
        switch (dim.arity) {
        case 1: return fillProgressive<Isa, 1>(set, grid, first, count, out, blue);
        case 2: return fillProgressive<Isa, 2>(set, grid, first, count, out, blue);
        default: return fillProgressive<Isa, 3>(set, grid, first, count, out, blue);
        }
    } else {
        switch (dim.arity) {
        case 1: return fillPermuted<Isa, 1>(set, grid, first, count, out, blue);
        case 2: return fillPermuted<Isa, 2>(set, grid, first, count, out, blue);
        default: return fillPermuted<Isa, 3>(set, grid, first, count, out, blue);
        }
    }
}

void pointStratified(uint64_t key, const Dimension& dim, uint32_t p, float* out, const CrossPixelStrata* blue) {
    const StrataGrid& grid = dim.stateAs<StrataGrid>();
    const StratifiedSet set(key, grid);
    if (!grid.progressive) return permutedPoint(set, grid, p, out, blue);
    if (blue) {
        switch (dim.arity) {
        case 1: return progressivePoint<1, true>(set, grid, p, out, blue);
        case 2: return progressivePoint<2, true>(set, grid, p, out, blue);
        default: return progressivePoint<3, true>(set, grid, p, out, blue);
        }
    }
    switch (dim.arity) {
    case 1: return progressivePoint<1, false>(set, grid, p, out, nullptr);
    case 2: return progressivePoint<2, false>(set, grid, p, out, nullptr);
    default: return progressivePoint<3, false>(set, grid, p, out, nullptr);
    }
}

namespace {
template <BatchIsa Isa>
void fillSet(const SetKey& set, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
    fillStratified<Isa>(set.key, dim, first, count, out);
}

template <BatchIsa Isa>
void blueFillSet(const SetKey& set, const Dimension& dim, uint32_t first, uint32_t count, float* out,
                 const CrossPixelStrata& strata) {
    fillStratified<Isa>(set.key, dim, first, count, out, &strata);
}
} // namespace

extern const PatternOps kStratifiedPattern;
constinit const PatternOps kStratifiedPattern{
    .name = "stratified",
    .domain = HashDomain::Stratified,
    .blockKeying = BlockKeying::Rekeyed,
    .blueNoise = BlueNoiseMode::CrossPixelStrata,
    .prepare =
        [](Dimension& dim) {
            dim.patternState = std::make_shared<const StrataGrid>(StrataGrid::choose(dim.arity, dim.setSize));
        },
    .strata =
        [](const Dimension& dim, uint32_t* axes) {
            for (uint32_t c = 0; c < dim.arity; ++c) axes[c] = dim.stateAs<StrataGrid>().axis[c];
        },
    .point = [](const SetKey& set, const Dimension& dim, uint32_t p,
                float* out) { pointStratified(set.key, dim, p, out); },
    .fill = {fillSet<BatchIsa::Baseline>, fillSet<BatchIsa::Avx2>, fillSet<BatchIsa::Avx512>},
    .fillStrata = {blueFillSet<BatchIsa::Baseline>, blueFillSet<BatchIsa::Avx2>, blueFillSet<BatchIsa::Avx512>},
};

} // namespace stipple::detail
