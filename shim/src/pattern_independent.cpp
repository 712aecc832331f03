// pattern_independent.cpp — independent uniform values: value (p, c) is the hash of (set key, p * arity + c).
#include "hash.h"
#include "patterns.h"

namespace stipple {

void fillIndependent(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
  const uint64_t begin = uint64_t(first) * dim.arity;
  const uint64_t n = uint64_t(count) * dim.arity;
  for (uint64_t i = 0; i < n; ++i) out[i] = unitFloat(hashAt(key, begin + i));
}

void pointIndependent(uint64_t key, const Dimension& dim, uint32_t p, float* out) {
  const uint64_t first = uint64_t(p) * dim.arity;
  for (uint32_t c = 0; c < dim.arity; ++c) out[c] = unitFloat(hashAt(key, first + c));
}

}  // namespace stipple
