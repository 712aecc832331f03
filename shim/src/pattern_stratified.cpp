// pattern_stratified.cpp — jittered strata: one sample per used cell of the dimension's StrataGrid.
//
// Per (pixel, dimension) the key gives: the permutation of sample order (so sample i of this dimension is not
// tied to sample i of another), the choice of padded lines and hole offset, and the jitter of every point.
#include "blue_noise.h"
#include "hash.h"
#include "patterns.h"
#include "permutation.h"

#include <bit>

namespace stipple {

namespace {

struct StratifiedSet {
    uint32_t orderSeed, lineSeed, holeOffset;
    uint64_t jitterKey;

    StratifiedSet(uint64_t key, const StrataGrid& grid)
        : orderSeed(static_cast<uint32_t>(hashAt(key, 0) >> 32)), lineSeed(static_cast<uint32_t>(hashAt(key, 1) >> 32)),
          holeOffset(static_cast<uint32_t>((hashAt(key, 2) >> 32) % grid.lineLength)), jitterKey(hashCombine(key, 3)) {}
};

// (cell + u) / strata with a 32-bit jitter u, rounded to float, then moved by one ulp if rounding crossed the
// stratum's border, so floor(value * strata) == cell holds exactly and 1.0 never occurs. Rounding moves the
// value by less than one ulp and a stratum spans at least 2 ulps (strata <= 2^22), so one step suffices.
inline float jittered(uint32_t cell, uint32_t strata, double inverseStrata, uint32_t jitter) {
    float value = static_cast<float>((double(cell) + double(jitter) * 0x1p-32) * inverseStrata);
    const double scaled = double(value) * strata; // exact: 24-bit mantissa times <= 2^22
    if (scaled >= double(cell) + 1.0)
        value = std::bit_cast<float>(std::bit_cast<uint32_t>(value) - 1);
    else if (scaled < double(cell))
        value = std::bit_cast<float>(std::bit_cast<uint32_t>(value) + 1);
    return value;
}

inline void stratifiedPoint(const StratifiedSet& set, const Dimension& dim, uint32_t p, float* out,
                            const CrossPixelStrata* blue) {
    const StrataGrid& grid = dim.grid;
    const uint32_t q = permuteIndex(p, dim.setSize, set.orderSeed);
    uint32_t cell[3] = {0, 0, 0};
    grid.cellOf(q, set.lineSeed, set.holeOffset, cell);
    // One 64-bit hash jitters two axes (32 bits each).
    const uint64_t bits01 = hashAt(set.jitterKey, uint64_t(q) * 2);
    uint32_t jitter[3] = {static_cast<uint32_t>(bits01 >> 32), static_cast<uint32_t>(bits01), 0};
    if (dim.arity == 3) jitter[2] = static_cast<uint32_t>(hashAt(set.jitterKey, uint64_t(q) * 2 + 1) >> 32);
    // Blue noise: the stratum (named by its cell, the same in every pixel) is shared with the tile's pixels.
    if (blue) blue->place((uint64_t(cell[2]) << 42) ^ (uint64_t(cell[1]) << 21) ^ cell[0], dim.arity, jitter);
    for (uint32_t c = 0; c < dim.arity; ++c) out[c] = jittered(cell[c], grid.axis[c], grid.inverseAxis[c], jitter[c]);
}

} // namespace

void fillStratified(uint64_t key, const Dimension& dim, float* out, const CrossPixelStrata* blue) {
    const StratifiedSet set(key, dim.grid);
    for (uint32_t p = 0; p < dim.setSize; ++p) stratifiedPoint(set, dim, p, out + size_t(p) * dim.arity, blue);
}

void pointStratified(uint64_t key, const Dimension& dim, uint32_t p, float* out, const CrossPixelStrata* blue) {
    stratifiedPoint(StratifiedSet(key, dim.grid), dim, p, out, blue);
}

} // namespace stipple
