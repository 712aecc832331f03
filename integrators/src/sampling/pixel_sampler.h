// A shim sampler for one render plus the per-thread cache and the per-(pixel, sample) view integrators read.
// Values are drawn lazily: the first read of a dimension in a pixel sample asks the shim for that sample's k
// values of that dimension (stipple_sampler_sample, random access), so a path that ends at its first bounce never
// pays for the dimensions of deeper bounces (poisson-seed, which generates a whole set for any request, and poisson,
// whose batch call is its cheaper path, are drawn a pixel's dimension at a time). Time inside the shim is
// accumulated per cache (see PixelSamples).
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
    // Points `out` at pixel (x, y); values are drawn when first read.
    void startPixel(uint32_t x, uint32_t y, PixelSamples& out) const;
    // poisson-seed and poisson are drawn a pixel's dimension at a time (their batch call is the cheaper path).
    bool drawsWholePixel() const { return wholePixel_; }

private:
    friend class PixelSamples;
    // Sample i's k values of dimension d into out (k*arity floats). Throws ShimError on failure.
    void draw(uint32_t x, uint32_t y, uint32_t i, uint32_t d, float* out, size_t count) const;
    void drawPixel(uint32_t x, uint32_t y, uint32_t d, float* out, size_t count) const;

    const ShimLibrary& shim_;
    stipple_sampler sampler_ = nullptr;
    double clockSeconds_ = 0; // an empty steady_clock interval
    bool wholePixel_ = false;
    uint32_t spp_;
    SampleLayout layout_;
};

// One thread's cache of the values of the pixel sample being traced: per dimension, the sample index whose values
// it holds. Owned by one thread at a time.
class PixelSamples {
public:
    explicit PixelSamples(const PixelSampler& sampler);
    // Time spent inside the shim, estimated from every 16th draw (reading the clock costs more than a draw): the
    // timed draws' total times 16, each timed interval minus the clock's own cost (the mean of 4096 empty
    // intervals, measured once per sampler), as benchmark harnesses subtract their timer overhead.
    mutable double samplerSeconds = 0;

private:
    friend class PixelSampler;
    friend class SampleView;
    const float* values(uint32_t dim, uint32_t sampleIndex) const {
        if (wholePixel_) {
            if (heldSample_[dim] == kNone) fetchPixel(dim);
            return &pixelValues_[pixelOffset_[dim] +
                                 size_t(sampleIndex) * (pixelOffset_[dim + 1] - pixelOffset_[dim]) / spp_];
        }
        if (heldSample_[dim] != sampleIndex) fetch(dim, sampleIndex);
        return &values_[offset_[dim]];
    }
    void fetchPixel(uint32_t dim) const;
    void fetch(uint32_t dim, uint32_t sampleIndex) const;

    const PixelSampler* sampler_;
    uint32_t x_ = 0, y_ = 0;
    mutable std::vector<float> values_;        // per dimension, k*arity floats of the held sample
    mutable std::vector<uint32_t> heldSample_; // per dimension, the sample index held (kNone: none)
    mutable uint64_t draws_ = 0;
    std::vector<size_t> offset_;
    std::vector<uint32_t> arity_;
    bool wholePixel_ = false; // the sampler's drawsWholePixel()
    uint32_t spp_ = 0;
    mutable std::vector<float> pixelValues_; // whole-pixel mode: per dimension, N*k*arity floats
    std::vector<size_t> pixelOffset_;        // dimension count + 1 entries
    static constexpr uint32_t kNone = 0xffffffffu;
};

// The values of one pixel sample. Reading an undeclared dimension (index < 0) returns 0.5: integrators only do
// so for inputs the scene's materials ignore (e.g. the lobe choice when no material has two lobes).
class SampleView {
public:
    SampleView(const PixelSamples& p, uint32_t sampleIndex) : p_(&p), i_(sampleIndex) {}
    uint32_t sampleIndex() const { return i_; }
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
