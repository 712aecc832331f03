// patterns.h — the four sample patterns as pure functions of a set key.
//
// Each pattern serves the set of one (pixel, dimension): M = k*N points of `arity` floats. fill* writes the
// whole set (point p at out[p * arity]); point* writes point p alone and is bitwise equal to fill*'s point p.
// The key is setKey(seed, pattern domain, pixel, dimension).
#pragma once

#include "dimension.h"

#include <cstdint>

namespace stipple {

void fillIndependent(uint64_t key, const Dimension& dim, float* out);
void pointIndependent(uint64_t key, const Dimension& dim, uint32_t p, float* out);

void fillStratified(uint64_t key, const Dimension& dim, float* out);
void pointStratified(uint64_t key, const Dimension& dim, uint32_t p, float* out);

void fillPoisson(uint64_t key, const Dimension& dim, float* out);
void pointPoisson(uint64_t key, const Dimension& dim, uint32_t p, float* out);

// poisson-seed generates its set afresh on every call (the study's cost, kept deliberately); random access to
// one sample therefore goes through a whole fill (Sampler::sample).
void fillPoissonSeed(uint64_t key, const Dimension& dim, float* out);

}  // namespace stipple
