// sampler.cpp — dispatch from a (pixel, dimension) request to its pattern.
#include "sampler.h"

#include "hash.h"
#include "patterns.h"

#include <algorithm>
#include <utility>

namespace stipple {

namespace {
constexpr HashDomain kPatternDomain[STIPPLE_PATTERN_COUNT] = {HashDomain::Independent, HashDomain::Stratified,
                                                             HashDomain::Poisson, HashDomain::PoissonSeed};
}  // namespace

Sampler::Sampler(uint32_t pattern, uint32_t samplesPerPixel, uint64_t seed, std::vector<Dimension> dimensions)
    : pattern_(pattern), samplesPerPixel_(samplesPerPixel), seed_(seed), dimensions_(std::move(dimensions)) {}

uint64_t Sampler::key(uint32_t pixelX, uint32_t pixelY, uint32_t d) const {
  return setKey(seed_, kPatternDomain[pattern_], pixelX, pixelY, d);
}

void Sampler::fillPixel(uint32_t pixelX, uint32_t pixelY, uint32_t d, float* out) const {
  const Dimension& dim = dimensions_[d];
  const uint64_t k = key(pixelX, pixelY, d);
  switch (pattern_) {
    case STIPPLE_PATTERN_INDEPENDENT: return fillIndependent(k, dim, out);
    case STIPPLE_PATTERN_STRATIFIED: return fillStratified(k, dim, out);
    case STIPPLE_PATTERN_POISSON: return fillPoisson(k, dim, out);
    default: return fillPoissonSeed(k, dim, out);
  }
}

void Sampler::sample(uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex, uint32_t d, float* out) const {
  const Dimension& dim = dimensions_[d];
  const uint64_t k = key(pixelX, pixelY, d);
  if (pattern_ == STIPPLE_PATTERN_POISSON_SEED) {
    // One generation for the k points of the sample, not k generations.
    thread_local std::vector<float> scratch;
    scratch.resize(dim.floatsPerPixel());
    fillPoissonSeed(k, dim, scratch.data());
    const float* first = scratch.data() + size_t(sampleIndex) * dim.floatsPerSample();
    std::copy(first, first + dim.floatsPerSample(), out);
    return;
  }
  for (uint32_t j = 0; j < dim.count; ++j) {
    const uint32_t p = sampleIndex * dim.count + j;
    float* point = out + size_t(j) * dim.arity;
    switch (pattern_) {
      case STIPPLE_PATTERN_INDEPENDENT: pointIndependent(k, dim, p, point); break;
      case STIPPLE_PATTERN_STRATIFIED: pointStratified(k, dim, p, point); break;
      default: pointPoisson(k, dim, p, point); break;
    }
  }
}

void Sampler::sampleIndependent(uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex, uint32_t stream, float* out,
                                size_t count) const {
  const uint64_t k = hashCombine(setKey(seed_, HashDomain::PastLayout, pixelX, pixelY, stream), sampleIndex);
  for (size_t i = 0; i < count; ++i) out[i] = unitFloat(hashAt(k, i));
}

}  // namespace stipple
