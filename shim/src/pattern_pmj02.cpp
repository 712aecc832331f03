// pattern_pmj02.cpp — progressive multi-jittered (0,2) sequences, served from cached families.
//
// Each (pixel, dimension) set takes one cached pmj02 sequence of L = 2^m >= M points (pmj02_family.h) by hash
// and serves its first M points: 2D points are (x, y) of that sequence; 1D points its x; 3D points its (x, y)
// and, for z, the x of a second, different sequence of the family (the pmj02 construction is 2D; z is then a
// progressive stratified 1D sequence on its own). Randomisation, all hashed from the set key:
// - an index shuffle that keeps every octave [2^j, 2^(j+1)) in place and Owen-scrambles the order inside it, so
//   every prefix of 2^j points is exactly the sequence's own prefix (a (0,j,2)-net) while two dimensions that
//   drew the same sequence still pair their points differently;
// - Owen scrambling of every coordinate, which maps elementary intervals onto elementary intervals (the nets
//   stay nets) and makes every point uniformly distributed.
// Sample indices past the set (block b = i / N > 0) take the first M points of a set randomised from the block's
// key hashCombine(set key, b) (the sampler computes it; block 0 is hashCombine(set key, 0)).
#include "owen_scrambling.h"
#include "pattern_registry.h"
#include "patterns.h"

#include <bit>

namespace stipple::detail {

namespace {

struct Pmj02Set {
    uint32_t sequence, zSequence;
    uint32_t indexSeed, zIndexSeed;
    uint32_t scramble[3];

    Pmj02Set(uint64_t key, const Pmj02Family& family) {
        const uint64_t h0 = hashAt(key, 0), h1 = hashAt(key, 1), h2 = hashAt(key, 2);
        sequence = static_cast<uint32_t>((h0 >> 32) % family.setCount());
        // A different sequence for z: the same one would tie z to x.
        zSequence = (sequence + 1 + static_cast<uint32_t>(h0 % (family.setCount() - 1))) % family.setCount();
        indexSeed = static_cast<uint32_t>(h1);
        zIndexSeed = static_cast<uint32_t>(h1 >> 32);
        scramble[0] = static_cast<uint32_t>(h2);
        scramble[1] = static_cast<uint32_t>(h2 >> 32);
        scramble[2] = static_cast<uint32_t>(hashAt(key, 3));
    }
};

// Keeps octaves in place, Owen-scrambles the order inside each.
inline uint32_t octaveShuffle(uint32_t i, uint32_t seed) {
    if (i < 2) return i;
    const uint32_t octave = std::bit_floor(i);
    return octave | (nestedUniformScramble(i - octave, seed ^ octave) & (octave - 1));
}

inline void pmj02Point(const Pmj02Set& set, const Pmj02Family& family, uint32_t arity, uint32_t r, float* out) {
    const FixedPoint2& xy = family.sequence(set.sequence)[octaveShuffle(r, set.indexSeed)];
    out[0] = fixedToUnitFloat(nestedUniformScramble(xy.x, set.scramble[0]));
    if (arity == 1) return;
    out[1] = fixedToUnitFloat(nestedUniformScramble(xy.y, set.scramble[1]));
    if (arity == 2) return;
    const FixedPoint2& z = family.sequence(set.zSequence)[octaveShuffle(r, set.zIndexSeed)];
    out[2] = fixedToUnitFloat(nestedUniformScramble(z.x, set.scramble[2]));
}

} // namespace

void fillPmj02(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
    const Pmj02Family& family = *dim.pmj02;
    const Pmj02Set set(key, family);
    for (uint32_t i = 0; i < count; ++i) pmj02Point(set, family, dim.arity, first + i, out + size_t(i) * dim.arity);
}

void pointPmj02(uint64_t key, const Dimension& dim, uint32_t p, float* out) {
    const Pmj02Family& family = *dim.pmj02;
    pmj02Point(Pmj02Set(key, family), family, dim.arity, p, out);
}

namespace {
void fillSet(const SetKey& set, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
    fillPmj02(set.key, dim, first, count, out);
}
} // namespace

// Every block keyed hashCombine(set key, b), block 0 included; no batch kernels per ISA (table lookups).
extern const PatternOps kPmj02Pattern;
constinit const PatternOps kPmj02Pattern{
    .name = "pmj02",
    .domain = HashDomain::Pmj02,
    .blockKeying = BlockKeying::EveryBlock,
    .blueNoise = BlueNoiseMode::TileShift,
    .latticeUse = LatticeUse::Shift,
    .limits = {.maxArity = 3, .maxSetSize = 1u << Pmj02Family::kMaxLog2Length},
    .prepare = [](Dimension& dim) { dim.pmj02 = Pmj02Family::acquire(dim.log2Length); },
    .prepareStreamsOnFirstUse = false, // a family generates its sequences on first use
    .strata = nullptr,
    .point = [](const SetKey& set, const Dimension& dim, uint32_t p, float* out) { pointPmj02(set.key, dim, p, out); },
    .fill = {fillSet, fillSet, fillSet},
    .fillStrata = nullptr,
};

} // namespace stipple::detail
