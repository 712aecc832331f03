// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// A shim sampler for one render plus the per-thread cache and the per-(pixel, sample) view integrators read.
// Values are drawn lazily, a dimension at a time: the first read of dimension d by any sample of a pixel asks the
// shim for all N samples of d in that pixel (stipple_sampler_fill_pixel, the batch call), so a dimension that no
// path of the pixel reaches (the deeper bounces of paths that end early) is never drawn. One batch call per
// (pixel, dimension) rather than one random-access call per (pixel sample, dimension): a call costs ~25-35 ns
// whatever it returns, while the batch call costs ~1 ns per value (shim/README.md), so the batch is cheaper as soon
// as a few of a pixel's N samples reach d. The values are the same either way (the shim's batch and random-access
// calls agree bitwise). Time inside the shim is accumulated per cache (see PixelSamples).
#pragma once

#include "sampling/sample_layout.h"
#include "sampling/warps.h"
#include "sampling/shim_loader.h"

#include <stipple/stipple.hpp>

#include <vector>

namespace stipple::render {

class PixelSamples;

class PixelSampler {
public:
    // pattern: a shim pattern name, optionally followed by "+blue-noise". Throws std::invalid_argument for an
    // unknown name and ShimError with the shim's message when the layout is rejected.
    PixelSampler(const ShimLibrary& shim, const std::string& pattern, uint32_t spp, uint64_t seed,
                 const SampleLayout& layout);
    PixelSampler(const PixelSampler&) = delete;
    PixelSampler& operator=(const PixelSampler&) = delete;

    uint32_t samplesPerPixel() const { return spp_; }
    const SampleLayout& layout() const { return layout_; }
    // Points `out` at pixel (x, y); values are drawn when first read.
    void startPixel(uint32_t x, uint32_t y, PixelSamples& out) const;

private:
    friend class PixelSamples;
    // All N samples' k values of dimension d into out (N*k*arity floats). Throws ShimError on failure.
    void drawPixel(uint32_t x, uint32_t y, uint32_t d, float* out, size_t count) const;

    stipple::Sampler sampler_; // stipple.hpp's owner of the handle, over the loaded library's table
    double clockSeconds_ = 0; // an empty steady_clock interval
    uint32_t spp_;
    SampleLayout layout_;
};

// One thread's cache of the values of the pixel sample being traced: per dimension, the sample index whose values
// it holds. Owned by one thread at a time.
class PixelSamples {
public:
    explicit PixelSamples(const PixelSampler& sampler);
    // Time spent inside the shim, estimated by sampling pixels: the batch calls of every kTimedEvery-th pixel this
    // cache starts are timed, each interval minus the clock's own cost (the mean of 4096 empty intervals, measured
    // once per sampler, as benchmark harnesses subtract their timer overhead), and the sum is scaled by pixels
    // started over pixels timed. Whole pixels, so that every dimension a pixel reaches is timed alike; two clock
    // reads per call on one pixel in kTimedEvery instead of on all.
    static constexpr uint32_t kTimedEvery = 16;
    double samplerSeconds() const {
        return pixelsTimed_ > 0 ? timedSeconds_ * double(pixels_) / double(pixelsTimed_) : 0.0;
    }

private:
    friend class PixelSampler;
    friend class SampleView;
    const float* values(uint32_t dim, uint32_t sampleIndex) const {
        if (!held_[dim]) fetchPixel(dim);
        return &pixelValues_[pixelOffset_[dim] + size_t(sampleIndex) * perSample_[dim]];
    }
    void fetchPixel(uint32_t dim) const;

    const PixelSampler* sampler_;
    uint32_t x_ = 0, y_ = 0;
    uint64_t pixels_ = 0, pixelsTimed_ = 0; // started by this cache; of them, timed
    bool timed_ = false;                    // the current pixel's calls are timed
    mutable double timedSeconds_ = 0;
    mutable std::vector<uint8_t> held_;      // per dimension: drawn for the current pixel
    std::vector<uint32_t> arity_;            // per dimension
    std::vector<size_t> perSample_;          // per dimension, k*arity floats of one sample
    mutable std::vector<float> pixelValues_; // per dimension, N*k*arity floats of the current pixel
    std::vector<size_t> pixelOffset_;        // dimension count + 1 entries
};

// The values of one pixel sample. Reading an undeclared dimension (index < 0) returns 0.5: integrators only do
// so for inputs the scene's materials ignore (e.g. the lobe choice when no material has two lobes).
class SampleView {
public:
    SampleView(const PixelSamples& p, uint32_t sampleIndex) : p_(&p), i_(sampleIndex) {}
    uint32_t sampleIndex() const { return i_; }
    const PixelSamples& pixel() const { return *p_; }
    float get1D(int dim, uint32_t j = 0) const {
        if (dim < 0) return 0.5f;
        return p_->values(uint32_t(dim), i_)[j * p_->arity_[dim]];
    }
    Point2 get2D(int dim, uint32_t j = 0) const {
        if (dim < 0) return {0.5f, 0.5f};
        const float* v = p_->values(uint32_t(dim), i_) + j * p_->arity_[dim];
        return {v[0], v[1]};
    }

private:
    const PixelSamples* p_;
    uint32_t i_;
};

} // namespace stipple::render
