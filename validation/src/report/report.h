// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The report folder: results.csv / results.json, gnuplot log-log plots per scene, index.html with the
// tables, plots, crops, checks and the matrix text. Needs no renderer: crops are PNGs already written
// into <dir>/crops by whoever rendered them.
#pragma once

#include <string>
#include <vector>

#include "base/file_names.h"
#include "matrix/matrix.h"
#include "report/report_inputs.h"
#include "run/results.h"

namespace stipple::validation {

// Writes results.csv, results.json, plots/ and index.html into dir (created). Returns false (and says why
// on stderr) when gnuplot is missing or fails; the rest of the report is written anyway.
bool writeReport(const std::string& dir, const ReportInputs& in);

// The table printed at the end of a run: RMS and seconds per scene × pattern at the given spp.
std::string summaryTable(const Matrix& matrix, const std::vector<CellAggregate>& cells, uint32_t spp);

} // namespace stipple::validation
