// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// sampler_create.cpp — validating a stipple_sampler_desc and building the Sampler it describes.
//
// Extensible structs: struct_size below the first released size is STIPPLE_ERROR_STRUCT_SIZE; bytes past the
// size this library knows must be zero (a newer host asking for a feature we lack is an error, not ignored).
// The dimension array's stride is dimensions[0].struct_size, and every entry must carry that same size.
#include "error.h"
#include "pattern_registry.h"
#include "sampler.h"

#include <bit>
#include <cstring>
#include <string>

namespace stipple::detail {

namespace {

void requireZeroTail(const void* object, size_t knownSize, size_t structSize, const std::string& argument) {
    const unsigned char* bytes = static_cast<const unsigned char*>(object);
    for (size_t i = knownSize; i < structSize; ++i)
        if (bytes[i] != 0)
            throw Error(STIPPLE_ERROR_INVALID_ARGUMENT,
                        argument + " has struct_size " + std::to_string(structSize) +
                            " and a non-zero byte at offset " + std::to_string(i) + "; this library (ABI " +
                            std::to_string(STIPPLE_ABI_MAJOR) + "." + std::to_string(STIPPLE_ABI_MINOR) + ") knows " +
                            std::to_string(knownSize) + " bytes and requires unknown trailing fields to be zero");
}

Dimension makeDimension(const stipple_dimension_desc& in, uint32_t index, const PatternOps& pattern,
                        uint32_t samplesPerPixel) {
    const std::string argument = "desc->dimensions[" + std::to_string(index) + "]";
    if (in.arity < 1 || in.arity > pattern.limits.maxArity)
        throw Error(STIPPLE_ERROR_INVALID_ARGUMENT, argument + ".arity is " + std::to_string(in.arity) + "; expected " +
                                                        arityList(pattern.limits.maxArity));
    const uint32_t count = in.count == 0 ? 1 : in.count;
    if (count > STIPPLE_MAX_VALUES_PER_SAMPLE)
        throw Error(STIPPLE_ERROR_OUT_OF_RANGE, argument + ".count is " + std::to_string(in.count) + "; expected 1.." +
                                                    std::to_string(STIPPLE_MAX_VALUES_PER_SAMPLE) + " (0 reads as 1)");
    if (uint64_t(count) * samplesPerPixel > STIPPLE_MAX_SET_SIZE)
        throw Error(STIPPLE_ERROR_OUT_OF_RANGE,
                    argument + ".count is " + std::to_string(count) +
                        ": count * samples_per_pixel = " + std::to_string(uint64_t(count) * samplesPerPixel) +
                        "; expected at most STIPPLE_MAX_SET_SIZE (" + std::to_string(STIPPLE_MAX_SET_SIZE) + ")");
    if (in.reserved != 0)
        throw Error(STIPPLE_ERROR_INVALID_ARGUMENT,
                    argument + ".reserved is " + std::to_string(in.reserved) + "; expected 0");
    if (count * samplesPerPixel > pattern.limits.maxSetSize)
        throw Error(STIPPLE_ERROR_OUT_OF_RANGE,
                    argument + ": count * samples_per_pixel = " + std::to_string(count * samplesPerPixel) + "; the " +
                        pattern.name + " pattern serves sets of at most " + std::to_string(pattern.limits.maxSetSize) +
                        " points");
    Dimension dim = makePatternDimension(pattern, in.arity, count, count * samplesPerPixel);
    if (in.name) {
        const size_t length = strnlen(in.name, STIPPLE_MAX_NAME_LENGTH + 1);
        if (length > STIPPLE_MAX_NAME_LENGTH)
            throw Error(STIPPLE_ERROR_OUT_OF_RANGE, argument + ".name is longer than " +
                                                        std::to_string(STIPPLE_MAX_NAME_LENGTH) +
                                                        " characters; expected a shorter name or NULL");
        dim.name.assign(in.name, length);
    }
    return dim;
}

} // namespace

Sampler* createSampler(const stipple_sampler_desc& desc) {
    constexpr size_t kDescSize = sizeof(stipple_sampler_desc);
    if (desc.struct_size < kDescSize)
        throw Error(STIPPLE_ERROR_STRUCT_SIZE, "desc->struct_size is " + std::to_string(desc.struct_size) +
                                                   "; expected at least " + std::to_string(kDescSize) +
                                                   " (sizeof(stipple_sampler_desc))");
    requireZeroTail(&desc, kDescSize, desc.struct_size, "desc");
    const PatternOps* pattern = findPattern(desc.pattern);
    if (!pattern)
        throw Error(STIPPLE_ERROR_INVALID_ARGUMENT,
                    "desc->pattern is " + std::to_string(desc.pattern) + "; expected " + patternIdList());
    if (desc.samples_per_pixel < 1 || desc.samples_per_pixel > STIPPLE_MAX_SAMPLES_PER_PIXEL)
        throw Error(STIPPLE_ERROR_OUT_OF_RANGE, "desc->samples_per_pixel is " + std::to_string(desc.samples_per_pixel) +
                                                    "; expected 1.." + std::to_string(STIPPLE_MAX_SAMPLES_PER_PIXEL));
    if (desc.dimension_count > STIPPLE_MAX_DIMENSIONS)
        throw Error(STIPPLE_ERROR_OUT_OF_RANGE, "desc->dimension_count is " + std::to_string(desc.dimension_count) +
                                                    "; expected 0.." + std::to_string(STIPPLE_MAX_DIMENSIONS) +
                                                    " (0: no declared layout, streams only)");
    constexpr uint32_t kKnownFlags = STIPPLE_SAMPLER_FLAG_BLUE_NOISE;
    if ((desc.flags & ~kKnownFlags) != 0)
        throw Error(STIPPLE_ERROR_INVALID_ARGUMENT,
                    "desc->flags is " + std::to_string(desc.flags) + "; unknown bits " +
                        std::to_string(desc.flags & ~kKnownFlags) +
                        " (this library knows only STIPPLE_SAMPLER_FLAG_BLUE_NOISE = 1)");
    if ((desc.flags & STIPPLE_SAMPLER_FLAG_BLUE_NOISE) != 0 && pattern->blueNoise == BlueNoiseMode::Unsupported)
        throw Error(STIPPLE_ERROR_INVALID_ARGUMENT,
                    std::string("desc->flags has STIPPLE_SAMPLER_FLAG_BLUE_NOISE, which the ") + pattern->name +
                        " pattern does not support: " + pattern->blueNoiseRefusal + "; the flag is supported by " +
                        blueNoisePatternList());
    // Streams serve sets of N points of every pattern, so N itself must be a set the pattern serves.
    if (desc.samples_per_pixel > pattern->limits.maxSetSize)
        throw Error(STIPPLE_ERROR_OUT_OF_RANGE, "desc->samples_per_pixel is " + std::to_string(desc.samples_per_pixel) +
                                                    "; the " + pattern->name + " pattern serves sets of at most " +
                                                    std::to_string(pattern->limits.maxSetSize) + " points");
    if (desc.reserved != 0)
        throw Error(STIPPLE_ERROR_INVALID_ARGUMENT,
                    "desc->reserved is " + std::to_string(desc.reserved) + "; expected 0");

    if (desc.dimension_count == 0) { // streams only; dimensions is not read and may be NULL
        return new Sampler(desc.pattern, desc.samples_per_pixel, desc.seed, {}, desc.flags);
    }
    requireNonNull(desc.dimensions, "desc->dimensions");
    constexpr size_t kDimensionSize = sizeof(stipple_dimension_desc);
    const uint32_t stride = desc.dimensions[0].struct_size;
    if (stride < kDimensionSize)
        throw Error(STIPPLE_ERROR_STRUCT_SIZE, "desc->dimensions[0].struct_size is " + std::to_string(stride) +
                                                   "; expected at least " + std::to_string(kDimensionSize) +
                                                   " (sizeof(stipple_dimension_desc))");
    const unsigned char* base = reinterpret_cast<const unsigned char*>(desc.dimensions);
    std::vector<Dimension> dimensions;
    dimensions.reserve(desc.dimension_count);
    for (uint32_t d = 0; d < desc.dimension_count; ++d) {
        const unsigned char* bytes = base + size_t(d) * stride;
        stipple_dimension_desc entry;
        std::memcpy(&entry, bytes, kDimensionSize);
        if (entry.struct_size != stride)
            throw Error(STIPPLE_ERROR_STRUCT_SIZE, "desc->dimensions[" + std::to_string(d) + "].struct_size is " +
                                                       std::to_string(entry.struct_size) + "; expected " +
                                                       std::to_string(stride) + " like desc->dimensions[0]");
        requireZeroTail(bytes, kDimensionSize, stride, "desc->dimensions[" + std::to_string(d) + "]");
        dimensions.push_back(makeDimension(entry, d, *pattern, desc.samples_per_pixel));
    }
    return new Sampler(desc.pattern, desc.samples_per_pixel, desc.seed, std::move(dimensions), desc.flags);
}

} // namespace stipple::detail
