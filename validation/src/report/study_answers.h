// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The report's first screen in sentences: for each statement of the study (the checks tagged `study:`), what
// the run measured, scene by scene, and whether the statement holds; then stratified against independent, the
// comparison the library itself stands on. A reader who stops there has the answer; the tables below give the
// intervals and the regions.
#pragma once

#include <string>

#include "claims/checks.h"
#include "report/report_inputs.h"

namespace stipple::validation {

// The claim counts as the terminal gives them: FAIL is what fails the run; a study statement the data refutes
// (fails_run: false) is counted as refuted, a library finding that did not hold and does not fail the run as
// reported. The counts add up to the number of claims.
struct ClaimCounts {
    size_t total = 0, pass = 0, fail = 0, refuted = 0, reported = 0, notSeparated = 0;
};
ClaimCounts countClaims(const std::vector<CheckOutcome>& outcomes);

// The sentences (<p class="answer"> each, inside <div id="answers">) and a one-line legend of the error they
// use. Empty when the matrix tags no statement and lacks stratified or independent.
std::string studyAnswersHtml(const ReportInputs& in);

} // namespace stipple::validation
