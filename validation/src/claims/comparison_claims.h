// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Pattern A against pattern B per scene and region, per sample (equal spp) or per cost (equal CPU seconds), on MSE
// or mean FLIP, judged with equivalence.h: EQUIVALENT (inside the margin), BETTER, WORSE or NOT SEPARATED, then
// against what a compare check (compare_check.cpp) expects (PASS / FAIL / NOT SEPARATED).
#pragma once

#include <string>
#include <vector>

#include "claims/checks.h"
#include "metrics/equivalence.h"
#include "run/results.h"

namespace stipple::validation {

// Whether a pattern's pixels are sampled independently of each other. The shim's blue-noise flag shares one set
// across the pixels of a kBlueNoiseTilePixels-square tile (tiles are keyed apart), so its units are tiles.
bool pixelsIndependent(const std::string& pattern);
inline constexpr int kBlueNoiseTilePixels = 64;

// A pattern's error at one spp over its seeds (rows of results.json with block lists): region < 0 the whole image,
// else the scene's region'th region. flip: mean FLIP (no floor); relative: the capped relative squared error
// (blockRelativeSquaredErrors, image_metrics.h), else the MSE; less `floor` in the same units. The weights and the
// cap are the same for every pattern and seed of a scene, so a ratio compares the same quantity, and neither a
// light's edge nor one seed's firefly decides it (validation/README.md: Deciding).
ErrorEstimate patternError(const std::vector<ResultRow>& rows, const MatrixScene& scene, const std::string& pattern,
                           uint32_t spp, int region, bool flip, double floor, bool relative = true);
// The floor patternError subtracts: 0 for FLIP, the reference's noise in relative or MSE units.
double errorFloor(const std::vector<ResultRow>& rows, const std::string& scene, int region, bool flip, bool relative);

// The paired per-seed log ratio of A's CPU seconds to B's at one spp (renders of a seed ran back to back).
LogShift cpuTimeShift(const std::vector<ResultRow>& rows, const std::string& scene, const std::string& a,
                      const std::string& b, uint32_t spp);

// A's error over B's (region < 0: whole image); equal time multiplies by the CPU-time ratio (MSE · s).
Comparison comparePatterns(const std::vector<ResultRow>& rows, const MatrixScene& scene, const std::string& a,
                           const std::string& b, uint32_t spp, int region, bool flip, bool equalTime,
                           const Margin& margin = {}, bool relative = true);

// What a compare check expects of pattern A against pattern B (error ratio A / B).
enum class Expectation { Any, Equivalent, Better, Worse };

CheckStatus statusFor(Expectation expect, const Comparison& c);
// The verdict statusFor decided on, in the report's words: BETTER (WORSE) for a gain inside the margin that is
// separated from 1 where better (worse) is expected, else the comparison's own verdict.
Verdict decidingVerdict(Expectation expect, const Comparison& c);
const char* expectationName(Expectation e);

Json verdictsJson(const std::vector<VerdictRow>& verdicts);

} // namespace stipple::validation
