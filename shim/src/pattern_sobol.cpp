// pattern_sobol.cpp — Owen-scrambled Sobol' points (Burley 2020), padded per (pixel, dimension).
//
// The set of one (pixel, dimension) is M points of the first `arity` Sobol' dimensions (M = k*N for a declared
// dimension, N for a stream). Let L = 2^m be the smallest power of two >= M. Sample index i lies in block
// b = i / N (the sampler passes SobolSet::atBlock(b)); point r of that block has the Sobol' index
//     (block(b) << m) | (nestedUniformScramble(r, indexSeed) mod L),   block(b) = blockBase + b * blockStride,
// where the index shuffle (an Owen scramble of r's binary digits) maps every prefix [0, 2^j) of r onto an
// aligned run of 2^j Sobol' indices, i.e. a (0,j,2)-net in 2D. Each coordinate is then Owen-scrambled with its
// own seed. indexSeed and the scramble seeds are hashed from the set key, so the dimensions of one pixel are
// decorrelated (the pairing of points across dimensions is shuffled), as in Burley's padding.
// - M a power of two: each block is a full (0,m,2)-net (3D: a (1,m,3)-net), and block b follows block b - 1 in
//   the sequence, so the first 2^j blocks together are again a net: progressive by construction.
// - Other M: each block is the first M points of a shuffled net of L points (every prefix of a power-of-two
//   length is a net; the rest is a nested-scrambled part of the next doubling). Never a fall-back to random.
// The index is 32-bit: past 2^32 points the sequence repeats.
#include "owen_scrambling.h"
#include "patterns.h"
#include "sobol_matrices.h"

namespace stipple {

namespace {

inline void sobolPoint(const SobolSet& set, const Dimension& dim, uint32_t r, float* out) {
    const uint32_t lowMask = dim.log2Length == 32 ? ~0u : (1u << dim.log2Length) - 1u;
    const uint32_t index = (dim.log2Length >= 32 ? 0u : set.blockBase << dim.log2Length) |
                           (nestedUniformScramble(r, set.indexSeed) & lowMask);
    for (uint32_t c = 0; c < dim.arity; ++c)
        out[c] = fixedToUnitFloat(nestedUniformScramble(sobolSample(index, c), set.scramble[c]));
}

} // namespace

SobolSet SobolSet::perPixel(uint64_t key) {
    SobolSet set;
    const uint64_t h0 = hashAt(key, 0), h1 = hashAt(key, 1);
    set.indexSeed = static_cast<uint32_t>(h0);
    set.scramble[0] = static_cast<uint32_t>(h0 >> 32);
    set.scramble[1] = static_cast<uint32_t>(h1);
    set.scramble[2] = static_cast<uint32_t>(h1 >> 32);
    return set;
}

void fillSobol(const SobolSet& set, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
    for (uint32_t i = 0; i < count; ++i) sobolPoint(set, dim, first + i, out + size_t(i) * dim.arity);
}

void pointSobol(const SobolSet& set, const Dimension& dim, uint32_t p, float* out) { sobolPoint(set, dim, p, out); }

} // namespace stipple
