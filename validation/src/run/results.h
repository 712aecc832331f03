// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// What a run measured: one row per cell × seed, per-scene facts (load, BVH build, reference), and the
// per-cell aggregates over seeds. Written as results.csv / results.json; results.json reads back for
// --merge and --baseline.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <stipple/render/input_limits.h>

#include "base/fields.h"
#include "matrix/matrix.h"
#include "run/shard_fingerprint.h"
#include "metrics/statistics.h"

namespace stipple::validation {

struct ResultRow {
    std::string scene, pattern;
    uint32_t spp = 0;
    uint64_t seed = 0;
    int width = 0, height = 0;
    double mse = 0, rms = 0;                   // against the reference, as measured
    double mseCorrected = 0, rmsCorrected = 0; // reference noise floor removed: max(mse − floor, 0)
    bool floorLimited = false;                 // mseCorrected ≤ 2 × floor
    uint64_t nonFinitePixels = 0;              // excluded from the error
    uint64_t nonFiniteSamples = 0;             // reported by the renderer's film
    double renderSeconds = 0, samplerSeconds = 0;
    double cpuSeconds = 0;                             // thread CPU seconds of the render loop, summed over its workers
    std::vector<double> regionMse, regionMseCorrected; // per region of the scene (matrix order), as mse above
    double flip = NAN;                                 // mean LDR-FLIP (67 pixels per degree) against the reference
    double spectrumRatio = NAN;                        // error power high / low frequency: 1 white, > 1 blue
    std::vector<double> regionFlip, regionSpectrumRatio; // per region, as above
    // Per block of kErrorBlockSize pixels (image_metrics.h), row-major: Σ squared error and Σ FLIP, of the whole image
    // and of each region (its own blocks from its top left, the regions' lists one after the other).
    std::vector<double> blockSse, blockFlip, regionBlockSse, regionBlockFlip;
    // As blockSse / regionBlockSse, of the capped relative squared error (blockRelativeSquaredErrors, image_metrics.h).
    std::vector<double> blockRse, regionBlockRse;
    double rseFloor = 0;                // the reference's noise in the same units (relativeNoiseFloor), per pixel
    std::vector<double> regionRseFloor; // per region
};

struct SceneInfo {
    std::string name, file, contentHash, integrator;
    int width = 0, height = 0;
    uint64_t triangles = 0;
    double loadSeconds = 0, buildSeconds = 0; // reported apart from the cells' render seconds
    double warmupSeconds = 0;                 // untimed warm-up renders (one small render per pattern × spp)
    std::string referenceKey;                 // cache key of the reference
    uint32_t referenceSpp = 0;
    double referenceSeconds = 0; // 0 when it came from the cache
    double noiseFloor = 0;       // E[MSE contribution of the reference's noise]
};

// A scene a run could not load or render: its matrix name and the error, file:line first.
struct SkippedScene {
    std::string name, error;
    bool operator==(const SkippedScene&) const = default;
};

struct Results {
    std::string matrixName, rendererVersion;
    std::vector<SceneInfo> scenes;
    std::vector<ResultRow> rows;
    std::vector<SkippedScene> skipped; // scenes that could not be loaded or rendered: the run goes on without them
    Fingerprint fingerprint;           // what makes these rows comparable with another run's (--merge checks it)
};

// Over the K seeds of one (scene, pattern, spp).
struct CellAggregate {
    std::string scene, pattern;
    uint32_t spp = 0;
    Interval rms;                 // of rmsCorrected, t interval, 95%
    SampleSummary logRms;         // of log(rmsCorrected) over the seeds where it is > 0
    SampleSummary logRmsMeasured; // of log(rms), before the floor correction, over the seeds where it is > 0
    double meanRmsMeasured = 0;   // before the floor correction
    double meanMse = 0, meanMseCorrected = 0;
    double medianRenderSeconds = 0, medianSamplerSeconds = 0, medianCpuSeconds = 0;
    double efficiency = 0; // 1 / (mean corrected MSE · median render seconds)
    int floorLimitedSeeds = 0;
    uint64_t nonFinitePixels = 0;
    size_t seeds = 0;
    size_t unmeasuredSeeds = 0; // seeds whose error is not a finite number (a merged or hand-made row): no verdict
};

// Fitted log RMS vs log spp over per-seed points of one (scene, pattern).
struct SlopeFit {
    std::string scene, pattern;
    LineFit fit;
    size_t excluded = 0; // points with corrected RMS 0 (no logarithm)
};

// Rows in the matrix's canonical order (scene, pattern, spp, seed as listed); unknown names last.
void sortRows(std::vector<ResultRow>& rows, const Matrix& matrix);
std::vector<CellAggregate> aggregate(const std::vector<ResultRow>& sortedRows);
std::vector<SlopeFit> fitSlopes(const std::vector<ResultRow>& rows, const Matrix& matrix);
const CellAggregate* findCell(const std::vector<CellAggregate>& cells, const std::string& scene,
                              const std::string& pattern, uint32_t spp);

// The field lists behind results.json and the CSV files (one per record type).
const Fields<ResultRow>& resultRowFields();
const Fields<SceneInfo>& sceneInfoFields();
const Fields<SkippedScene>& skippedSceneFields();
const Fields<CellAggregate>& cellFields();
const Fields<SlopeFit>& slopeFields();

void writeResultsCsv(const std::string& path, const std::vector<ResultRow>& rows);
// The per-cell aggregates: mean RMS with its 95% half width, medians, efficiency.
void writeCellsCsv(const std::string& path, const std::vector<CellAggregate>& cells);
// Writes everything: rows, scenes, aggregates, slopes; `checks` (a JSON array) goes under "checks".
void writeResultsJson(const std::string& path, const Results& results, const std::vector<CellAggregate>& cells,
                      const std::vector<SlopeFit>& slopes, const Json& checks);
// The largest results.json a run of `matrix` writes, which is what --merge and --baseline read back of one: its
// rows (scenes × patterns × spp × seeds) with their per-block lists (blocks of the image and its regions at the
// matrix's size, else at the largest image a render may have) and a fixed allowance for the rest; at most
// kMaxResultsFileBytes. A file beyond it is not this matrix's and is refused before it is parsed.
inline constexpr uint64_t kMaxResultsFileBytes = 1ull << 30;
uint64_t resultsFileByteLimit(const Matrix& matrix);

// Reads the rows and scenes back (files of format "stipple-validate results 1"), refusing a file over `maxBytes`
// (resultsFileByteLimit of the matrix it is read for; the default is the limit of any other YAML or JSON input).
// Throws std::runtime_error naming the file (and line:column, or the record and field, or the limit) on bad input.
Results readResultsJson(const std::string& path, uint64_t maxBytes = render::limits::kMaxYamlFileBytes);

// Writes `text` to `path` through a temporary file (render::TempPath) renamed into place.
void writeTextFile(const std::string& path, const std::string& text);

} // namespace stipple::validation
