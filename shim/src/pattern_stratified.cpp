// pattern_stratified.cpp — jittered strata: one sample per used cell of the dimension's StrataGrid.
//
// Per (pixel, dimension) the key gives: the permutation of sample order (so sample i of this dimension is not
// tied to sample i of another), the choice of padded lines and hole offset, and the jitter of every point.
#include "hash.h"
#include "patterns.h"
#include "permutation.h"

#include <cmath>

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

// (cell + u) / strata rounded to float, then nudged by one ulp if rounding crossed the stratum's border, so
// floor(value * strata) == cell holds exactly and 1.0 never occurs.
inline float jittered(uint32_t cell, uint32_t strata, double u) {
  float value = static_cast<float>((double(cell) + u) / double(strata));
  const double scaled = double(value) * strata;  // exact: 24-bit mantissa times <= 2^22
  if (scaled >= double(cell) + 1.0) value = std::nextafter(value, 0.0f);
  else if (scaled < double(cell)) value = std::nextafter(value, 1.0f);
  return value;
}

inline void stratifiedPoint(const StratifiedSet& set, const Dimension& dim, uint32_t p, float* out) {
  const StrataGrid& grid = dim.grid;
  const uint32_t q = permuteIndex(p, dim.setSize, set.orderSeed);
  uint32_t cell[3];
  grid.cellOf(q, set.lineSeed, set.holeOffset, cell);
  const uint64_t first = uint64_t(q) * dim.arity;
  for (uint32_t c = 0; c < dim.arity; ++c)
    out[c] = jittered(cell[c], grid.axis[c], unitDouble(hashAt(set.jitterKey, first + c)));
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
