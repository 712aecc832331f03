// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pattern_registry.h — what a pattern is to the sampler: one PatternOps per STIPPLE_PATTERN_* id.
//
// A pattern is defined once, in its own source file, as a PatternOps (its name, hash domain, block keying,
// blue-noise mode, limits, set preparation, per-point and batch functions, the batch function compiled per ISA);
// pattern_registry.cpp lists them in public id order. Nothing else in the library names a pattern id: the
// sampler, the creation checks and the ABI read the table.
//
// ISA: the batch functions come in one variant per BatchIsa (batch_isa.h). The ISA is detected once, when the
// library loads; a sampler takes its pattern's variant for it when it is created, so a batch call is one indirect
// call with no ISA test (forceBatchIsa, for tests and benchmarks, applies to samplers created after it).
#pragma once

#include "batch_isa.h"
#include "blue_noise.h"
#include "dimension.h"
#include "hash.h"

#include <stipple/stipple.h>

#include <array>
#include <cstdint>
#include <string>

namespace stipple::detail {

// The key a pattern's functions get for one block of one set (the sampler's set key: seed, pattern domain,
// pixel or blue-noise tile, dimension, stream arity), after the pattern's block keying.
struct SetKey {
    uint64_t key;
    uint32_t block; // sample indices [block * N, (block + 1) * N)
};

// How block b (sample indices past N: b = i / N > 0) gets a set of its own.
enum class BlockKeying : uint32_t {
    Rekeyed,    // key = hashCombine(set key, kBlockWord | b) for b > 0; block 0 keeps the set key (ABI 1.0's)
    EveryBlock, // key = hashCombine(set key, b) for every block, block 0 included
    Sequence,   // key = the set key; the pattern continues its own sequence at block b (SetKey::block)
};

// What STIPPLE_SAMPLER_FLAG_BLUE_NOISE does with the pattern (blue_noise.h).
enum class BlueNoiseMode : uint32_t {
    // The pixels of a tile stratify each stratum among themselves: fillStrata, with a lattice map of blue_noise.h.
    CrossPixelStrata,
    // The flag is refused at sampler creation (STIPPLE_ERROR_INVALID_ARGUMENT naming the pattern and the flag):
    // no mechanism here keeps the pattern's low-frequency error at or below its plain level on every integrand of
    // the battery. (A per-pixel toroidal shift of a tile-shared set, measured with shim_blue_noise_gain, added
    // low-frequency error on ramps, edges and the off-centre Gaussian and up to 500 times the per-pixel MSE of
    // sobol and pmj02.)
    Unsupported,
};

struct PatternLimits {
    uint32_t maxArity = 3;                      // arities 1..maxArity (the ABI's limit is 3)
    uint32_t maxSetSize = STIPPLE_MAX_SET_SIZE; // k * N of a declared dimension, and N itself (streams serve N)
};

using PatternFill = void (*)(const SetKey& set, const Dimension& dim, uint32_t first, uint32_t count, float* out);
using PatternPoint = void (*)(const SetKey& set, const Dimension& dim, uint32_t p, float* out);
using PatternStrataFill = void (*)(const SetKey& set, const Dimension& dim, uint32_t first, uint32_t count, float* out,
                                   const CrossPixelStrata& strata);

// A pattern's entry lists its name, domain, block keying, point and fill; the rest have defaults (a pattern without
// blue noise, limits, precomputed state or strata to report).
struct PatternOps {
    const char* name; // stipple_pattern_name's
    HashDomain domain;
    BlockKeying blockKeying;
    BlueNoiseMode blueNoise = BlueNoiseMode::Unsupported;
    // Unsupported only: why, for the refusal's message (sampler_create.cpp) after "which the <name> pattern does
    // not support: ".
    const char* blueNoiseRefusal = "a per-pixel shift of a tile-shared set adds low-frequency error on non-periodic "
                                   "integrands (edges, ramps) and breaks the set's stratification";
    PatternLimits limits = {};
    // The pattern's precomputed state of a set (Dimension's arity, count, setSize and log2Length are set):
    // nullptr when it has none. Streams are prepared when the sampler is created, or on their first use when
    // prepareStreamsOnFirstUse (state that counts against a cache budget).
    void (*prepare)(Dimension& dim) = nullptr;
    bool prepareStreamsOnFirstUse = false;
    // stipple_dimension_info's strata per axis; nullptr: the pattern reports none (zeros).
    void (*strata)(const Dimension& dim, uint32_t* axes) = nullptr;
    // Point p of the block alone, bitwise equal to fill's point p.
    PatternPoint point;
    // Points [first, first + count) of the block, one variant per BatchIsa (the same bits in each).
    // (batch_kernel.h's kernelFills makes this row from one kernel.)
    std::array<PatternFill, kBatchIsaCount> fill;
    std::array<PatternStrataFill, kBatchIsaCount> fillStrata = {}; // CrossPixelStrata only, per BatchIsa like fill
};

// The key of block `block` of a set keyed `key` (BlockKeying).
inline SetKey keyBlock(const PatternOps& ops, uint64_t key, uint32_t block) {
    constexpr uint64_t kBlockWord = 0xb10c000000000000ull;
    switch (ops.blockKeying) {
    case BlockKeying::Rekeyed: return {block == 0 ? key : hashCombine(key, kBlockWord | block), block};
    case BlockKeying::EveryBlock: return {hashCombine(key, block), block};
    case BlockKeying::Sequence: break;
    }
    return {key, block};
}

// The pattern of public id `id` (STIPPLE_PATTERN_*), or nullptr past the table.
const PatternOps* findPattern(uint32_t id);
// The id of the pattern named `name`; false if none is.
bool findPatternId(const char* name, uint32_t* id);
uint32_t patternCount();
// For messages: "0 (independent), 1 (stratified), ... or 5 (pmj02)" and "\"independent\", ... or \"pmj02\"".
std::string patternIdList();
std::string patternNameList();
// For messages: the names of the patterns that support STIPPLE_SAMPLER_FLAG_BLUE_NOISE ("\"stratified\"").
std::string blueNoisePatternList();
// For messages: "1, 2 or 3" for maxArity 3.
std::string arityList(uint32_t maxArity);

} // namespace stipple::detail
