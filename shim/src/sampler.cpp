// sampler.cpp — dispatch from a (pixel, dimension, sample) request to its pattern and its set.
#include "sampler.h"

#include "blue_noise.h"
#include "hash.h"
#include "patterns.h"
#include "poisson_cache.h"

#include <algorithm>
#include <bit>
#include <utility>

namespace stipple {

namespace {
constexpr HashDomain kPatternDomain[STIPPLE_PATTERN_COUNT] = {HashDomain::Independent, HashDomain::Stratified,
                                                              HashDomain::Poisson,     HashDomain::PoissonSeed,
                                                              HashDomain::Sobol,       HashDomain::Pmj02};
// Words folded into a key: a stream's arity, a block index > 0 (block 0 keeps the 1.0 key of the layout).
constexpr uint64_t kStreamWord = 0x57e4a3c0ffee0000ull;
constexpr uint64_t kBlockWord = 0xb10c000000000000ull;

constexpr uint64_t streamWord(uint64_t key, uint32_t streamArity) {
    return streamArity == 0 ? key : hashCombine(key, kStreamWord | streamArity);
}

constexpr HashDomain tileDomain(uint32_t pattern) {
    return static_cast<HashDomain>(static_cast<uint64_t>(kPatternDomain[pattern]) ^
                                   static_cast<uint64_t>(HashDomain::BlueNoiseTile));
}
} // namespace

Dimension makePatternDimension(uint32_t pattern, uint32_t arity, uint32_t count, uint32_t points) {
    Dimension dim;
    dim.arity = arity;
    dim.count = count;
    dim.setSize = points;
    dim.log2Length = static_cast<uint32_t>(std::bit_width(points - 1));
    if (pattern == STIPPLE_PATTERN_STRATIFIED) dim.grid = StrataGrid::choose(arity, points);
    if (pattern == STIPPLE_PATTERN_POISSON) dim.poisson = PoissonCache::global().acquire(arity, points);
    if (pattern == STIPPLE_PATTERN_PMJ02) dim.pmj02 = Pmj02Family::acquire(dim.log2Length);
    return dim;
}

Sampler::Sampler(uint32_t pattern, uint32_t samplesPerPixel, uint64_t seed, std::vector<Dimension> dimensions,
                 uint32_t flags)
    : pattern_(pattern), samplesPerPixel_(samplesPerPixel), seed_(seed),
      seedKey_(seedKey(seed, kPatternDomain[pattern])), dimensions_(std::move(dimensions)), flags_(flags),
      tileSeedKey_(seedKey(seed, tileDomain(pattern))) {
    // Streams: grids and pmj02 families now (cheap: a family generates its sequences on first use), Poisson
    // families on first use (they count against the cache budget).
    for (uint32_t a = 1; a <= 3; ++a) {
        Dimension& s = streams_[a - 1];
        s.arity = a;
        s.setSize = samplesPerPixel;
        s.log2Length = static_cast<uint32_t>(std::bit_width(samplesPerPixel - 1));
        if (pattern == STIPPLE_PATTERN_STRATIFIED) s.grid = StrataGrid::choose(a, samplesPerPixel);
        if (pattern == STIPPLE_PATTERN_PMJ02) s.pmj02 = Pmj02Family::acquire(s.log2Length);
    }
}

uint64_t Sampler::pixelKey(const SetRef& set) const {
    return streamWord(setKeyFrom(seedKey_, set.pixelX, set.pixelY, set.d), set.streamArity);
}

uint64_t Sampler::blockKey(uint64_t key, uint32_t block) const {
    if (pattern_ == STIPPLE_PATTERN_PMJ02) return hashCombine(key, block); // pmj02's own key of every block
    return block == 0 ? key : hashCombine(key, kBlockWord | block);
}

const Dimension& Sampler::streamDimension(uint32_t arity) const {
    const Dimension& s = streams_[arity - 1];
    if (pattern_ == STIPPLE_PATTERN_POISSON)
        std::call_once(streamFamilyOnce_[arity - 1], [&] {
            const_cast<Dimension&>(s).poisson = PoissonCache::global().acquire(arity, samplesPerPixel_);
        });
    return s;
}

void Sampler::fill(const SetRef& set, const Dimension& dim, uint32_t first, uint32_t count, float* out) const {
    if (flags_ != 0) [[unlikely]]
        return fillBlueNoise(set, dim, first, count, out);
    const uint64_t key = pixelKey(set);
    switch (pattern_) {
    case STIPPLE_PATTERN_INDEPENDENT: return fillIndependent(blockKey(key, set.block), dim, first, count, out);
    case STIPPLE_PATTERN_STRATIFIED: return fillStratified(blockKey(key, set.block), dim, first, count, out);
    case STIPPLE_PATTERN_POISSON: return fillPoisson(blockKey(key, set.block), dim, first, count, out);
    case STIPPLE_PATTERN_SOBOL: return fillSobol(SobolSet::perPixel(key).atBlock(set.block), dim, first, count, out);
    case STIPPLE_PATTERN_PMJ02: return fillPmj02(key, set.block, dim, first, count, out);
    default: return fillPoissonSeed(blockKey(key, set.block), dim, first, count, out);
    }
}

void Sampler::point(const SetRef& set, const Dimension& dim, uint32_t p, float* out) const {
    if (flags_ != 0) [[unlikely]]
        return fillBlueNoise(set, dim, p, 1, out);
    const uint64_t key = pixelKey(set);
    switch (pattern_) {
    case STIPPLE_PATTERN_INDEPENDENT: return pointIndependent(blockKey(key, set.block), dim, p, out);
    case STIPPLE_PATTERN_STRATIFIED: return pointStratified(blockKey(key, set.block), dim, p, out);
    case STIPPLE_PATTERN_POISSON: return pointPoisson(blockKey(key, set.block), dim, p, out);
    case STIPPLE_PATTERN_SOBOL: return pointSobol(SobolSet::perPixel(key).atBlock(set.block), dim, p, out);
    case STIPPLE_PATTERN_PMJ02: return pointPmj02(key, set.block, dim, p, out);
    default: return pointPoissonSeed(blockKey(key, set.block), dim, p, out);
    }
}

// Every variant keys the tile-shared part of a set from (seed, pattern ^ tile domain, tile, d[, stream arity][, block])
// and the per-pixel part from the plain set key, so blocks and streams are blue noise on their own and every
// sample stays uniform.
void Sampler::fillBlueNoise(const SetRef& set, const Dimension& dim, uint32_t first, uint32_t count, float* out) const {
    const uint64_t tileKey =
        streamWord(setKeyFrom(tileSeedKey_, set.pixelX >> kBlueNoiseTileLog2, set.pixelY >> kBlueNoiseTileLog2, set.d),
                   set.streamArity);
    switch (pattern_) {
    case STIPPLE_PATTERN_INDEPENDENT:
    case STIPPLE_PATTERN_STRATIFIED: { // stratification across the pixels of a tile
        const CrossPixelStrata strata(blockKey(tileKey, set.block), set.pixelX, set.pixelY, dim.arity,
                                      pattern_ == STIPPLE_PATTERN_INDEPENDENT ? LatticeUse::Square
                                                                              : LatticeUse::Strata);
        const uint64_t key = blockKey(pixelKey(set), set.block);
        if (pattern_ == STIPPLE_PATTERN_INDEPENDENT) return fillIndependent(key, dim, first, count, out, &strata);
        return fillStratified(key, dim, first, count, out, &strata);
    }
    case STIPPLE_PATTERN_SOBOL: { // one sequence per tile, one shift per pixel for all its blocks
        fillSobol(SobolSet::perPixel(tileKey).atBlock(set.block), dim, first, count, out);
        float shift[3];
        blueNoiseShift(tileKey, set.pixelX, set.pixelY, dim.arity, shift);
        return applyToroidalShift(shift, dim.arity, count, out);
    }
    default: { // poisson, poisson-seed, pmj02: a tile-shared set per block, shifted per pixel
        const uint64_t key = blockKey(tileKey, set.block);
        if (pattern_ == STIPPLE_PATTERN_POISSON)
            fillPoisson(key, dim, first, count, out);
        else if (pattern_ == STIPPLE_PATTERN_PMJ02)
            fillPmj02(tileKey, set.block, dim, first, count, out);
        else
            fillPoissonSeed(key, dim, first, count, out);
        float shift[3];
        blueNoiseShift(key, set.pixelX, set.pixelY, dim.arity, shift);
        return applyToroidalShift(shift, dim.arity, count, out);
    }
    }
}

void Sampler::fillPixel(uint32_t pixelX, uint32_t pixelY, uint32_t d, float* out) const {
    const Dimension& dim = dimensions_[d];
    fill(SetRef{pixelX, pixelY, d, 0, 0}, dim, 0, dim.setSize, out);
}

void Sampler::sample(uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex, uint32_t d, float* out) const {
    const Dimension& dim = dimensions_[d];
    const uint32_t block =
        sampleIndex < samplesPerPixel_ ? 0 : sampleIndex / samplesPerPixel_; // no division in block 0
    const uint32_t position = sampleIndex - block * samplesPerPixel_;
    const SetRef set{pixelX, pixelY, d, 0, block};
    if (dim.count == 1) return point(set, dim, position, out);
    fill(set, dim, position * dim.count, dim.count, out); // one generation for poisson-seed, not k
}

void Sampler::stream(uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex, uint32_t d, uint32_t arity,
                     float* out) const {
    const uint32_t block = sampleIndex < samplesPerPixel_ ? 0 : sampleIndex / samplesPerPixel_;
    const uint32_t position = sampleIndex - block * samplesPerPixel_;
    point(SetRef{pixelX, pixelY, d, arity, block}, streamDimension(arity), position, out);
}

void Sampler::streamFill(uint32_t pixelX, uint32_t pixelY, uint32_t firstSample, uint32_t count, uint32_t d,
                         uint32_t arity, float* out) const {
    const Dimension& dim = streamDimension(arity);
    uint64_t i = firstSample;
    const uint64_t end = uint64_t(firstSample) + count;
    while (i < end) { // one fill per block touched
        const uint32_t block = static_cast<uint32_t>(i / samplesPerPixel_);
        const uint32_t position = static_cast<uint32_t>(i - uint64_t(block) * samplesPerPixel_);
        const uint32_t run = static_cast<uint32_t>(std::min<uint64_t>(end - i, samplesPerPixel_ - position));
        fill(SetRef{pixelX, pixelY, d, arity, block}, dim, position, run, out);
        out += size_t(run) * arity;
        i += run;
    }
}

void Sampler::sampleIndependent(uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex, uint32_t stream, float* out,
                                size_t count) const {
    const uint64_t k = hashCombine(setKey(seed_, HashDomain::PastLayout, pixelX, pixelY, stream), sampleIndex);
    for (size_t i = 0; i < count; ++i) out[i] = unitFloat(hashAt(k, i));
}

} // namespace stipple
