// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// stipple.hpp — the header-only C++ kit over the C ABI (stipple.h). C++11 and later; works with and without
// exceptions.
//
//   stipple::Sampler sampler("stratified+blue-noise", 64, seed);    // no layout: streams and arrays (ABI 1.1 / 1.2)
//   if (!sampler) { /* sampler.status().message() */ }          // (with exceptions the constructor throws instead)
//   stipple::PixelSampleCursor cursor(sampler);                 // one per thread
//   cursor.start(stipple::Pixel{x, y}, sampleIndex);            // like pbrt-v4's Sampler::StartPixelSample
//   std::array<float, 2> film = cursor.getPixel2D();            // its own stream, not counted
//   float u = cursor.get1D();  std::array<float, 2> uv = cursor.get2D();  // stream 0, 1, ...: the call counter
//   const float* lights = cursor.get2DArray(4);                 // 4 (u, v) pairs, one array of 4 N points
//
// Values are a pure function of (seed, pixel, sample index, stream index, arity [, k]): any thread, any order.
// Every sample index is served (index i reads block i / N: each N consecutive indices form a full set).
//
// The cursor is the fast path: it fetches each (pixel, stream, arity) with one batch call for the rest of the
// sample's block on first use and serves the following samples of that pixel from its cache (see
// PixelSampleCursor). Sampler's per-value calls (stream, array) are one C call each.
//
// Errors. Every operation has a form that returns a stipple::Status (the C status and the library's message);
// those never throw. Built with exceptions, the value-returning conveniences (the Sampler constructors, the
// cursor's get*) throw stipple::Error; built with -fno-exceptions (or STIPPLE_HPP_EXCEPTIONS defined to 0) they
// record the failure instead: `if (!sampler)` / `sampler.status()`, `cursor.status()` (the first failure since
// the last start(); the values of a failing call are 0). std::bad_alloc is the only other exception.
//
// Loading: a linking host (-lstipple) uses the defaults as shown; a dlopen host passes the function table it got
// from stipple_get_api as the last argument (streams need a 1.1 table, arrays, listing and limits a 1.2 one; an
// older table gives STIPPLE_ERROR_ABI_VERSION for those calls only).
#ifndef STIPPLE_STIPPLE_HPP
#define STIPPLE_STIPPLE_HPP

#include <stipple/stipple.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#ifndef STIPPLE_HPP_EXCEPTIONS
#if defined(__cpp_exceptions) || defined(__EXCEPTIONS) || defined(_CPPUNWIND)
#define STIPPLE_HPP_EXCEPTIONS 1
#else
#define STIPPLE_HPP_EXCEPTIONS 0
#endif
#endif
#if STIPPLE_HPP_EXCEPTIONS
#include <stdexcept>
#endif

#if defined(__GNUC__) || defined(__clang__)
#define STIPPLE_HPP_MUST_USE __attribute__((warn_unused_result))
#else
#define STIPPLE_HPP_MUST_USE
#endif
// The cursor's miss path is kept out of its hit path (NOINLINE) and built in one piece (ALWAYS_INLINE).
#if defined(__GNUC__) || defined(__clang__)
#define STIPPLE_HPP_NOINLINE __attribute__((noinline))
#define STIPPLE_HPP_ALWAYS_INLINE __attribute__((always_inline)) inline
#elif defined(_MSC_VER)
#define STIPPLE_HPP_NOINLINE __declspec(noinline)
#define STIPPLE_HPP_ALWAYS_INLINE __forceinline
#else
#define STIPPLE_HPP_NOINLINE
#define STIPPLE_HPP_ALWAYS_INLINE inline
#endif

namespace stipple {

// The outcome of one operation: STIPPLE_OK, or a failing status with the library's message (which names the
// argument, its value and what was expected).
class Status {
public:
    Status() : code_(STIPPLE_OK) {}
    Status(stipple_status code, const std::string& message) : code_(code), message_(message) {}
    bool ok() const { return code_ == STIPPLE_OK; }
    stipple_status code() const { return code_; }
    const std::string& message() const { return message_; }
    void swap(Status& other) noexcept {
        std::swap(code_, other.code_);
        message_.swap(other.message_);
    }

private:
    stipple_status code_;
    std::string message_;
};

#if STIPPLE_HPP_EXCEPTIONS
class Error : public std::runtime_error {
public:
    Error(stipple_status status, const std::string& message) : std::runtime_error(message), status_(status) {}
    stipple_status status() const noexcept { return status_; }

private:
    stipple_status status_;
};
// Throws Error for a failing status: the bridge from the status forms to exceptions.
inline void check(const Status& status) {
    if (!status.ok()) throw Error(status.code(), status.message());
}
#endif

namespace kit_detail {

inline Status statusOf(const stipple_api& api, stipple_status code) {
    if (code == STIPPLE_OK) return Status();
    return Status(code, api.last_error_message ? api.last_error_message() : "");
}
// Whether the table holds the 1.1 (streams) / 1.2 (arrays, listing, limits, flags by name) entries.
inline bool hasStreams(const stipple_api& api) {
    return api.struct_size >= offsetof(stipple_api, sampler_stream_fill) + sizeof(api.sampler_stream_fill);
}
inline bool hasArrays(const stipple_api& api) {
    return api.struct_size >= offsetof(stipple_api, pattern_parse) + sizeof(api.pattern_parse);
}
inline Status tooOld(const stipple_api& api, const char* what, const char* minor) {
    return Status(STIPPLE_ERROR_ABI_VERSION, std::string("stipple.hpp: ") + what + " needs libstipple ABI " + minor +
                                                 "; this library's table is " + std::to_string(api.struct_size) +
                                                 " bytes, ABI 1." + std::to_string(api.abi_minor));
}
// A table with no entries, handed out when the linked library refuses this header's major version (it cannot,
// given the SONAME): every operation then fails with STIPPLE_ERROR_ABI_VERSION instead of crashing.
inline const stipple_api& emptyApi() {
    static const stipple_api empty = stipple_api();
    return empty;
}

} // namespace kit_detail

// The table of the linked library (only for hosts that link -lstipple; a dlopen host passes its own and never
// calls this, so it needs no stipple_get_api symbol at link time).
inline const stipple_api& linkedApi() {
    const stipple_api* api = nullptr;
    if (stipple_get_api(STIPPLE_ABI_MAJOR, &api) != STIPPLE_OK || !api) return kit_detail::emptyApi();
    return *api;
}

// Pixel coordinates are signed (film crop windows and filter footprints reach negative pixels, as pbrt-v4's
// Point2i does). The C ABI takes uint32: a signed coordinate is passed as its two's-complement bits, a bijection,
// so every signed pixel gets its own sets and (-1, 0) is not (0, 0). An aggregate: Pixel{x, y}.
struct Pixel {
    int32_t x, y;
};
inline uint32_t pixelBits(int32_t coordinate) { return static_cast<uint32_t>(coordinate); }
inline bool operator==(Pixel a, Pixel b) { return a.x == b.x && a.y == b.y; }
inline bool operator!=(Pixel a, Pixel b) { return !(a == b); }

// ---- patterns ---------------------------------------------------------------------------------------------------

// The names of the patterns the library serves, in id order ("independent", "stratified", ...). ABI 1.2.
inline Status patternNames(std::vector<std::string>& out, const stipple_api& api = linkedApi()) STIPPLE_HPP_MUST_USE;
inline Status patternNames(std::vector<std::string>& out, const stipple_api& api) {
    out.clear();
    if (!kit_detail::hasArrays(api)) return kit_detail::tooOld(api, "pattern listing", "1.2");
    uint32_t count = 0;
    Status s = kit_detail::statusOf(api, api.pattern_count(&count));
    for (uint32_t p = 0; s.ok() && p < count; ++p) {
        const char* name = nullptr;
        s = kit_detail::statusOf(api, api.pattern_name(p, &name));
        if (s.ok()) out.push_back(name);
    }
    return s;
}

// A pattern name as hosts write it, "<name>" or "<name>+blue-noise", to its id and STIPPLE_SAMPLER_FLAG_* bits:
// the library's own parser (stipple_pattern_parse, ABI 1.2); on a 1.1 library, its bare names and the 1.1 flag.
inline Status parsePattern(const std::string& pattern, uint32_t& id, uint32_t& flags,
                           const stipple_api& api = linkedApi()) STIPPLE_HPP_MUST_USE;
inline Status parsePattern(const std::string& pattern, uint32_t& id, uint32_t& flags, const stipple_api& api) {
    flags = 0;
    if (kit_detail::hasArrays(api)) return kit_detail::statusOf(api, api.pattern_parse(pattern.c_str(), &id, &flags));
    if (!kit_detail::hasStreams(api)) return kit_detail::tooOld(api, "stipple::parsePattern", "1.1");
    static const char kBlueNoise[] = "+blue-noise";
    const size_t suffix = sizeof kBlueNoise - 1;
    std::string name = pattern;
    if (name.size() > suffix && name.compare(name.size() - suffix, suffix, kBlueNoise) == 0) {
        name.resize(name.size() - suffix);
        flags = STIPPLE_SAMPLER_FLAG_BLUE_NOISE;
    }
    return kit_detail::statusOf(api, api.pattern_from_name(name.c_str(), &id));
}

// What a pattern serves (largest N, largest k * N, largest k, flags), for checks before creating a sampler. The
// name may carry "+blue-noise". ABI 1.2.
inline Status patternLimits(const std::string& pattern, stipple_pattern_limits& out,
                            const stipple_api& api = linkedApi()) STIPPLE_HPP_MUST_USE;
inline Status patternLimits(const std::string& pattern, stipple_pattern_limits& out, const stipple_api& api) {
    if (!kit_detail::hasArrays(api)) return kit_detail::tooOld(api, "pattern limits", "1.2");
    uint32_t id = 0, flags = 0;
    Status s = kit_detail::statusOf(api, api.pattern_parse(pattern.c_str(), &id, &flags));
    if (!s.ok()) return s;
    out = stipple_pattern_limits();
    out.struct_size = sizeof out;
    return kit_detail::statusOf(api, api.pattern_get_limits(id, &out));
}

// One entry of a declared layout (the layout half: fillPixel / sample). An aggregate: {arity, count, "name"}.
struct LayoutDimension {
    uint32_t arity;   // 1, 2 or 3 floats per value
    uint32_t count;   // k >= 1 values per pixel sample
    std::string name; // optional ("" = unnamed)
};

// What the sampler reports about one declared dimension (stipple_sampler_get_dimension_info).
struct DimensionInfo {
    uint32_t arity, count, floatsPerPixel;
    std::string name;
    uint32_t strata[3]; // stratified: strata per axis of the k * N set; others 0
};

// ---- Sampler ----------------------------------------------------------------------------------------------------

// RAII owner of a stipple_sampler. Move-only. Immutable after creation: share it (by reference) between threads.
class Sampler {
public:
    Sampler() : api_(nullptr), sampler_(nullptr), samplesPerPixel_(0), dimensionCount_(0) {}

    // Streams and arrays only (no layout). pattern: a name, optionally with "+blue-noise" (needs ABI 1.2); flags:
    // more STIPPLE_SAMPLER_FLAG_* bits. Throws Error on failure with exceptions, else records it in status().
    Sampler(const std::string& pattern, uint32_t samplesPerPixel, uint64_t seed, uint32_t flags = 0,
            const stipple_api& api = linkedApi())
        : Sampler() {
        finish(create(*this, pattern, samplesPerPixel, seed, flags, api));
    }
    // With a declared layout (fillPixel / sample serve it; streams and arrays work as well).
    Sampler(const std::string& pattern, uint32_t samplesPerPixel, uint64_t seed,
            const std::vector<LayoutDimension>& layout, uint32_t flags = 0, const stipple_api& api = linkedApi())
        : Sampler() {
        finish(create(*this, pattern, samplesPerPixel, seed, layout, flags, api));
    }
    // Any description.
    explicit Sampler(const stipple_sampler_desc& desc, const stipple_api& api = linkedApi()) : Sampler() {
        finish(create(*this, desc, api));
    }

    // The status forms of the constructors: out is replaced on success, left empty (with status()) on failure.
    static Status create(Sampler& out, const std::string& pattern, uint32_t samplesPerPixel, uint64_t seed,
                         uint32_t flags = 0, const stipple_api& api = linkedApi()) {
        return create(out, pattern, samplesPerPixel, seed, std::vector<LayoutDimension>(), flags, api);
    }
    static Status create(Sampler& out, const std::string& pattern, uint32_t samplesPerPixel, uint64_t seed,
                         const std::vector<LayoutDimension>& layout, uint32_t flags = 0,
                         const stipple_api& api = linkedApi()) {
        uint32_t id = 0, nameFlags = 0;
        Status s = parsePattern(pattern, id, nameFlags, api);
        if (!s.ok()) return out.fail(api, s);
        std::vector<stipple_dimension_desc> dims(layout.size(), stipple_dimension_desc());
        for (size_t d = 0; d < layout.size(); ++d) {
            dims[d].struct_size = sizeof(stipple_dimension_desc);
            dims[d].arity = layout[d].arity;
            dims[d].count = layout[d].count;
            dims[d].name = layout[d].name.empty() ? nullptr : layout[d].name.c_str();
        }
        stipple_sampler_desc desc = stipple_sampler_desc();
        desc.struct_size = sizeof desc;
        desc.pattern = id;
        desc.samples_per_pixel = samplesPerPixel;
        desc.seed = seed;
        desc.flags = flags | nameFlags;
        desc.dimension_count = static_cast<uint32_t>(layout.size());
        desc.dimensions = dims.empty() ? nullptr : dims.data();
        return create(out, desc, api);
    }
    static Status create(Sampler& out, const stipple_sampler_desc& desc, const stipple_api& api = linkedApi()) {
        if (!kit_detail::hasStreams(api)) return out.fail(api, kit_detail::tooOld(api, "stipple::Sampler", "1.1"));
        stipple_sampler handle = nullptr;
        Status s = kit_detail::statusOf(api, api.sampler_create(&desc, &handle));
        if (!s.ok()) return out.fail(api, s);
        Sampler made;
        made.api_ = &api;
        made.sampler_ = handle;
        made.samplesPerPixel_ = desc.samples_per_pixel;
        made.dimensionCount_ = desc.dimension_count;
        out = static_cast<Sampler&&>(made);
        return Status();
    }

    ~Sampler() { reset(); }
    Sampler(Sampler&& other) noexcept : Sampler() { swap(other); }
    Sampler& operator=(Sampler&& other) noexcept {
        if (this != &other) {
            reset();
            swap(other);
        }
        return *this;
    }
    Sampler(const Sampler&) = delete;
    Sampler& operator=(const Sampler&) = delete;

    explicit operator bool() const { return sampler_ != nullptr; }
    // Why the last creation into this object failed (ok() when it holds a sampler).
    const Status& status() const { return status_; }
    stipple_sampler handle() const { return sampler_; }
    const stipple_api& api() const { return *api_; }
    uint32_t samplesPerPixel() const { return samplesPerPixel_; }
    uint32_t dimensionCount() const { return dimensionCount_; }

    // ---- streams (no layout): one value of stream (index, arity), or a run of samples of it (count * arity).
    Status stream(Pixel pixel, uint32_t sampleIndex, uint32_t index, uint32_t arity, float* out) const
        STIPPLE_HPP_MUST_USE {
        if (!sampler_) return empty();
        return kit_detail::statusOf(*api_, api_->sampler_stream(sampler_, pixelBits(pixel.x), pixelBits(pixel.y),
                                                                sampleIndex, index, arity, out, arity));
    }
    Status streamFill(Pixel pixel, uint32_t firstSample, uint32_t count, uint32_t index, uint32_t arity,
                      float* out) const STIPPLE_HPP_MUST_USE {
        if (!sampler_) return empty();
        return kit_detail::statusOf(*api_,
                                    api_->sampler_stream_fill(sampler_, pixelBits(pixel.x), pixelBits(pixel.y),
                                                              firstSample, count, index, arity, out,
                                                              size_t(count) * arity));
    }

    // ---- arrays (ABI 1.2): k values per sample of array (index, arity), one set of k * N points per block.
    // k * arity floats (array) or count * k * arity (arrayFill), sample-major.
    Status array(Pixel pixel, uint32_t sampleIndex, uint32_t index, uint32_t arity, uint32_t k, float* out) const
        STIPPLE_HPP_MUST_USE {
        if (!sampler_) return empty();
        if (!kit_detail::hasArrays(*api_)) return kit_detail::tooOld(*api_, "arrays", "1.2");
        return kit_detail::statusOf(*api_, api_->sampler_array(sampler_, pixelBits(pixel.x), pixelBits(pixel.y),
                                                               sampleIndex, index, arity, k, out, size_t(k) * arity));
    }
    Status arrayFill(Pixel pixel, uint32_t firstSample, uint32_t count, uint32_t index, uint32_t arity, uint32_t k,
                     float* out) const STIPPLE_HPP_MUST_USE {
        if (!sampler_) return empty();
        if (!kit_detail::hasArrays(*api_)) return kit_detail::tooOld(*api_, "arrays", "1.2");
        return kit_detail::statusOf(*api_, api_->sampler_array_fill(sampler_, pixelBits(pixel.x), pixelBits(pixel.y),
                                                                    firstSample, count, index, arity, k, out,
                                                                    size_t(count) * k * arity));
    }

    // ---- the declared layout: all N samples of one dimension (N * k * arity floats, sample-major), or one sample
    // (k * arity floats); outCount is the capacity of out in floats.
    Status fillPixel(Pixel pixel, uint32_t dimension, float* out, size_t outCount) const STIPPLE_HPP_MUST_USE {
        if (!sampler_) return empty();
        return kit_detail::statusOf(*api_, api_->sampler_fill_pixel(sampler_, pixelBits(pixel.x), pixelBits(pixel.y),
                                                                    dimension, out, outCount));
    }
    Status sample(Pixel pixel, uint32_t sampleIndex, uint32_t dimension, float* out, size_t outCount) const
        STIPPLE_HPP_MUST_USE {
        if (!sampler_) return empty();
        return kit_detail::statusOf(*api_, api_->sampler_sample(sampler_, pixelBits(pixel.x), pixelBits(pixel.y),
                                                                sampleIndex, dimension, out, outCount));
    }
    // Past the layout: count independent uniform floats for (pixel, sample index, stream).
    Status sampleIndependent(Pixel pixel, uint32_t sampleIndex, uint32_t stream, float* out, size_t count) const
        STIPPLE_HPP_MUST_USE {
        if (!sampler_) return empty();
        return kit_detail::statusOf(*api_,
                                    api_->sampler_sample_independent(sampler_, pixelBits(pixel.x), pixelBits(pixel.y),
                                                                     sampleIndex, stream, out, count));
    }
    Status dimensionInfo(uint32_t dimension, DimensionInfo& out) const STIPPLE_HPP_MUST_USE {
        if (!sampler_) return empty();
        stipple_dimension_info info = stipple_dimension_info();
        info.struct_size = sizeof info;
        Status s = kit_detail::statusOf(*api_, api_->sampler_get_dimension_info(sampler_, dimension, &info));
        if (!s.ok()) return s;
        out.arity = info.arity;
        out.count = info.count;
        out.floatsPerPixel = info.floats_per_pixel;
        out.name = info.name ? info.name : "";
        for (int c = 0; c < 3; ++c) out.strata[c] = info.strata[c];
        return s;
    }
    Status findDimension(const std::string& name, uint32_t& out) const STIPPLE_HPP_MUST_USE {
        if (!sampler_) return empty();
        return kit_detail::statusOf(*api_, api_->sampler_find_dimension(sampler_, name.c_str(), &out));
    }

private:
    Status fail(const stipple_api& api, const Status& why) {
        reset();
        api_ = &api;
        status_ = why;
        return why;
    }
    void finish(const Status& s) {
#if STIPPLE_HPP_EXCEPTIONS
        check(s);
#else
        (void)s; // recorded in status_
#endif
    }
    Status empty() const {
        return status_.ok() ? Status(STIPPLE_ERROR_NULL_ARGUMENT, "stipple::Sampler: no sampler (default-constructed "
                                                                  "or moved from)")
                            : status_;
    }
    void reset() {
        if (sampler_) api_->sampler_release(sampler_);
        sampler_ = nullptr;
        status_ = Status();
    }
    void swap(Sampler& other) noexcept {
        std::swap(api_, other.api_);
        std::swap(sampler_, other.sampler_);
        std::swap(samplesPerPixel_, other.samplesPerPixel_);
        std::swap(dimensionCount_, other.dimensionCount_);
        status_.swap(other.status_);
    }

    const stipple_api* api_;
    stipple_sampler sampler_;
    uint32_t samplesPerPixel_;
    uint32_t dimensionCount_;
    Status status_;
};

// ---- PixelSampleCursor ------------------------------------------------------------------------------------------

// The per-thread view of one pixel sample, shaped like pbrt-v4's sampler interface: start() a pixel sample, then
// each get1D/get2D/get3D takes the next stream index (the call counter) with the arity of that call, and each
// get1DArray/get2DArray(k) the next array index (a counter of its own, as pbrt-v3's arrays). Skipping calls on
// data-dependent branches is fine: an index is only a name, values never depend on which indices were asked
// before. For stratification across the samples of a pixel, ask a given index with the same arity (and k) in
// every sample (another arity is defined: an independent set).
//
// Batching: start() opens a window of samples when the pixel changes, the sample index steps back or leaves the
// window: the rest of the sample's block, at most batchSamples() samples. The first time a (stream, arity) or
// (array, arity, k) is asked in a window, the cursor fetches it for the window's remaining samples with one
// stream_fill / array_fill call; later samples read the cache. Hosts that loop over the samples of a pixel (pbrt,
// Mitsuba, Cycles' tiles) pay one C call per (pixel, index) instead of per value, and a cached value costs one
// tag compare. A host that visits a pixel once per pass (sample-major: all pixels at sample 0, then sample 1, ...)
// sets setBatchSamples(1): one call per value, no waste.
class PixelSampleCursor {
public:
    // getPixel2D's stream: the last stream index (STIPPLE_STREAM_RESERVED_FIRST .. 0xffffffff are the kit's).
    enum : uint32_t { kPixelStream = 0xffffffffu };
    // Indices up to this many are cached; larger ones (a start dimension far out) are served per call.
    enum : uint32_t { kMaxCachedIndex = 4096 };

    explicit PixelSampleCursor(const Sampler& sampler)
        : sampler_(&sampler), pixel_(Pixel()), sampleIndex_(0), dimension_(0), array_(0),
          batchSamples_(sampler.samplesPerPixel() ? sampler.samplesPerPixel() : 1), windowFirst_(0), windowCount_(0),
          offset_(0), generation_(0), windowOpen_(false), streamCount_(), arrayCount_(), film_(), failed_(3, 0.0f) {}

    // The largest number of samples one fetch covers (default N; it never crosses a block). Takes effect at the
    // next start().
    void setBatchSamples(uint32_t samples) {
        batchSamples_ = samples < 1 ? 1 : samples;
        windowOpen_ = false;
    }
    uint32_t batchSamples() const { return batchSamples_; }

    void start(Pixel pixel, uint32_t sampleIndex, uint32_t dimension = 0) {
        if (!windowOpen_ || pixel != pixel_ || sampleIndex < sampleIndex_ || sampleIndex - windowFirst_ >= windowCount_)
            openWindow(pixel, sampleIndex);
        sampleIndex_ = sampleIndex;
        offset_ = sampleIndex - windowFirst_;
        dimension_ = dimension;
        array_ = 0;
        if (!status_.ok()) status_ = Status();
    }
    uint32_t dimension() const { return dimension_; }
    uint32_t sampleIndex() const { return sampleIndex_; }
    Pixel pixel() const { return pixel_; }
    // The first failure since start() (ok() if none). Without exceptions the get* forms report here.
    const Status& status() const { return status_; }

    float get1D() {
        const uint32_t index = dimension_++;
        return (isCached<1>(index) ? cached<1>(index) : value(fetchStream<1>(index)))[0];
    }
    std::array<float, 2> get2D() {
        const uint32_t index = dimension_++;
        return pair(isCached<2>(index) ? cached<2>(index) : value(fetchStream<2>(index)));
    }
    std::array<float, 3> get3D() {
        const uint32_t index = dimension_++;
        const float* v = isCached<3>(index) ? cached<3>(index) : value(fetchStream<3>(index));
        std::array<float, 3> r = {{v[0], v[1], v[2]}};
        return r;
    }
    // The film position within the pixel: its own 2D stream (kPixelStream); does not advance the counter.
    std::array<float, 2> getPixel2D() {
        return pair(film_.tag == generation_ ? film_.values + size_t(offset_) * 2 : value(fetchFilm()));
    }
    // The next array: k values (k floats, or k (u, v) pairs as 2k floats), valid until this cursor's next call.
    const float* get1DArray(uint32_t k) { return array(1, k); }
    const float* get2DArray(uint32_t k) { return array(2, k); }

    // The status forms: the same values, the status returned (also recorded in status()). Never throw.
    Status next1D(float& out) STIPPLE_HPP_MUST_USE {
        const uint32_t index = dimension_++;
        const float* v = isCached<1>(index) ? cached<1>(index) : fetchStream<1>(index);
        out = v[0];
        return outcome(v);
    }
    Status next2D(std::array<float, 2>& out) STIPPLE_HPP_MUST_USE {
        const uint32_t index = dimension_++;
        const float* v = isCached<2>(index) ? cached<2>(index) : fetchStream<2>(index);
        out[0] = v[0];
        out[1] = v[1];
        return outcome(v);
    }
    Status next3D(std::array<float, 3>& out) STIPPLE_HPP_MUST_USE {
        const uint32_t index = dimension_++;
        const float* v = isCached<3>(index) ? cached<3>(index) : fetchStream<3>(index);
        for (int c = 0; c < 3; ++c) out[c] = v[c];
        return outcome(v);
    }
    // The next array of arity 1..3: out points at k * arity floats, valid until this cursor's next call.
    Status nextArray(uint32_t arity, uint32_t k, const float*& out) STIPPLE_HPP_MUST_USE {
        const uint32_t index = array_++;
        out = isCachedArray(index, arity, k) ? cachedArray(index, arity, k) : fetchArray(index, arity, k);
        return outcome(out);
    }

private:
    // One cached batch: `values` (its storage's data()) holds the window's samples, `floats` per sample, filled from
    // the sample of the fetch on. tag = the window's generation | k << 32 (k = 0 for streams): a batch is current
    // exactly when its tag equals the expected one, so a hit costs one compare (arity is the table it sits in).
    struct Batch {
        uint64_t tag;
        float* values;
    };

    // The hot path: whether the current window holds (index, arity[, k]), and where its sample is. Checked and
    // read apart (no null pointer for a miss) so that a hit is a bounds check, one tag compare and an address.
    template <uint32_t Arity>
    bool isCached(uint32_t index) const {
        return index < streamCount_[Arity - 1] && streams_[Arity - 1][index].tag == generation_;
    }
    template <uint32_t Arity>
    const float* cached(uint32_t index) const {
        return streams_[Arity - 1][index].values + size_t(offset_) * Arity;
    }
    bool isCachedArray(uint32_t index, uint32_t arity, uint32_t k) const {
        return arity - 1 < 3 && index < arrayCount_[arity - 1] && // other arities: fetchArray() reports them
               arrays_[arity - 1][index].tag == (uint64_t(k) << 32 | generation_);
    }
    const float* cachedArray(uint32_t index, uint32_t arity, uint32_t k) const {
        return arrays_[arity - 1][index].values + size_t(offset_) * k * arity;
    }
    const float* array(uint32_t arity, uint32_t k) {
        const uint32_t index = array_++;
        return isCachedArray(index, arity, k) ? cachedArray(index, arity, k) : value(fetchArray(index, arity, k));
    }

    // A failed call returns failed_.data() (zeros); nothing else does, so the pointer itself says whether it failed.
    const float* value(const float* v) {
#if STIPPLE_HPP_EXCEPTIONS
        if (v == failed_.data()) check(lastError_);
#endif
        return v;
    }
    static std::array<float, 2> pair(const float* v) {
        std::array<float, 2> r = {{v[0], v[1]}};
        return r;
    }
    Status outcome(const float* v) const { return v == failed_.data() ? lastError_ : Status(); }

    // A new window: every batch stale (tags hold the generation; on its wrap-around they are cleared).
    void openWindow(Pixel pixel, uint32_t sampleIndex) {
        if (++generation_ == 0) {
            for (int a = 0; a < 3; ++a) {
                for (size_t i = 0; i < streams_[a].size(); ++i) streams_[a][i].tag = 0;
                for (size_t i = 0; i < arrays_[a].size(); ++i) arrays_[a][i].tag = 0;
            }
            film_.tag = 0;
            generation_ = 1;
        }
        const uint64_t n = sampler_->samplesPerPixel() ? sampler_->samplesPerPixel() : 1;
        const uint64_t blockEnd = sampleIndex < n ? n : (uint64_t(sampleIndex) / n + 1) * n; // no division in block 0
        const uint64_t count = blockEnd - sampleIndex;
        pixel_ = pixel;
        windowFirst_ = sampleIndex;
        windowCount_ = count < batchSamples_ ? uint32_t(count) : batchSamples_;
        windowOpen_ = true;
    }

    // A miss (the first use of an index in the window, or no cache for it): one batch call for the window's
    // remaining samples. Out of line, one function per kind (and arity), so that the hit path stays small enough to
    // inline into the host's loop and the miss path does no work for shapes it is not serving.
    template <uint32_t Arity>
    STIPPLE_HPP_NOINLINE const float* fetchStream(uint32_t index) {
        if (index >= kMaxCachedIndex) {
            // The call counter never reaches the kit's reserved streams: getPixel2D's would return the film position.
            if (index >= STIPPLE_STREAM_RESERVED_FIRST)
                return failed(Status(STIPPLE_ERROR_OUT_OF_RANGE,
                                     "PixelSampleCursor: the call counter reached stream index " +
                                         std::to_string(index) +
                                         ", in the kit's reserved range (getPixel2D's stream and the kit's own)"),
                              Arity);
            return direct(false, index, Arity, 0, Arity);
        }
        if (index >= streamCount_[Arity - 1])
            grow(streams_[Arity - 1], streamValues_[Arity - 1], streamCount_[Arity - 1], index);
        return refill(streams_[Arity - 1][index], streamValues_[Arity - 1][index], false, index, Arity, 0);
    }
    STIPPLE_HPP_NOINLINE const float* fetchArray(uint32_t index, uint32_t arity, uint32_t k) {
        // Shapes the library refuses (arity outside 1..3, k outside 1..STIPPLE_MAX_VALUES_PER_SAMPLE, k * N past
        // STIPPLE_MAX_SET_SIZE) go straight to it for its message, with no buffer sized by the window: every limit
        // is checked before anything is sized, so a status form never meets std::bad_alloc from a bad shape (which
        // a -fno-exceptions host could only abort on). So do indices past the cache.
        if (arity - 1 >= 3 || k - 1 >= STIPPLE_MAX_VALUES_PER_SAMPLE) return direct(true, index, arity, k, 3);
        const uint64_t n = sampler_->samplesPerPixel() ? sampler_->samplesPerPixel() : 1;
        if (uint64_t(k) * n > STIPPLE_MAX_SET_SIZE) return direct(true, index, arity, k, size_t(k) * arity);
        if (index >= kMaxCachedIndex) return direct(true, index, arity, k, size_t(k) * arity);
        if (index >= arrayCount_[arity - 1])
            grow(arrays_[arity - 1], arrayValues_[arity - 1], arrayCount_[arity - 1], index);
        return refill(arrays_[arity - 1][index], arrayValues_[arity - 1][index], true, index, arity, k);
    }
    STIPPLE_HPP_NOINLINE const float* fetchFilm() { return refill(film_, filmValues_, false, kPixelStream, 2, 0); }

    static void grow(std::vector<Batch>& table, std::vector<std::vector<float>>& values, uint32_t& count,
                     uint32_t index) {
        const Batch stale = {0, nullptr};
        table.resize(size_t(index) + 1, stale);
        values.resize(size_t(index) + 1);
        count = index + 1;
    }
    // Fills `batch` for the window's samples from the current one on (its storage grows to the window, never
    // shrinks) and returns the current sample's values.
    STIPPLE_HPP_ALWAYS_INLINE const float* refill(Batch& batch, std::vector<float>& storage, bool isArray,
                                                  uint32_t index, uint32_t arity, uint32_t k) {
        if (!windowOpen_) { // no start() yet, or setBatchSamples() since: a window from the current sample
            openWindow(pixel_, sampleIndex_);
            offset_ = 0;
        }
        const uint32_t floats = (isArray ? k : 1) * arity;
        const size_t size = size_t(windowCount_) * floats;
        if (storage.size() < size) storage.resize(size);
        batch.tag = 0;
        float* out = storage.data() + size_t(offset_) * floats;
        const uint32_t count = windowCount_ - offset_;
        const stipple_sampler handle = sampler_->handle();
        if (!handle || (isArray && !kit_detail::hasArrays(sampler_->api()))) { // Sampler's calls say why
            const Status s = isArray ? sampler_->arrayFill(pixel_, sampleIndex_, count, index, arity, k, out)
                                     : sampler_->streamFill(pixel_, sampleIndex_, count, index, arity, out);
            if (!s.ok()) return failed(s, floats);
        } else { // the C call itself: no Status built on success
            const stipple_api& api = sampler_->api();
            const stipple_status code =
                isArray ? api.sampler_array_fill(handle, pixelBits(pixel_.x), pixelBits(pixel_.y), sampleIndex_, count,
                                                 index, arity, k, out, size_t(count) * floats)
                        : api.sampler_stream_fill(handle, pixelBits(pixel_.x), pixelBits(pixel_.y), sampleIndex_, count,
                                                  index, arity, out, size_t(count) * floats);
            if (code != STIPPLE_OK) return failed(kit_detail::statusOf(api, code), floats);
        }
        batch.values = storage.data();
        batch.tag = (isArray ? uint64_t(k) << 32 : 0) | generation_;
        return out;
    }
    // Indices past the cache and shapes the library refuses: one call per value.
    const float* direct(bool isArray, uint32_t index, uint32_t arity, uint32_t k, size_t floats) {
        spill_.resize(floats);
        const Status s = isArray ? sampler_->array(pixel_, sampleIndex_, index, arity, k, spill_.data())
                                 : sampler_->stream(pixel_, sampleIndex_, index, arity, spill_.data());
        if (!s.ok()) return failed(s, floats);
        return spill_.data();
    }
    const float* failed(const Status& s, size_t floats) {
        if (status_.ok()) status_ = s;
        lastError_ = s;
        failed_.assign(floats < 3 ? 3 : floats, 0.0f);
        return failed_.data();
    }
    const Sampler* sampler_;
    Pixel pixel_;
    uint32_t sampleIndex_, dimension_, array_, batchSamples_;
    uint32_t windowFirst_, windowCount_, offset_; // the window's samples; offset_ = sampleIndex_ - windowFirst_
    uint32_t generation_;                         // of the window; 0 is never current
    bool windowOpen_;
    Status status_, lastError_;
    std::vector<Batch> streams_[3], arrays_[3]; // per arity - 1, indexed by stream / array index (hot: 16 bytes)
    uint32_t streamCount_[3], arrayCount_[3];   // their sizes, for the hot path's bounds check
    std::vector<std::vector<float>> streamValues_[3], arrayValues_[3]; // their storage, in the same places
    Batch film_;                                                       // getPixel2D's stream
    std::vector<float> filmValues_, spill_, failed_;
};

} // namespace stipple

#endif // STIPPLE_STIPPLE_HPP
