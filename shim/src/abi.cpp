// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// abi.cpp — the C ABI: every exported stipple_* function and the dlopen function table.
//
// Each entry point checks its arguments (messages name the argument, its value and what was expected) and runs
// its body through callGuarded, so no exception reaches the host and nothing aborts or prints.
#include "error.h"
#include "pattern_registry.h"
#include "sampler.h"

#include <stipple/stipple.h>

#include <algorithm>
#include <cstring>
#include <string>

using stipple::detail::callGuarded;
using stipple::detail::Error;
using stipple::detail::requireNonNull;

namespace {

const stipple::detail::Sampler& checkedSampler(stipple_sampler sampler) {
    requireNonNull(sampler, "sampler");
    return *stipple::detail::fromHandle(sampler);
}

void checkDimension(const stipple::detail::Sampler& sampler, uint32_t dimension) {
    if (sampler.dimensionCount() == 0)
        throw Error(STIPPLE_ERROR_OUT_OF_RANGE,
                    "dimension is " + std::to_string(dimension) +
                        "; this sampler declares no layout (dimension_count 0): use stipple_sampler_stream");
    if (dimension >= sampler.dimensionCount())
        throw Error(STIPPLE_ERROR_OUT_OF_RANGE,
                    "dimension is " + std::to_string(dimension) + "; expected 0.." +
                        std::to_string(sampler.dimensionCount() - 1) +
                        " (the declared layout; past it use stipple_sampler_sample_independent)");
}

// The checks of the per-value calls inline into them; building the message is out of line (cold).
[[noreturn, gnu::cold, gnu::noinline]] void throwArity(uint32_t arity, uint32_t maxArity) {
    throw Error(STIPPLE_ERROR_INVALID_ARGUMENT,
                "arity is " + std::to_string(arity) + "; expected " + stipple::detail::arityList(maxArity));
}

inline void checkArity(const stipple::detail::Sampler& sampler, uint32_t arity) {
    const uint32_t maxArity = sampler.patternOps().limits.maxArity;
    if (arity < 1 || arity > maxArity) [[unlikely]]
        throwArity(arity, maxArity);
}

[[noreturn, gnu::cold, gnu::noinline]] void throwCapacity(size_t outCount, size_t needed) {
    throw Error(STIPPLE_ERROR_OUT_OF_RANGE,
                "out_count is " + std::to_string(outCount) + "; expected at least " + std::to_string(needed));
}

inline void checkCapacity(size_t outCount, size_t needed) {
    if (outCount < needed) [[unlikely]]
        throwCapacity(outCount, needed);
}

// A run of sample indices [first, first + count): at least one, and all of them uint32.
void checkSampleRange(uint32_t first, uint32_t count) {
    if (count == 0) throw Error(STIPPLE_ERROR_OUT_OF_RANGE, "sample_count is 0; expected at least 1");
    if (uint64_t(first) + count > (uint64_t(1) << 32))
        throw Error(STIPPLE_ERROR_OUT_OF_RANGE, "first_sample + sample_count is " +
                                                    std::to_string(uint64_t(first) + count) +
                                                    "; expected at most 2^32 (sample indices are uint32)");
}

// Output structs: struct_size is set by the caller; we fill what we know and zero the rest of its struct.
template <typename Info>
void prepareOutput(Info* info, const char* argument) {
    requireNonNull(info, argument);
    if (info->struct_size < sizeof(Info))
        throw Error(STIPPLE_ERROR_STRUCT_SIZE, std::string(argument) + "->struct_size is " +
                                                   std::to_string(info->struct_size) + "; expected at least " +
                                                   std::to_string(sizeof(Info)));
    const uint32_t size = info->struct_size;
    std::memset(static_cast<void*>(info), 0, size);
    info->struct_size = size;
}

} // namespace

extern "C" {

STIPPLE_API const char* stipple_last_error_message(void) { return stipple::detail::lastErrorMessage(); }

STIPPLE_API stipple_status stipple_get_version(uint32_t* major, uint32_t* minor, uint32_t* patch) {
    return callGuarded(__func__, [&] {
        requireNonNull(major, "major");
        requireNonNull(minor, "minor");
        requireNonNull(patch, "patch");
        *major = STIPPLE_ABI_MAJOR;
        *minor = STIPPLE_ABI_MINOR;
        *patch = STIPPLE_VERSION_PATCH; // the project's, from CMake
    });
}

STIPPLE_API stipple_status stipple_pattern_from_name(const char* name, uint32_t* out_pattern) {
    return callGuarded(__func__, [&] {
        requireNonNull(name, "name");
        requireNonNull(out_pattern, "out_pattern");
        if (stipple::detail::findPatternId(name, out_pattern)) return;
        const size_t length = strnlen(name, 64);
        throw Error(STIPPLE_ERROR_INVALID_ARGUMENT, "name is \"" + std::string(name, length) +
                                                        (length == 64 ? "...\"" : "\"") + "; expected " +
                                                        stipple::detail::patternNameList());
    });
}

STIPPLE_API stipple_status stipple_pattern_name(uint32_t pattern, const char** out_name) {
    return callGuarded(__func__, [&] {
        requireNonNull(out_name, "out_name");
        const stipple::detail::PatternOps* ops = stipple::detail::findPattern(pattern);
        if (!ops)
            throw Error(STIPPLE_ERROR_INVALID_ARGUMENT, "pattern is " + std::to_string(pattern) + "; expected 0.." +
                                                            std::to_string(stipple::detail::patternCount() - 1));
        *out_name = ops->name;
    });
}

STIPPLE_API stipple_status stipple_sampler_create(const stipple_sampler_desc* desc, stipple_sampler* out_sampler) {
    return callGuarded(__func__, [&] {
        requireNonNull(out_sampler, "out_sampler");
        *out_sampler = nullptr;
        requireNonNull(desc, "desc");
        *out_sampler = stipple::detail::toHandle(stipple::detail::createSampler(*desc));
    });
}

STIPPLE_API stipple_status stipple_sampler_release(stipple_sampler sampler) {
    return callGuarded(__func__, [&] { delete stipple::detail::fromHandle(sampler); });
}

STIPPLE_API stipple_status stipple_sampler_get_info(stipple_sampler sampler, stipple_sampler_info* out_info) {
    return callGuarded(__func__, [&] {
        const stipple::detail::Sampler& s = checkedSampler(sampler);
        prepareOutput(out_info, "out_info");
        out_info->pattern = s.pattern();
        out_info->samples_per_pixel = s.samplesPerPixel();
        out_info->dimension_count = s.dimensionCount();
        out_info->seed = s.seed();
    });
}

STIPPLE_API stipple_status stipple_sampler_get_dimension_info(stipple_sampler sampler, uint32_t dimension,
                                                              stipple_dimension_info* out_info) {
    return callGuarded(__func__, [&] {
        const stipple::detail::Sampler& s = checkedSampler(sampler);
        checkDimension(s, dimension);
        prepareOutput(out_info, "out_info");
        const stipple::detail::Dimension& dim = s.dimension(dimension);
        out_info->arity = dim.arity;
        out_info->count = dim.count;
        out_info->floats_per_pixel = dim.floatsPerPixel();
        out_info->name = dim.name.c_str();
        if (s.patternOps().strata) s.patternOps().strata(dim, out_info->strata);
    });
}

STIPPLE_API stipple_status stipple_sampler_find_dimension(stipple_sampler sampler, const char* name,
                                                          uint32_t* out_dimension) {
    return callGuarded(__func__, [&] {
        const stipple::detail::Sampler& s = checkedSampler(sampler);
        requireNonNull(name, "name");
        requireNonNull(out_dimension, "out_dimension");
        for (uint32_t d = 0; d < s.dimensionCount(); ++d)
            if (s.dimension(d).name == name) {
                *out_dimension = d;
                return;
            }
        const size_t length = strnlen(name, 64);
        throw Error(STIPPLE_ERROR_INVALID_ARGUMENT, "name is \"" + std::string(name, length) +
                                                        (length == 64 ? "...\"" : "\"") +
                                                        "; expected the name of one of the sampler's " +
                                                        std::to_string(s.dimensionCount()) + " dimensions");
    });
}

STIPPLE_API stipple_status stipple_sampler_fill_pixel(stipple_sampler sampler, uint32_t pixel_x, uint32_t pixel_y,
                                                      uint32_t dimension, float* out, size_t out_count) {
    return callGuarded(__func__, [&] {
        const stipple::detail::Sampler& s = checkedSampler(sampler);
        checkDimension(s, dimension);
        requireNonNull(out, "out");
        checkCapacity(out_count, s.dimension(dimension).floatsPerPixel());
        s.fillPixel(pixel_x, pixel_y, dimension, out);
    });
}

STIPPLE_API stipple_status stipple_sampler_sample(stipple_sampler sampler, uint32_t pixel_x, uint32_t pixel_y,
                                                  uint32_t sample_index, uint32_t dimension, float* out,
                                                  size_t out_count) {
    return callGuarded(__func__, [&] {
        const stipple::detail::Sampler& s = checkedSampler(sampler);
        checkDimension(s, dimension);
        requireNonNull(out, "out");
        checkCapacity(out_count, s.dimension(dimension).floatsPerSample());
        s.sample(pixel_x, pixel_y, sample_index, dimension, out);
    });
}

STIPPLE_API stipple_status stipple_sampler_sample_independent(stipple_sampler sampler, uint32_t pixel_x,
                                                              uint32_t pixel_y, uint32_t sample_index, uint32_t stream,
                                                              float* out, size_t out_count) {
    return callGuarded(__func__, [&] {
        const stipple::detail::Sampler& s = checkedSampler(sampler);
        requireNonNull(out, "out");
        if (out_count == 0) throw Error(STIPPLE_ERROR_OUT_OF_RANGE, "out_count is 0; expected at least 1");
        s.sampleIndependent(pixel_x, pixel_y, sample_index, stream, out, out_count);
    });
}

STIPPLE_API stipple_status stipple_sampler_stream(stipple_sampler sampler, uint32_t pixel_x, uint32_t pixel_y,
                                                  uint32_t sample_index, uint32_t dimension, uint32_t arity, float* out,
                                                  size_t out_count) {
    return callGuarded(__func__, [&] {
        const stipple::detail::Sampler& s = checkedSampler(sampler);
        checkArity(s, arity);
        requireNonNull(out, "out");
        checkCapacity(out_count, arity);
        s.stream(pixel_x, pixel_y, sample_index, dimension, arity, out);
    });
}

STIPPLE_API stipple_status stipple_sampler_stream_fill(stipple_sampler sampler, uint32_t pixel_x, uint32_t pixel_y,
                                                       uint32_t first_sample, uint32_t sample_count, uint32_t dimension,
                                                       uint32_t arity, float* out, size_t out_count) {
    return callGuarded(__func__, [&] {
        const stipple::detail::Sampler& s = checkedSampler(sampler);
        checkArity(s, arity);
        checkSampleRange(first_sample, sample_count);
        requireNonNull(out, "out");
        checkCapacity(out_count, size_t(sample_count) * arity);
        s.streamFill(pixel_x, pixel_y, first_sample, sample_count, dimension, arity, out);
    });
}

// ---- 1.2: array streams, pattern listing and limits, flags by name ----------------------------------------------

} // extern "C"

namespace {

stipple_pattern_limits patternLimits(const stipple::detail::PatternOps& ops) {
    stipple_pattern_limits limits{};
    limits.struct_size = sizeof limits;
    limits.max_samples_per_pixel = std::min<uint32_t>(ops.limits.maxSetSize, STIPPLE_MAX_SAMPLES_PER_PIXEL);
    limits.max_set_size = ops.limits.maxSetSize;
    limits.max_values_per_sample = STIPPLE_MAX_VALUES_PER_SAMPLE;
    limits.max_dimensions = STIPPLE_MAX_DIMENSIONS;
    limits.flags = ops.blueNoise == stipple::detail::BlueNoiseMode::Unsupported ? 0u : STIPPLE_SAMPLER_FLAG_BLUE_NOISE;
    return limits;
}

const stipple::detail::PatternOps& checkedPattern(uint32_t pattern) {
    const stipple::detail::PatternOps* ops = stipple::detail::findPattern(pattern);
    if (!ops)
        throw Error(STIPPLE_ERROR_INVALID_ARGUMENT,
                    "pattern is " + std::to_string(pattern) + "; expected " + stipple::detail::patternIdList());
    return *ops;
}

// k of an array: 1..max, and k * N within the sampler's pattern's set size.
void checkArrayCount(const stipple::detail::Sampler& s, uint32_t k) {
    const stipple::detail::PatternOps& ops = s.patternOps();
    if (k < 1 || k > STIPPLE_MAX_VALUES_PER_SAMPLE)
        throw Error(STIPPLE_ERROR_OUT_OF_RANGE,
                    "k is " + std::to_string(k) + "; expected 1.." + std::to_string(STIPPLE_MAX_VALUES_PER_SAMPLE));
    if (uint64_t(k) * s.samplesPerPixel() > ops.limits.maxSetSize)
        throw Error(STIPPLE_ERROR_OUT_OF_RANGE,
                    "k is " + std::to_string(k) + ": k * samples_per_pixel = " +
                        std::to_string(uint64_t(k) * s.samplesPerPixel()) + "; the " + ops.name +
                        " pattern serves sets of at most " + std::to_string(ops.limits.maxSetSize) +
                        " points (stipple_pattern_get_limits)");
}

} // namespace

extern "C" {

STIPPLE_API stipple_status stipple_sampler_array(stipple_sampler sampler, uint32_t pixel_x, uint32_t pixel_y,
                                                 uint32_t sample_index, uint32_t array_index, uint32_t arity,
                                                 uint32_t k, float* out, size_t out_count) {
    return callGuarded(__func__, [&] {
        const stipple::detail::Sampler& s = checkedSampler(sampler);
        checkArity(s, arity);
        checkArrayCount(s, k);
        requireNonNull(out, "out");
        checkCapacity(out_count, size_t(k) * arity);
        s.array(pixel_x, pixel_y, sample_index, array_index, arity, k, out);
    });
}

STIPPLE_API stipple_status stipple_sampler_array_fill(stipple_sampler sampler, uint32_t pixel_x, uint32_t pixel_y,
                                                      uint32_t first_sample, uint32_t sample_count,
                                                      uint32_t array_index, uint32_t arity, uint32_t k, float* out,
                                                      size_t out_count) {
    return callGuarded(__func__, [&] {
        const stipple::detail::Sampler& s = checkedSampler(sampler);
        checkArity(s, arity);
        checkArrayCount(s, k);
        checkSampleRange(first_sample, sample_count);
        requireNonNull(out, "out");
        checkCapacity(out_count, uint64_t(sample_count) * k * arity);
        s.arrayFill(pixel_x, pixel_y, first_sample, sample_count, array_index, arity, k, out);
    });
}

STIPPLE_API stipple_status stipple_pattern_count(uint32_t* out_count) {
    return callGuarded(__func__, [&] {
        requireNonNull(out_count, "out_count");
        *out_count = stipple::detail::patternCount();
    });
}

STIPPLE_API stipple_status stipple_pattern_get_limits(uint32_t pattern, stipple_pattern_limits* out_limits) {
    return callGuarded(__func__, [&] {
        const stipple::detail::PatternOps& ops = checkedPattern(pattern);
        prepareOutput(out_limits, "out_limits");
        const uint32_t size = out_limits->struct_size;
        *out_limits = patternLimits(ops);
        out_limits->struct_size = size;
    });
}

STIPPLE_API stipple_status stipple_pattern_parse(const char* name, uint32_t* out_pattern, uint32_t* out_flags) {
    return callGuarded(__func__, [&] {
        requireNonNull(name, "name");
        requireNonNull(out_pattern, "out_pattern");
        requireNonNull(out_flags, "out_flags");
        static const char kBlueNoise[] = "+blue-noise";
        const size_t length = strnlen(name, 128);
        std::string base(name, length);
        uint32_t flags = 0;
        const size_t plus = base.find('+');
        if (plus != std::string::npos) {
            if (base.compare(plus, std::string::npos, kBlueNoise) != 0)
                throw Error(STIPPLE_ERROR_INVALID_ARGUMENT, "name is \"" + base + "\"; the only suffix is \"" +
                                                                kBlueNoise + "\" (STIPPLE_SAMPLER_FLAG_BLUE_NOISE)");
            flags = STIPPLE_SAMPLER_FLAG_BLUE_NOISE;
            base.resize(plus);
        }
        uint32_t id = 0;
        if (stipple::detail::findPatternId(base.c_str(), &id)) {
            *out_pattern = id;
            *out_flags = flags;
            return;
        }
        throw Error(STIPPLE_ERROR_INVALID_ARGUMENT, "name is \"" + std::string(name, length) + (length == 128 ? "...\"" : "\"") +
                                                        "; expected " + stipple::detail::patternNameList() +
                                                        ", optionally followed by \"" +
                                                        kBlueNoise + "\"");
    });
}

STIPPLE_API stipple_status stipple_get_api(uint32_t abi_major, const stipple_api** out_api) {
    static const stipple_api kApi = {
        sizeof(stipple_api),
        STIPPLE_ABI_MAJOR,
        STIPPLE_ABI_MINOR,
        0,
        &stipple_last_error_message,
        &stipple_get_version,
        &stipple_pattern_from_name,
        &stipple_pattern_name,
        &stipple_sampler_create,
        &stipple_sampler_release,
        &stipple_sampler_get_info,
        &stipple_sampler_get_dimension_info,
        &stipple_sampler_find_dimension,
        &stipple_sampler_fill_pixel,
        &stipple_sampler_sample,
        &stipple_sampler_sample_independent,
        &stipple_sampler_stream,
        &stipple_sampler_stream_fill,
        &stipple_sampler_array,
        &stipple_sampler_array_fill,
        &stipple_pattern_count,
        &stipple_pattern_get_limits,
        &stipple_pattern_parse,
    };
    return callGuarded(__func__, [&] {
        requireNonNull(out_api, "out_api");
        *out_api = nullptr;
        if (abi_major != STIPPLE_ABI_MAJOR)
            throw Error(STIPPLE_ERROR_ABI_VERSION, "abi_major is " + std::to_string(abi_major) +
                                                       "; this library implements ABI major version " +
                                                       std::to_string(STIPPLE_ABI_MAJOR));
        *out_api = &kApi;
    });
}

} // extern "C"
