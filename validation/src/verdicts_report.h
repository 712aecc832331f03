// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The report's verdicts: a headline (claims PASS / FAIL / NOT SEPARATED, the machine and its load, the study's
// question answered per scene in one sentence), the equal-time efficiency table per scene × region × pattern
// with intervals, the reference's noise floor as a share of each cell's MSE, heavy-tailed cells marked with
// their trimmed mean, and per-region crop grids.
#pragma once

#include <string>

#include "report.h"

namespace stipple::validation {

// The headline: claim counts (with ids the browser test reads), the machine, one sentence per scene.
std::string verdictHeadlineHtml(const ReportInputs& in);
// A scene's equal-time / perceptual table (whole image and regions) and its region crop grids.
std::string sceneVerdictsHtml(const ReportInputs& in, const MatrixScene& scene);
// The colour of a pattern in plots and tables (Okabe–Ito, safe for colour-blind readers).
std::string patternColor(const std::string& pattern);
// A table header: colour swatch and name.
std::string patternHeader(const std::string& pattern);
// The same verdict table as plain text (stdout at the end of a run).
std::string verdictsText(const ReportInputs& in);

} // namespace stipple::validation
