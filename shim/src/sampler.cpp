// sampler.cpp — dispatch from a (pixel, dimension) request to its pattern.
#include "sampler.h"

#include "blue_noise.h"
#include "hash.h"
#include "patterns.h"

#include <algorithm>
#include <optional>
#include <utility>

namespace stipple {

namespace {
constexpr HashDomain kPatternDomain[STIPPLE_PATTERN_COUNT] = {HashDomain::Independent, HashDomain::Stratified,
                                                              HashDomain::Poisson,     HashDomain::PoissonSeed,
                                                              HashDomain::Sobol,       HashDomain::Pmj02};
} // namespace

Sampler::Sampler(uint32_t pattern, uint32_t samplesPerPixel, uint64_t seed, std::vector<Dimension> dimensions,
                 uint32_t flags)
    : pattern_(pattern), samplesPerPixel_(samplesPerPixel), seed_(seed), dimensions_(std::move(dimensions)),
      flags_(flags) {}

uint64_t Sampler::key(uint32_t pixelX, uint32_t pixelY, uint32_t d) const {
    return setKey(seed_, kPatternDomain[pattern_], pixelX, pixelY, d);
}

bool Sampler::maskShifted() const {
    return blueNoise() && (pattern_ == STIPPLE_PATTERN_POISSON || pattern_ == STIPPLE_PATTERN_POISSON_SEED ||
                           pattern_ == STIPPLE_PATTERN_PMJ02);
}

std::optional<CrossPixelStrata> Sampler::crossPixelStrata(uint32_t pixelX, uint32_t pixelY, uint32_t d) const {
    if (!blueNoise() || (pattern_ != STIPPLE_PATTERN_STRATIFIED && pattern_ != STIPPLE_PATTERN_INDEPENDENT))
        return std::nullopt;
    const auto domain = static_cast<HashDomain>(static_cast<uint64_t>(kPatternDomain[pattern_]) ^
                                                static_cast<uint64_t>(HashDomain::BlueNoiseTile));
    return CrossPixelStrata{setKey(seed_, domain, pixelX >> kCrossPixelLevels, pixelY >> kCrossPixelLevels, d), pixelX,
                            pixelY};
}

uint64_t Sampler::patternKey(uint32_t pixelX, uint32_t pixelY, uint32_t d) const {
    if (!maskShifted()) return key(pixelX, pixelY, d);
    const auto domain = static_cast<HashDomain>(static_cast<uint64_t>(kPatternDomain[pattern_]) ^
                                                static_cast<uint64_t>(HashDomain::BlueNoiseTile));
    return setKey(seed_, domain, pixelX >> kBlueNoiseMaskLog2, pixelY >> kBlueNoiseMaskLog2, d);
}

SobolSet Sampler::sobolSet(uint32_t pixelX, uint32_t pixelY, uint32_t d) const {
    const uint64_t pixelKey = key(pixelX, pixelY, d);
    if (!blueNoise()) return SobolSet::perPixel(pixelKey);
    const uint64_t dimensionKey = hashCombine(
        mix64(seed_ ^ static_cast<uint64_t>(HashDomain::Sobol) ^ static_cast<uint64_t>(HashDomain::BlueNoiseTile)), d);
    return zOrderSobolSet(dimensionKey, pixelKey, pixelX, pixelY, dimensions_[d].log2Length);
}

void Sampler::blueNoiseShiftInPlace(uint32_t pixelX, uint32_t pixelY, uint32_t d, size_t points, float* out) const {
    if (!maskShifted()) return;
    float shift[3];
    const uint32_t arity = dimensions_[d].arity;
    blueNoiseShift(patternKey(pixelX, pixelY, d), pixelX, pixelY, arity, shift);
    applyToroidalShift(shift, arity, points, out);
}

void Sampler::fillPixel(uint32_t pixelX, uint32_t pixelY, uint32_t d, float* out) const {
    const Dimension& dim = dimensions_[d];
    const uint64_t k = patternKey(pixelX, pixelY, d);
    const std::optional<CrossPixelStrata> strata = crossPixelStrata(pixelX, pixelY, d);
    const CrossPixelStrata* blue = strata ? &*strata : nullptr;
    switch (pattern_) {
    case STIPPLE_PATTERN_INDEPENDENT: fillIndependent(k, dim, out, blue); break;
    case STIPPLE_PATTERN_STRATIFIED: fillStratified(k, dim, out, blue); break;
    case STIPPLE_PATTERN_POISSON: fillPoisson(k, dim, out); break;
    case STIPPLE_PATTERN_SOBOL: fillSobol(sobolSet(pixelX, pixelY, d), dim, out); break;
    case STIPPLE_PATTERN_PMJ02: fillPmj02(k, dim, out); break;
    default: fillPoissonSeed(k, dim, out); break;
    }
    blueNoiseShiftInPlace(pixelX, pixelY, d, dim.setSize, out);
}

void Sampler::sample(uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex, uint32_t d, float* out) const {
    const Dimension& dim = dimensions_[d];
    const uint64_t k = patternKey(pixelX, pixelY, d);
    if (pattern_ == STIPPLE_PATTERN_POISSON_SEED) {
        // One generation for the k points of the sample, not k generations.
        thread_local std::vector<float> scratch;
        scratch.resize(dim.floatsPerPixel());
        fillPoissonSeed(k, dim, scratch.data());
        const float* first = scratch.data() + size_t(sampleIndex) * dim.floatsPerSample();
        std::copy(first, first + dim.floatsPerSample(), out);
        blueNoiseShiftInPlace(pixelX, pixelY, d, dim.count, out);
        return;
    }
    const SobolSet sobol = pattern_ == STIPPLE_PATTERN_SOBOL ? sobolSet(pixelX, pixelY, d) : SobolSet{};
    const std::optional<CrossPixelStrata> strata = crossPixelStrata(pixelX, pixelY, d);
    const CrossPixelStrata* blue = strata ? &*strata : nullptr;
    for (uint32_t j = 0; j < dim.count; ++j) {
        const uint32_t p = sampleIndex * dim.count + j;
        float* point = out + size_t(j) * dim.arity;
        switch (pattern_) {
        case STIPPLE_PATTERN_INDEPENDENT: pointIndependent(k, dim, p, point, blue); break;
        case STIPPLE_PATTERN_STRATIFIED: pointStratified(k, dim, p, point, blue); break;
        case STIPPLE_PATTERN_SOBOL: pointSobol(sobol, dim, p, point); break;
        case STIPPLE_PATTERN_PMJ02: pointPmj02(k, dim, p, point); break;
        default: pointPoisson(k, dim, p, point); break;
        }
    }
    blueNoiseShiftInPlace(pixelX, pixelY, d, dim.count, out);
}

void Sampler::sampleIndependent(uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex, uint32_t stream, float* out,
                                size_t count) const {
    const uint64_t k = hashCombine(setKey(seed_, HashDomain::PastLayout, pixelX, pixelY, stream), sampleIndex);
    for (size_t i = 0; i < count; ++i) out[i] = unitFloat(hashAt(k, i));
}

} // namespace stipple
