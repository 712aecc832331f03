// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// sampler_arrays.cpp — array streams: k values per sample of one array, one set of k * N points per block.
//
// An array is served exactly as a declared dimension of count k (sample i's values are points i * k .. i * k + k - 1
// of block i / N), from set state made on first use of its (arity, k). Its sets are keyed like a stream's, with a
// tag no call-order stream has (stream tags are the arity, 1..3): array a is never stream a, and each (arity, k)
// is an index space of its own.
#include "sampler.h"

#include <algorithm>

namespace stipple::detail {

namespace {
// The SetRef stream word of array (arity, k): bit 15 marks arrays; k <= 1024 fits in bits 2..12.
constexpr uint32_t kArrayTag = 1u << 15;
constexpr uint32_t arrayTag(uint32_t arity, uint32_t k) { return kArrayTag | (k << 2) | arity; }
static_assert(STIPPLE_MAX_VALUES_PER_SAMPLE << 2 < kArrayTag, "array tags must stay below the array bit");
} // namespace

const Dimension& Sampler::arraySet(uint32_t arity, uint32_t k) const {
    return arraySets_.get(arity, k, [&] { return makePatternDimension(ops_, arity, k, k * samplesPerPixel_); });
}

void Sampler::array(uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex, uint32_t index, uint32_t arity,
                    uint32_t k, float* out) const {
    const Dimension& dim = arraySet(arity, k);
    const uint32_t block = sampleIndex < samplesPerPixel_ ? 0 : sampleIndex / samplesPerPixel_;
    const uint32_t position = sampleIndex - block * samplesPerPixel_;
    const SetRef set{pixelX, pixelY, index, arrayTag(arity, k), block};
    if (k == 1) return point(set, dim, position, out);
    fill(set, dim, position * k, k, out);
}

void Sampler::arrayFill(uint32_t pixelX, uint32_t pixelY, uint32_t firstSample, uint32_t count, uint32_t index,
                        uint32_t arity, uint32_t k, float* out) const {
    const Dimension& dim = arraySet(arity, k);
    uint64_t i = firstSample;
    const uint64_t end = uint64_t(firstSample) + count;
    while (i < end) { // one fill per block touched
        const uint32_t block = static_cast<uint32_t>(i / samplesPerPixel_);
        const uint32_t position = static_cast<uint32_t>(i - uint64_t(block) * samplesPerPixel_);
        const uint32_t run = static_cast<uint32_t>(std::min<uint64_t>(end - i, samplesPerPixel_ - position));
        fill(SetRef{pixelX, pixelY, index, arrayTag(arity, k), block}, dim, position * k, run * k, out);
        out += size_t(run) * k * arity;
        i += run;
    }
}

} // namespace stipple::detail
