// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The report's verdicts: a headline (claims PASS / FAIL / NOT SEPARATED, the machine and its load, the study's
// question answered per scene in one sentence), the equal-time efficiency table per scene × region × pattern
// with intervals, the reference's noise floor as a share of each cell's MSE, heavy-tailed cells marked with
// their trimmed mean, and per-region crop grids.
#pragma once

#include <string>

#include "report/report_inputs.h"

namespace stipple::validation {

// The first screen: claim counts as the terminal gives them (with ids the browser test reads) and the study's
// answers in sentences (study_answers.h).
std::string verdictHeadlineHtml(const ReportInputs& in);
// Below it: the study's statements per scene and region in a table, the best pattern per scene, the run's
// matrix and machine, and Figure 3 where ci/main.sh made it.
std::string studyDetailsHtml(const ReportInputs& in);
// A scene's equal-time / perceptual table (whole image and regions) and its region crop grids.
std::string sceneVerdictsHtml(const ReportInputs& in, const MatrixScene& scene);
// The colour of a pattern in plots and tables (Okabe–Ito, safe for colour-blind readers).
std::string patternColor(const std::string& pattern);
// A table header: colour swatch and name.
std::string patternHeader(const std::string& pattern);
// The same verdict table as plain text (stdout at the end of a run).
std::string verdictsText(const ReportInputs& in);

} // namespace stipple::validation
