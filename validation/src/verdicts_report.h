// The report's verdicts: a headline (claims PASS / FAIL / NOT SEPARATED, the machine and its load, the study's
// question answered per scene in one sentence), the equal-time efficiency table per scene × region × pattern
// with intervals, the reference's noise floor as a share of each cell's MSE, heavy-tailed cells marked with
// their trimmed mean, and per-region crop grids.
#pragma once

#include <string>

#include "report.h"

namespace stipple::validation {

std::string verdictsHtml(const ReportInputs& in);
// The same verdict table as plain text (stdout at the end of a run).
std::string verdictsText(const ReportInputs& in);

} // namespace stipple::validation
