// A shim sampler for one render plus the per-pixel buffer and the per-(pixel, sample) view integrators read.
// Per pixel, one stipple_sampler_fill_pixel per dimension (the shim's fast path) fills a per-thread buffer;
// sample i then reads its slice. Time inside the shim is accumulated per buffer.
#pragma once

#include "sampling/sample_layout.h"
#include "sampling/warps.h"
#include "sampling/shim_loader.h"

#include <vector>

namespace stipple::render {

class PixelSamples;

class PixelSampler {
public:
    // pattern: a shim pattern name, optionally followed by "+blue-noise". Throws std::invalid_argument for an
    // unknown name and ShimError with the shim's message when the layout is rejected.
    PixelSampler(const ShimLibrary& shim, const std::string& pattern, uint32_t spp, uint64_t seed,
                 const SampleLayout& layout);
    ~PixelSampler();
    PixelSampler(const PixelSampler&) = delete;
    PixelSampler& operator=(const PixelSampler&) = delete;

    uint32_t samplesPerPixel() const { return spp_; }
    const SampleLayout& layout() const { return layout_; }
    // Fills every declared dimension of pixel (x, y) into `out`.
    void fillPixel(uint32_t x, uint32_t y, PixelSamples& out) const;

private:
    const ShimLibrary& shim_;
    stipple_sampler sampler_ = nullptr;
    uint32_t spp_;
    SampleLayout layout_;
};

// One pixel's values for every dimension (owned by one thread at a time).
class PixelSamples {
public:
    explicit PixelSamples(const PixelSampler& sampler);
    double samplerSeconds = 0; // time spent inside the shim by fillPixel on this buffer

private:
    friend class PixelSampler;
    friend class SampleView;
    std::vector<float> values_;
    std::vector<size_t> offset_;   // per dimension, start of its N*k*arity floats
    std::vector<uint32_t> stride_; // per dimension, k*arity floats per pixel sample
    std::vector<uint32_t> arity_;
};

// The values of one pixel sample. Reading an undeclared dimension (index < 0) returns 0.5: integrators only do
// so for inputs the scene's materials ignore (e.g. the lobe choice when no material has two lobes).
class SampleView {
public:
    SampleView(const PixelSamples& p, uint32_t sampleIndex) : p_(&p), i_(sampleIndex) {}
    uint32_t sampleIndex() const { return i_; }
    float get1D(int dim, uint32_t j = 0) const {
        if (dim < 0) return 0.5f;
        return p_->values_[p_->offset_[dim] + size_t(i_) * p_->stride_[dim] + j * p_->arity_[dim]];
    }
    Point2 get2D(int dim, uint32_t j = 0) const {
        if (dim < 0) return {0.5f, 0.5f};
        const float* v = &p_->values_[p_->offset_[dim] + size_t(i_) * p_->stride_[dim] + j * p_->arity_[dim]];
        return {v[0], v[1]};
    }

private:
    const PixelSamples* p_;
    uint32_t i_;
};

} // namespace stipple::render
