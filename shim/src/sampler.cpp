// sampler.cpp — dispatch from a (pixel, dimension, sample) request to its pattern and its set.
#include "sampler.h"

#include "hash.h"
#include "patterns.h"
#include "poisson_cache.h"

#include <algorithm>
#include <utility>

namespace stipple {

namespace {
constexpr HashDomain kPatternDomain[STIPPLE_PATTERN_COUNT] = {HashDomain::Independent, HashDomain::Stratified,
                                                             HashDomain::Poisson, HashDomain::PoissonSeed};
// Words folded into a key: a stream's arity, a block index > 0 (block 0 keeps the 1.0 key of the layout).
constexpr uint64_t kStreamWord = 0x57e4a3c0ffee0000ull;
constexpr uint64_t kBlockWord = 0xb10c000000000000ull;

constexpr uint64_t blockKey(uint64_t key, uint32_t block) {
  return block == 0 ? key : hashCombine(key, kBlockWord | block);
}
}  // namespace

Dimension makePatternDimension(uint32_t pattern, uint32_t arity, uint32_t count, uint32_t points) {
  Dimension dim;
  dim.arity = arity;
  dim.count = count;
  dim.setSize = points;
  if (pattern == STIPPLE_PATTERN_STRATIFIED) dim.grid = StrataGrid::choose(arity, points);
  if (pattern == STIPPLE_PATTERN_POISSON) dim.poisson = PoissonCache::global().acquire(arity, points);
  return dim;
}

Sampler::Sampler(uint32_t pattern, uint32_t samplesPerPixel, uint64_t seed, std::vector<Dimension> dimensions)
    : pattern_(pattern),
      samplesPerPixel_(samplesPerPixel),
      seed_(seed),
      seedKey_(seedKey(seed, kPatternDomain[pattern])),
      dimensions_(std::move(dimensions)) {
  // Streams: grids now (cheap), Poisson families on first use (they count against the cache budget).
  for (uint32_t a = 1; a <= 3; ++a) {
    Dimension& s = streams_[a - 1];
    s.arity = a;
    s.setSize = samplesPerPixel;
    if (pattern == STIPPLE_PATTERN_STRATIFIED) s.grid = StrataGrid::choose(a, samplesPerPixel);
  }
}

uint64_t Sampler::layoutKey(uint32_t pixelX, uint32_t pixelY, uint32_t d, uint32_t block) const {
  return blockKey(setKeyFrom(seedKey_, pixelX, pixelY, d), block);
}

uint64_t Sampler::streamKey(uint32_t pixelX, uint32_t pixelY, uint32_t d, uint32_t arity, uint32_t block) const {
  return blockKey(hashCombine(setKeyFrom(seedKey_, pixelX, pixelY, d), kStreamWord | arity), block);
}

const Dimension& Sampler::streamDimension(uint32_t arity) const {
  const Dimension& s = streams_[arity - 1];
  if (pattern_ == STIPPLE_PATTERN_POISSON)
    std::call_once(streamFamilyOnce_[arity - 1], [&] {
      const_cast<Dimension&>(s).poisson = PoissonCache::global().acquire(arity, samplesPerPixel_);
    });
  return s;
}

void Sampler::fill(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out) const {
  switch (pattern_) {
    case STIPPLE_PATTERN_INDEPENDENT: return fillIndependent(key, dim, first, count, out);
    case STIPPLE_PATTERN_STRATIFIED: return fillStratified(key, dim, first, count, out);
    case STIPPLE_PATTERN_POISSON: return fillPoisson(key, dim, first, count, out);
    default: return fillPoissonSeed(key, dim, first, count, out);
  }
}

void Sampler::point(uint64_t key, const Dimension& dim, uint32_t p, float* out) const {
  switch (pattern_) {
    case STIPPLE_PATTERN_INDEPENDENT: return pointIndependent(key, dim, p, out);
    case STIPPLE_PATTERN_STRATIFIED: return pointStratified(key, dim, p, out);
    case STIPPLE_PATTERN_POISSON: return pointPoisson(key, dim, p, out);
    default: return pointPoissonSeed(key, dim, p, out);
  }
}

void Sampler::fillPixel(uint32_t pixelX, uint32_t pixelY, uint32_t d, float* out) const {
  const Dimension& dim = dimensions_[d];
  fill(layoutKey(pixelX, pixelY, d, 0), dim, 0, dim.setSize, out);
}

void Sampler::sample(uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex, uint32_t d, float* out) const {
  const Dimension& dim = dimensions_[d];
  const uint32_t block = sampleIndex < samplesPerPixel_ ? 0 : sampleIndex / samplesPerPixel_;  // no division in block 0
  const uint32_t position = sampleIndex - block * samplesPerPixel_;
  const uint64_t key = layoutKey(pixelX, pixelY, d, block);
  if (dim.count == 1) return point(key, dim, position, out);
  fill(key, dim, position * dim.count, dim.count, out);  // one generation for poisson-seed, not k
}

void Sampler::stream(uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex, uint32_t d, uint32_t arity,
                     float* out) const {
  const uint32_t block = sampleIndex < samplesPerPixel_ ? 0 : sampleIndex / samplesPerPixel_;
  const uint32_t position = sampleIndex - block * samplesPerPixel_;
  point(streamKey(pixelX, pixelY, d, arity, block), streamDimension(arity), position, out);
}

void Sampler::streamFill(uint32_t pixelX, uint32_t pixelY, uint32_t firstSample, uint32_t count, uint32_t d,
                         uint32_t arity, float* out) const {
  const Dimension& dim = streamDimension(arity);
  uint64_t i = firstSample;
  const uint64_t end = uint64_t(firstSample) + count;
  while (i < end) {  // one fill per block touched
    const uint32_t block = static_cast<uint32_t>(i / samplesPerPixel_);
    const uint32_t position = static_cast<uint32_t>(i - uint64_t(block) * samplesPerPixel_);
    const uint32_t run = static_cast<uint32_t>(std::min<uint64_t>(end - i, samplesPerPixel_ - position));
    fill(streamKey(pixelX, pixelY, d, arity, block), dim, position, run, out);
    out += size_t(run) * arity;
    i += run;
  }
}

void Sampler::sampleIndependent(uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex, uint32_t stream, float* out,
                                size_t count) const {
  const uint64_t k = hashCombine(setKey(seed_, HashDomain::PastLayout, pixelX, pixelY, stream), sampleIndex);
  for (size_t i = 0; i < count; ++i) out[i] = unitFloat(hashAt(k, i));
}

}  // namespace stipple
