// sampler.h — the object behind a stipple_sampler handle: immutable after creation, shared by threads.
#pragma once

#include "dimension.h"
#include "blue_noise.h"
#include "patterns.h"

#include <stipple/stipple.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace stipple {

class Sampler {
public:
    Sampler(uint32_t pattern, uint32_t samplesPerPixel, uint64_t seed, std::vector<Dimension> dimensions,
            uint32_t flags = 0);

    uint32_t pattern() const { return pattern_; }
    uint32_t samplesPerPixel() const { return samplesPerPixel_; }
    uint64_t seed() const { return seed_; }
    uint32_t flags() const { return flags_; }
    uint32_t dimensionCount() const { return static_cast<uint32_t>(dimensions_.size()); }
    const Dimension& dimension(uint32_t d) const { return dimensions_[d]; }

    // Arguments are checked by the ABI layer; these only compute.
    void fillPixel(uint32_t pixelX, uint32_t pixelY, uint32_t d, float* out) const;
    void sample(uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex, uint32_t d, float* out) const;
    void sampleIndependent(uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex, uint32_t stream, float* out,
                           size_t count) const;

private:
    uint64_t key(uint32_t pixelX, uint32_t pixelY, uint32_t d) const;
    bool blueNoise() const { return (flags_ & STIPPLE_SAMPLER_FLAG_BLUE_NOISE) != 0; }
    bool maskShifted() const; // blue noise by per-pixel toroidal shifts (poisson, poisson-seed, pmj02)
    std::optional<CrossPixelStrata> crossPixelStrata(uint32_t pixelX, uint32_t pixelY, uint32_t d) const;
    // The key the pattern's set is drawn from: per pixel, or per blue-noise tile (shared, then shifted per pixel).
    uint64_t patternKey(uint32_t pixelX, uint32_t pixelY, uint32_t d) const;
    SobolSet sobolSet(uint32_t pixelX, uint32_t pixelY, uint32_t d) const;
    void blueNoiseShiftInPlace(uint32_t pixelX, uint32_t pixelY, uint32_t d, size_t points, float* out) const;

    uint32_t pattern_;
    uint32_t samplesPerPixel_;
    uint64_t seed_;
    std::vector<Dimension> dimensions_;
    uint32_t flags_;
};

// Validates desc completely (every message names the argument, its value and what was expected) and builds
// the sampler. Throws stipple::Error.
Sampler* createSampler(const stipple_sampler_desc& desc);

// The C handle (stipple_sampler_t*) is a Sampler* in disguise. struct stipple_sampler_t is never defined, so
// the library's debug info (and the ABI baseline made from it) shows the handle as opaque, as hosts see it.
inline stipple_sampler toHandle(Sampler* sampler) { return reinterpret_cast<stipple_sampler>(sampler); }
inline Sampler* fromHandle(stipple_sampler handle) { return reinterpret_cast<Sampler*>(handle); }

} // namespace stipple
