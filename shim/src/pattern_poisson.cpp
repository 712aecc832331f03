// pattern_poisson.cpp — serving Poisson-disk sets: "poisson" from the cache, "poisson-seed" generated fresh.
//
// A served set is a stored toroidal set moved by a symmetry of the torus (axis permutation and reflections) and
// a Cranley-Patterson shift, hashed from the set key. These maps are isometries of the torus, so they keep the
// set's minimum distance (rho); the shift makes every sample uniformly distributed over [0,1)^arity whatever the
// stored set is.
// Order: "poisson" serves the stored order (made progressive by the cache, progressive_order.h) shuffled only
// within each layer [2^j, 2^(j+1)) by a hashed permutation (Kensler 2013). Every prefix of 2^j points is thus
// exactly the stored prefix (high rho), other prefixes add a random part of the next layer; the shuffle keeps two
// dimensions that drew the same stored set and symmetry from pairing their samples point for point.
// "poisson-seed" serves its fresh set in a hashed random order.
#include "error.h"
#include "hash.h"
#include "patterns.h"
#include "permutation.h"
#include "pointsets/pointsets.h"

#include <algorithm>
#include <bit>
#include <string>
#include <vector>

namespace stipple {

namespace {

constexpr uint8_t kAxisOrders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

struct TorusMap {
  uint32_t orderSeed;
  uint8_t source[3] = {0, 1, 2};  // output axis c reads stored axis source[c]
  bool reflect[3] = {false, false, false};
  float shift[3];

  // One hash gives the three shifts (21 bits each: multiples of 2^-21), one the symmetry, one the order.
  TorusMap(uint64_t key, uint32_t arity, bool useSymmetry) {
    const uint64_t shifts = hashAt(key, 3);
    for (uint32_t c = 0; c < 3; ++c) shift[c] = float((shifts >> (43 - 21 * c)) & 0x1fffffu) * 0x1p-21f;
    const uint64_t symmetry = hashAt(key, 2);
    orderSeed = static_cast<uint32_t>(hashAt(key, 1) >> 32);
    if (!useSymmetry) return;
    const uint32_t axisOrder = arity == 3 ? uint32_t(symmetry % 6) : arity == 2 ? uint32_t(symmetry % 2) * 2 : 0;
    for (uint32_t c = 0; c < 3; ++c) {
      source[c] = kAxisOrders[axisOrder][c];
      reflect[c] = (symmetry >> (32 + c)) & 1;
    }
  }

  // s + x or s - x, wrapped into [0,1) without branches (the wrap is a coin flip per value: a branch would be
  // mispredicted half the time). s - x in (-1, 1) plus 1 may round up to 1.0, which the second step maps to 0;
  // s + x in [1, 2) minus 1 is exact.
  void apply(const float* stored, uint32_t arity, float* out) const {
    for (uint32_t c = 0; c < arity; ++c) {
      const float x = stored[source[c]];
      float v = shift[c] + (reflect[c] ? -x : x);
      v += float(v < 0.0f);
      v -= float(v >= 1.0f);
      out[c] = v;
    }
  }
};


// Position p of the served order -> stored point: p's layer [2^j, 2^(j+1)) (clipped to M) is shuffled.
inline uint32_t layeredIndex(uint32_t p, uint32_t points, uint32_t seed) {
  if (p < 2) return p;
  const uint32_t base = std::bit_floor(p);
  const uint32_t size = std::min(base, points - base);
  return base + permuteIndex(p - base, size, seed ^ base);
}

const float* cachedSet(uint64_t key, const Dimension& dim) {
  const PoissonFamily& family = *dim.poisson;
  return family.set(static_cast<uint32_t>(hashAt(key, 0) % family.setCount()));
}

// A fresh set per call: allocating here is part of the cost the study paid.
std::vector<float> freshSeedSet(uint64_t key, const Dimension& dim) {
  std::vector<float> set = pointsets::generatePoissonSeed(int(dim.arity), dim.setSize, hashAt(key, 6));
  if (set.size() != size_t(dim.setSize) * dim.arity)
    throw Error(STIPPLE_ERROR_INTERNAL, "poisson-seed generator returned " + std::to_string(set.size()) +
                                            " floats; expected " + std::to_string(size_t(dim.setSize) * dim.arity));
  return set;
}

}  // namespace

void fillPoisson(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
  const TorusMap map(key, dim.arity, true);
  const float* stored = cachedSet(key, dim);
  for (uint32_t i = 0; i < count; ++i) {
    const uint32_t q = layeredIndex(first + i, dim.setSize, map.orderSeed);
    map.apply(stored + size_t(q) * dim.arity, dim.arity, out + size_t(i) * dim.arity);
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

}  // namespace stipple
