// patterns.h — the sample patterns as pure functions of a set key.
//
// Each pattern serves the set of one (pixel, dimension, block): M points of `arity` floats (M = k*N for a
// declared dimension, N for a streamed one). fill* writes points [first, first + count) of the set (point p at
// out[(p - first) * arity]); point* writes point p alone and is bitwise equal to fill*'s point p. The key is
// Sampler::setKey (seed, pattern domain, pixel, dimension, arity for streams, block).
// A new pattern adds its pair here, a case to Sampler's dispatch and a row to the tables in abi.cpp.
#pragma once

#include "dimension.h"

#include <cstdint>

namespace stipple {

void fillIndependent(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out);
void pointIndependent(uint64_t key, const Dimension& dim, uint32_t p, float* out);

void fillStratified(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out);
void pointStratified(uint64_t key, const Dimension& dim, uint32_t p, float* out);

// The stored set a "poisson" set key serves: its top 32 bits scaled to [0, setCount) (no division per value).
constexpr uint32_t poissonSetIndex(uint64_t key, uint32_t setCount) {
  return static_cast<uint32_t>(((key >> 32) * setCount) >> 32);
}
void fillPoisson(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out);
void pointPoisson(uint64_t key, const Dimension& dim, uint32_t p, float* out);

// poisson-seed generates its set afresh on every call (the study's cost, kept deliberately); random access to
// one point therefore goes through a whole generation.
void fillPoissonSeed(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out);
void pointPoissonSeed(uint64_t key, const Dimension& dim, uint32_t p, float* out);

}  // namespace stipple
