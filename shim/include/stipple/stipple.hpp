// stipple.hpp — a header-only C++17 kit over the C ABI (stipple.h) for hosts that consume samples by call order.
//
//   stipple::Sampler sampler("stratified", 64, seed);         // no layout: streams only (ABI 1.1)
//   stipple::PixelSampleCursor cursor(sampler);                // one per thread
//   cursor.start({x, y}, sampleIndex);                         // like pbrt-v4's Sampler::StartPixelSample
//   auto film = cursor.getPixel2D();                           // its own stream, not counted
//   float u = cursor.get1D();  auto uv = cursor.get2D();       // dimension 0, 1, ...: the call counter
//
// Values are a pure function of (seed, pixel, sample index, dimension index, arity): any thread, any order.
// Every sample index is served (index i reads block i / N: each N consecutive indices form a full set), so a
// host may render 16 samples, then 16 more, or add samples to some pixels only.
//
// Errors: every failing C call throws stipple::Error (status + the library's message). Nothing else throws
// except std::bad_alloc.
//
// Loading: a linking host (-lstipple) uses the constructors as shown; a dlopen host passes the function table
// it got from stipple_get_api (struct_size must show the 1.1 functions; Error otherwise).
#ifndef STIPPLE_STIPPLE_HPP
#define STIPPLE_STIPPLE_HPP

#include <stipple/stipple.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

namespace stipple {

class Error : public std::runtime_error {
public:
    Error(stipple_status status, const std::string& message) : std::runtime_error(message), status_(status) {}
    stipple_status status() const noexcept { return status_; }

private:
    stipple_status status_;
};

inline void check(const stipple_api& api, stipple_status status) {
    if (status != STIPPLE_OK) throw Error(status, api.last_error_message());
}

// The table of the linked library (only for hosts that link -lstipple; a dlopen host never calls this).
inline const stipple_api& linkedApi() {
    const stipple_api* api = nullptr;
    const stipple_status status = stipple_get_api(STIPPLE_ABI_MAJOR, &api);
    if (status != STIPPLE_OK) throw Error(status, stipple_last_error_message());
    return *api;
}

// Pixel coordinates are signed (film crop windows and filter footprints reach negative pixels, as pbrt-v4's
// Point2i does). The C ABI takes uint32: a signed coordinate is passed as its two's-complement bits, a bijection,
// so every signed pixel gets its own sets and (-1, 0) is not (0, 0).
struct Pixel {
    int32_t x = 0, y = 0;
};
inline uint32_t pixelBits(int32_t coordinate) { return static_cast<uint32_t>(coordinate); }

// RAII owner of a stipple_sampler. Move-only. Immutable after creation: share it (by reference) between threads.
class Sampler {
public:
    // Streams only (dimension_count 0): the layout is whatever the host asks for, by call order.
    Sampler(const std::string& pattern, uint32_t samplesPerPixel, uint64_t seed, const stipple_api& api = linkedApi())
        : api_(&api) {
        requireStreams();
        uint32_t id = 0;
        check(api, api.pattern_from_name(pattern.c_str(), &id));
        stipple_sampler_desc desc{};
        desc.struct_size = sizeof desc;
        desc.pattern = id;
        desc.samples_per_pixel = samplesPerPixel;
        desc.seed = seed;
        check(api, api.sampler_create(&desc, &sampler_));
        samplesPerPixel_ = samplesPerPixel;
    }
    // Any description (a declared layout too).
    explicit Sampler(const stipple_sampler_desc& desc, const stipple_api& api = linkedApi()) : api_(&api) {
        requireStreams();
        check(api, api.sampler_create(&desc, &sampler_));
        samplesPerPixel_ = desc.samples_per_pixel;
    }
    ~Sampler() {
        if (sampler_) api_->sampler_release(sampler_);
    }
    Sampler(Sampler&& other) noexcept
        : api_(other.api_), sampler_(std::exchange(other.sampler_, nullptr)), samplesPerPixel_(other.samplesPerPixel_) {
    }
    Sampler& operator=(Sampler&& other) noexcept {
        if (this != &other) {
            if (sampler_) api_->sampler_release(sampler_);
            api_ = other.api_;
            sampler_ = std::exchange(other.sampler_, nullptr);
            samplesPerPixel_ = other.samplesPerPixel_;
        }
        return *this;
    }
    Sampler(const Sampler&) = delete;
    Sampler& operator=(const Sampler&) = delete;

    stipple_sampler handle() const { return sampler_; }
    const stipple_api& api() const { return *api_; }
    uint32_t samplesPerPixel() const { return samplesPerPixel_; }

    // One value of stream (dimension, arity): arity floats into out.
    void stream(Pixel pixel, uint32_t sampleIndex, uint32_t dimension, uint32_t arity, float* out) const {
        check(*api_, api_->sampler_stream(sampler_, pixelBits(pixel.x), pixelBits(pixel.y), sampleIndex, dimension,
                                          arity, out, arity));
    }
    // Samples [firstSample, firstSample + count) of one stream, sample-major (count * arity floats).
    void streamFill(Pixel pixel, uint32_t firstSample, uint32_t count, uint32_t dimension, uint32_t arity,
                    float* out) const {
        check(*api_, api_->sampler_stream_fill(sampler_, pixelBits(pixel.x), pixelBits(pixel.y), firstSample, count,
                                               dimension, arity, out, size_t(count) * arity));
    }

private:
    void requireStreams() const {
        const size_t needed = offsetof(stipple_api, sampler_stream_fill) + sizeof(api_->sampler_stream_fill);
        if (api_->struct_size < needed)
            throw Error(STIPPLE_ERROR_ABI_VERSION,
                        "stipple.hpp needs libstipple ABI 1.1 (streams); this library's table is " +
                            std::to_string(api_->struct_size) + " bytes, ABI 1." + std::to_string(api_->abi_minor));
    }

    const stipple_api* api_;
    stipple_sampler sampler_ = nullptr;
    uint32_t samplesPerPixel_ = 0;
};

// The per-thread view of one pixel sample, shaped like pbrt-v4's sampler interface: start() a pixel sample, then
// each get1D/get2D/get3D takes the next dimension index (the call counter) with the arity of that call. Skipping
// calls on data-dependent branches is fine: a dimension index is only a name, values never depend on which
// indices were asked before. For stratification across the samples of a pixel, a given index should be asked
// with the same arity in every sample (asking it with another arity is defined: an independent set).
class PixelSampleCursor {
public:
    // getPixel2D's stream: the last dimension index, outside any realistic call count.
    static constexpr uint32_t kPixelDimension = 0xffffffffu;

    explicit PixelSampleCursor(const Sampler& sampler) : sampler_(&sampler) {}

    void start(Pixel pixel, uint32_t sampleIndex, uint32_t dimension = 0) {
        pixel_ = pixel;
        sampleIndex_ = sampleIndex;
        dimension_ = dimension;
    }
    uint32_t dimension() const { return dimension_; }
    uint32_t sampleIndex() const { return sampleIndex_; }
    Pixel pixel() const { return pixel_; }

    float get1D() { return next<1>()[0]; }
    std::array<float, 2> get2D() { return next<2>(); }
    std::array<float, 3> get3D() { return next<3>(); }
    // The film position within the pixel: its own 2D stream (kPixelDimension); does not advance the counter.
    std::array<float, 2> getPixel2D() const {
        std::array<float, 2> v{};
        sampler_->stream(pixel_, sampleIndex_, kPixelDimension, 2, v.data());
        return v;
    }

private:
    template <size_t Arity>
    std::array<float, Arity> next() {
        // The counter never reaches getPixel2D's own stream: that would return the film position's values again.
        if (dimension_ == kPixelDimension)
            throw Error(STIPPLE_ERROR_OUT_OF_RANGE, "PixelSampleCursor: the call counter reached dimension " +
                                                        std::to_string(kPixelDimension) +
                                                        ", which is getPixel2D's stream");
        std::array<float, Arity> v{};
        sampler_->stream(pixel_, sampleIndex_, dimension_++, uint32_t(Arity), v.data());
        return v;
    }

    const Sampler* sampler_;
    Pixel pixel_{};
    uint32_t sampleIndex_ = 0;
    uint32_t dimension_ = 0;
};

} // namespace stipple

#endif // STIPPLE_STIPPLE_HPP
