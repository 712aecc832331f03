// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pattern_registry.cpp — the patterns in public id order: the one place a STIPPLE_PATTERN_* id meets its pattern.
#include "pattern_registry.h"

#include <cstring>
#include <iterator>

namespace stipple::detail {

// Each defined in its pattern's source file.
extern const PatternOps kIndependentPattern;
extern const PatternOps kStratifiedPattern;
extern const PatternOps kPoissonPattern;
extern const PatternOps kPoissonSeedPattern;
extern const PatternOps kSobolPattern;
extern const PatternOps kPmj02Pattern;
extern const PatternOps kLatticePattern;
extern const PatternOps kHaltonPattern;
#if defined(STIPPLE_TEST_SCRATCH_PATTERN)
extern const PatternOps kScratchPattern; // the scratch build's only (shim/tests/scratch_pattern.cpp)
#endif

namespace {

// Position = public id.
constexpr const PatternOps* kPatterns[] = {
    &kIndependentPattern, // STIPPLE_PATTERN_INDEPENDENT
    &kStratifiedPattern,  // STIPPLE_PATTERN_STRATIFIED
    &kPoissonPattern,     // STIPPLE_PATTERN_POISSON
    &kPoissonSeedPattern, // STIPPLE_PATTERN_POISSON_SEED
    &kSobolPattern,       // STIPPLE_PATTERN_SOBOL
    &kPmj02Pattern,       // STIPPLE_PATTERN_PMJ02
    &kLatticePattern,     // STIPPLE_PATTERN_LATTICE
    &kHaltonPattern,      // STIPPLE_PATTERN_HALTON
#if defined(STIPPLE_TEST_SCRATCH_PATTERN)
    &kScratchPattern, // past the public ids: the scratch build's check that the tests take a new pattern
#endif
};
#if defined(STIPPLE_TEST_SCRATCH_PATTERN)
static_assert(std::size(kPatterns) == STIPPLE_PATTERN_COUNT + 1, "the public ids in order, then the scratch pattern");
#else
static_assert(std::size(kPatterns) == STIPPLE_PATTERN_COUNT, "one entry per public pattern id, in id order");
#endif

std::string listOf(const std::string* items, size_t count) {
    std::string list;
    for (size_t i = 0; i < count; ++i) list += (i == 0 ? "" : i + 1 == count ? " or " : ", ") + items[i];
    return list;
}

} // namespace

const PatternOps* findPattern(uint32_t id) { return id < std::size(kPatterns) ? kPatterns[id] : nullptr; }

bool findPatternId(const char* name, uint32_t* id) {
    for (uint32_t p = 0; p < std::size(kPatterns); ++p)
        if (std::strcmp(name, kPatterns[p]->name) == 0) {
            *id = p;
            return true;
        }
    return false;
}

uint32_t patternCount() { return static_cast<uint32_t>(std::size(kPatterns)); }

std::string patternIdList() {
    std::string items[std::size(kPatterns)];
    for (uint32_t p = 0; p < std::size(kPatterns); ++p) items[p] = std::to_string(p) + " (" + kPatterns[p]->name + ")";
    return listOf(items, std::size(items));
}

std::string patternNameList() {
    std::string items[std::size(kPatterns)];
    for (uint32_t p = 0; p < std::size(kPatterns); ++p) items[p] = std::string("\"") + kPatterns[p]->name + "\"";
    return listOf(items, std::size(items));
}

std::string blueNoisePatternList() {
    std::string items[std::size(kPatterns)];
    size_t count = 0;
    for (const PatternOps* p : kPatterns)
        if (p->blueNoise != BlueNoiseMode::Unsupported) items[count++] = std::string("\"") + p->name + "\"";
    return count == 0 ? std::string("no pattern") : listOf(items, count);
}

std::string arityList(uint32_t maxArity) {
    std::string items[3];
    for (uint32_t a = 1; a <= maxArity && a <= 3; ++a) items[a - 1] = std::to_string(a);
    return listOf(items, maxArity < 3 ? maxArity : 3);
}

} // namespace stipple::detail
