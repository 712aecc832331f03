// pattern_stratified.cpp — jittered strata: one sample per used cell of the dimension's StrataGrid.
//
// Per (pixel, dimension) the key gives: the permutation of sample order (so sample i of this dimension is not
// tied to sample i of another), the choice of padded lines and hole offset, and the jitter of every point.
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
      : orderSeed(static_cast<uint32_t>(hashAt(key, 0) >> 32)),
        lineSeed(static_cast<uint32_t>(hashAt(key, 1) >> 32)),
        holeOffset(static_cast<uint32_t>((hashAt(key, 2) >> 32) % grid.lineLength)),
        jitterKey(hashCombine(key, 3)) {}
};

// (cell + u) / strata with a 32-bit jitter u, rounded to float, then moved by one ulp if rounding crossed the
// stratum's border, so floor(value * strata) == cell holds exactly and 1.0 never occurs. Rounding moves the
// value by less than one ulp and a stratum spans at least 2 ulps (strata <= 2^22), so one step suffices.
inline float jittered(uint32_t cell, uint32_t strata, double inverseStrata, uint32_t jitter) {
  float value = static_cast<float>((double(cell) + double(jitter) * 0x1p-32) * inverseStrata);
  const double scaled = double(value) * strata;  // exact: 24-bit mantissa times <= 2^22
  if (scaled >= double(cell) + 1.0) value = std::bit_cast<float>(std::bit_cast<uint32_t>(value) - 1);
  else if (scaled < double(cell)) value = std::bit_cast<float>(std::bit_cast<uint32_t>(value) + 1);
  return value;
}

inline void stratifiedPoint(const StratifiedSet& set, const Dimension& dim, uint32_t p, float* out) {
  const StrataGrid& grid = dim.grid;
  const uint32_t q = permuteIndex(p, dim.setSize, set.orderSeed);
  uint32_t cell[3];
  grid.cellOf(q, set.lineSeed, set.holeOffset, cell);
  // One 64-bit hash jitters two axes (32 bits each).
  const uint64_t bits01 = hashAt(set.jitterKey, uint64_t(q) * 2);
  out[0] = jittered(cell[0], grid.axis[0], grid.inverseAxis[0], static_cast<uint32_t>(bits01 >> 32));
  if (dim.arity == 1) return;
  out[1] = jittered(cell[1], grid.axis[1], grid.inverseAxis[1], static_cast<uint32_t>(bits01));
  if (dim.arity == 2) return;
  const uint64_t bits2 = hashAt(set.jitterKey, uint64_t(q) * 2 + 1);
  out[2] = jittered(cell[2], grid.axis[2], grid.inverseAxis[2], static_cast<uint32_t>(bits2 >> 32));
}

}  // namespace

void fillStratified(uint64_t key, const Dimension& dim, float* out) {
  const StratifiedSet set(key, dim.grid);
  for (uint32_t p = 0; p < dim.setSize; ++p) stratifiedPoint(set, dim, p, out + size_t(p) * dim.arity);
}

void pointStratified(uint64_t key, const Dimension& dim, uint32_t p, float* out) {
  stratifiedPoint(StratifiedSet(key, dim.grid), dim, p, out);
}

}  // namespace stipple
