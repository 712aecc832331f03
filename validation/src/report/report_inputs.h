// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// What the report is made of: the matrix, the run's results and aggregates, the claims' outcomes, the baseline.
// Every part of the page (report.h, verdicts_report.h, study_answers.h, perceptual/study_report.h) reads it.
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

} // namespace stipple::validation
