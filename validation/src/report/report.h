// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The report folder: results.csv / results.json, gnuplot log-log plots per scene, index.html with the
// tables, plots, crops, checks and the matrix text. Needs no renderer: crops are PNGs already written
// into <dir>/crops by whoever rendered them.
#pragma once

#include <string>
#include <vector>

#include "claims/baseline.h"
#include "claims/checks.h"
#include "matrix/matrix.h"
#include "run/results.h"

namespace stipple::validation {

struct ReportInputs {
    const Matrix* matrix = nullptr;
    const Results* results = nullptr; // rows sorted (sortRows)
    std::vector<CellAggregate> cells;
    std::vector<SlopeFit> slopes;
    std::vector<CheckOutcome> outcomes;
    const BaselineComparison* baseline = nullptr; // null: no --baseline
    std::string baselinePath;
    double wallSeconds = 0; // of the whole run (0 when merged)
    std::string note;       // e.g. "merged from 2 shard folders"
    std::string reportDir;  // the folder being written (set by writeReport): files the page links are checked there
    std::string studyDir;   // --study: a perceptual experiment folder whose votes/ fill the perceptual block
};

// File-name-safe form of a scene or pattern name.
std::string safeName(const std::string& name);
// Crop PNG path relative to the report folder.
std::string cropFile(const std::string& scene, const std::string& pattern);
// One seed's render of a cell as EXR (for outside viewers), relative to the report folder.
std::string cellExrFile(const std::string& scene, const std::string& pattern, uint32_t spp, uint64_t seed);
// The colour bar of the error maps, relative to the report folder.
inline const char* kErrorBarFile = "crops/error-scale.png";

// Writes results.csv, results.json, plots/ and index.html into dir (created). Returns false (and says why
// on stderr) when gnuplot is missing or fails; the rest of the report is written anyway.
bool writeReport(const std::string& dir, const ReportInputs& in);

// The table printed at the end of a run: RMS and seconds per scene × pattern at the given spp.
std::string summaryTable(const Matrix& matrix, const std::vector<CellAggregate>& cells, uint32_t spp);

} // namespace stipple::validation
