// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pattern_lattice.cpp — a randomly shifted rank-1 lattice sequence, extensible in base 2.
//
// Point j of the sequence is frac(phi2(j) * z + u) per axis: phi2 is the base-2 radical inverse (the reversed
// 32 bits of j as a binary fraction), z = (1, 364981, 245389) the generating vector of Hickernell, Kritzer, Kuo
// and Nuyens ("Weighted compound integration rules with higher order convergence for all N", 2012; OpenQMC's
// lattice uses it too), u a random shift per set. In 32-bit fixed point the point is z * reverse(j) + u mod 2^32,
// so the first 2^m points are exactly the lattice {k z / 2^m} shifted by u, and every prefix of 2^j points of the
// sequence is again a shifted lattice: the pattern is progressive in N.
//
// Sample index i of a set of M points (L = 2^m >= M) lies in block b = i / N; its sequence index is
//     ((blockBase + b) << m) | (nestedUniformScramble(i mod N, indexSeed) mod L),
// as sobol's: the index shuffle maps every prefix [0, 2^j) onto an aligned run of 2^j sequence indices, and the
// blocks continue the sequence for 2^(32-m) blocks, the period N * 2^(32-m) sample indices; block b past them is
// block b mod 2^(32-m) of a freshly shifted and shuffled sequence, generation b / 2^(32-m) (sequence_generation.h).
// indexSeed and the shifts are hashed from the set key, so the dimensions of a pixel are decorrelated (padding).
// The shift makes every point uniform on the unit cube.
//
// Strengths and weaknesses (shim/POINTSETS.md): a lattice integrates smooth PERIODIC integrands at a high rate and
// spaces its points evenly (large minimum distance); on non-periodic integrands a shifted lattice has a seam at the
// shift, and its 1D projections are evenly spaced grids with one common offset, so a 1D ramp sees the error of a
// single jittered offset.
#include "batch_kernel.h"
#include "owen_scrambling.h"
#include "pattern_registry.h"
#include "sequence_generation.h"

namespace stipple::detail {

namespace {

constexpr uint32_t kLatticeVector[3] = {1u, 364981u, 245389u};

struct LatticeSet {
    uint32_t indexSeed;
    uint32_t shift[3];
    uint32_t high; // block << m (the block within its generation): the block's part of the sequence index
    uint32_t lowMask;
};

LatticeSet latticeSet(const SetKey& blockKey, const Dimension& dim) {
    const SetKey set = sequenceGeneration(blockKey, blocksPerGenerationPadded(dim.log2Length));
    const uint64_t h0 = hashAt(set.key, 0), h1 = hashAt(set.key, 1);
    const uint32_t bits = dim.log2Length >= 32 ? 32 : dim.log2Length;
    return LatticeSet{static_cast<uint32_t>(h0),
                      {static_cast<uint32_t>(h0 >> 32), static_cast<uint32_t>(h1), static_cast<uint32_t>(h1 >> 32)},
                      bits >= 32 ? 0u : set.block << bits,
                      bits >= 32 ? ~0u : (1u << bits) - 1u};
}

template <uint32_t Arity>
[[gnu::always_inline]] inline void latticePoint(const LatticeSet& s, uint32_t r, float* out) {
    const uint32_t phi = reverseBits32(s.high | (nestedUniformScramble(r, s.indexSeed) & s.lowMask));
    for (uint32_t c = 0; c < Arity; ++c) out[c] = fixedToUnitFloat(kLatticeVector[c] * phi + s.shift[c]);
}

// The batch loop and its ISA variants come from batch_kernel.h.
struct LatticeKernel {
    using Set = LatticeSet;
    static Set set(const SetKey& key, const Dimension& dim) { return latticeSet(key, dim); }
    template <uint32_t Arity>
    [[gnu::always_inline]] static void point(const Set& s, uint32_t r, float* out) {
        latticePoint<Arity>(s, r, out);
    }
};

} // namespace

// Blocks continue the sequence (SetKey::block), a fresh one per period. The blue-noise flag is refused: its only
// mechanism for a set that is not strata, a per-pixel toroidal shift of a tile's set, adds a seam on non-periodic
// integrands (as for sobol).
extern const PatternOps kLatticePattern;
constinit const PatternOps kLatticePattern{
    .name = "lattice",
    .domain = HashDomain::Lattice,
    .blockKeying = BlockKeying::Sequence,
    .point = kernelPoint<LatticeKernel>,
    .fill = kernelFills<LatticeKernel>(),
};

} // namespace stipple::detail
