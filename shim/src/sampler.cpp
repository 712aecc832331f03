// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// sampler.cpp — from a (pixel, dimension, sample) request to its set, its block and its pattern's functions.
#include "sampler.h"

#include "blue_noise.h"
#include "hash.h"

#include <algorithm>
#include <bit>
#include <utility>

namespace stipple::detail {

namespace {
// The word folded into a key for a stream's arity (0: the declared layout, whose keys are ABI 1.0's).
constexpr uint64_t kStreamWord = 0x57e4a3c0ffee0000ull;

constexpr uint64_t streamWord(uint64_t key, uint32_t streamArity) {
    return streamArity == 0 ? key : hashCombine(key, kStreamWord | streamArity);
}

constexpr HashDomain tileDomain(HashDomain pattern) {
    return static_cast<HashDomain>(static_cast<uint64_t>(pattern) ^ static_cast<uint64_t>(HashDomain::BlueNoiseTile));
}

// The key of a blue-noise tile and its lattice map, memoised per thread. Hosts ask for the pixels of a tile row one
// after another (64 per tile row), each dimension in turn; without the memo the key's chain of 64-bit mixes and the
// map's hash lie on the path of every call, longer than the pixel's own key. A pure function of the fields
// compared, so a stale entry is never used.
struct TileKeyMemo {
    const PatternOps* ops = nullptr; // its block keying and lattice use
    uint64_t tileSeedKey = 0;
    uint32_t tileX = 0, tileY = 0, d = 0, streamArity = 0, block = 0, arity = 0;
    uint64_t key = 0;
    LatticeTile lattice;
};
constexpr uint32_t kTileKeyMemoEntries = 8; // picked by dimension and stream arity
thread_local TileKeyMemo tileKeyMemo[kTileKeyMemoEntries];

Dimension plainDimension(uint32_t arity, uint32_t count, uint32_t points) {
    Dimension dim;
    dim.arity = arity;
    dim.count = count;
    dim.setSize = points;
    dim.log2Length = static_cast<uint32_t>(std::bit_width(points - 1));
    return dim;
}
} // namespace

Dimension makePatternDimension(const PatternOps& ops, uint32_t arity, uint32_t count, uint32_t points) {
    Dimension dim = plainDimension(arity, count, points);
    if (ops.prepare) ops.prepare(dim);
    return dim;
}

Sampler::Sampler(uint32_t pattern, uint32_t samplesPerPixel, uint64_t seed, std::vector<Dimension> dimensions,
                 uint32_t flags)
    : pattern_(pattern), ops_(*findPattern(pattern)), fill_(ops_.fill[static_cast<uint32_t>(batchIsa())]),
      fillStrata_(ops_.fillStrata[static_cast<uint32_t>(batchIsa())]), samplesPerPixel_(samplesPerPixel), seed_(seed),
      seedKey_(seedKey(seed, ops_.domain)), dimensions_(std::move(dimensions)), flags_(flags),
      tileSeedKey_(seedKey(seed, tileDomain(ops_.domain))) {
    for (uint32_t a = 1; a <= 3; ++a) {
        streams_[a - 1] = plainDimension(a, 1, samplesPerPixel);
        if (ops_.prepare && !ops_.prepareStreamsOnFirstUse) ops_.prepare(streams_[a - 1]);
    }
}

uint64_t Sampler::pixelKey(const SetRef& set) const {
    return streamWord(setKeyFrom(seedKey_, set.pixelX, set.pixelY, set.d), set.streamArity);
}

const Dimension& Sampler::streamDimension(uint32_t arity) const {
    const Dimension& s = streams_[arity - 1];
    if (ops_.prepareStreamsOnFirstUse && ops_.prepare)
        std::call_once(streamFamilyOnce_[arity - 1], [&] { ops_.prepare(const_cast<Dimension&>(s)); });
    return s;
}

// The pixel's key is made here, where the SetRef is in registers: read back from the stack by the blue-noise
// path, its two 32-bit pixel fields loaded as one 64-bit word missed store forwarding (~10 ns per call).
void Sampler::fill(const SetRef& set, const Dimension& dim, uint32_t first, uint32_t count, float* out) const {
    const SetKey key = keyBlock(ops_, pixelKey(set), set.block);
    if (blueNoise()) [[unlikely]]
        return fillBlueNoise(set, key, dim, first, count, out);
    fill_(key, dim, first, count, out);
}

void Sampler::point(const SetRef& set, const Dimension& dim, uint32_t p, float* out) const {
    const SetKey key = keyBlock(ops_, pixelKey(set), set.block);
    if (blueNoise()) [[unlikely]]
        return fillBlueNoise(set, key, dim, p, 1, out);
    ops_.point(key, dim, p, out);
}

// Every variant keys the tile-shared part of a set from (seed, pattern ^ tile domain, tile, d[, stream arity][, block])
// and the per-pixel part from the plain set key, so blocks and streams are blue noise on their own and every
// sample stays uniform.
void Sampler::fillBlueNoise(const SetRef& set, const SetKey& pixel, const Dimension& dim, uint32_t first,
                            uint32_t count, float* out) const {
    const uint32_t tileX = set.pixelX >> kBlueNoiseTileLog2, tileY = set.pixelY >> kBlueNoiseTileLog2;
    TileKeyMemo& memo = tileKeyMemo[(set.d + set.streamArity) % kTileKeyMemoEntries];
    if (memo.ops != &ops_ || memo.tileSeedKey != tileSeedKey_ || memo.tileX != tileX || memo.tileY != tileY ||
        memo.d != set.d || memo.streamArity != set.streamArity || memo.block != set.block || memo.arity != dim.arity)
        [[unlikely]] {
        const uint64_t key =
            keyBlock(ops_, streamWord(setKeyFrom(tileSeedKey_, tileX, tileY, set.d), set.streamArity), set.block).key;
        memo = {&ops_, tileSeedKey_, tileX, tileY, set.d, set.streamArity, set.block, dim.arity, key, {}};
        memo.lattice = LatticeTile(key, dim.arity);
    }
    switch (ops_.blueNoise) {
    case BlueNoiseMode::CrossPixelStrata: {
        const CrossPixelStrata strata(memo.key, memo.lattice, set.pixelX, set.pixelY);
        return fillStrata_(pixel, dim, first, count, out, strata);
    }
    case BlueNoiseMode::Unsupported: break; // refused at creation (sampler_create.cpp)
    }
}

void Sampler::fillPixel(uint32_t pixelX, uint32_t pixelY, uint32_t d, float* out) const {
    const Dimension& dim = dimensions_[d];
    fill(SetRef{pixelX, pixelY, d, 0, 0}, dim, 0, dim.setSize, out);
}

void Sampler::sample(uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex, uint32_t d, float* out) const {
    const Dimension& dim = dimensions_[d];
    const uint32_t block =
        sampleIndex < samplesPerPixel_ ? 0 : sampleIndex / samplesPerPixel_; // no division in block 0
    const uint32_t position = sampleIndex - block * samplesPerPixel_;
    const SetRef set{pixelX, pixelY, d, 0, block};
    if (dim.count == 1) return point(set, dim, position, out);
    fill(set, dim, position * dim.count, dim.count, out); // one generation for poisson-seed, not k
}

void Sampler::stream(uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex, uint32_t d, uint32_t arity,
                     float* out) const {
    const uint32_t block = sampleIndex < samplesPerPixel_ ? 0 : sampleIndex / samplesPerPixel_;
    const uint32_t position = sampleIndex - block * samplesPerPixel_;
    point(SetRef{pixelX, pixelY, d, arity, block}, streamDimension(arity), position, out);
}

void Sampler::streamFill(uint32_t pixelX, uint32_t pixelY, uint32_t firstSample, uint32_t count, uint32_t d,
                         uint32_t arity, float* out) const {
    const Dimension& dim = streamDimension(arity);
    uint64_t i = firstSample;
    const uint64_t end = uint64_t(firstSample) + count;
    while (i < end) { // one fill per block touched
        const uint32_t block = static_cast<uint32_t>(i / samplesPerPixel_);
        const uint32_t position = static_cast<uint32_t>(i - uint64_t(block) * samplesPerPixel_);
        const uint32_t run = static_cast<uint32_t>(std::min<uint64_t>(end - i, samplesPerPixel_ - position));
        fill(SetRef{pixelX, pixelY, d, arity, block}, dim, position, run, out);
        out += size_t(run) * arity;
        i += run;
    }
}

void Sampler::sampleIndependent(uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex, uint32_t stream, float* out,
                                size_t count) const {
    const uint64_t k = hashCombine(setKey(seed_, HashDomain::PastLayout, pixelX, pixelY, stream), sampleIndex);
    for (size_t i = 0; i < count; ++i) out[i] = unitFloat(hashAt(k, i));
}

} // namespace stipple::detail
