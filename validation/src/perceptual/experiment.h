// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The experiment folder a run writes from its renders when the matrix has a 'perceptual' section:
// <report>/perceptual-study/ with index.html (study_page.html and its plan), crops/<id>.png (each set's region at
// 1:1, first seed, tone-mapped as the report's PNGs: through $OCIO when set) under ids that do not reveal the
// pattern, and key.json (ids to patterns, with each crop's mean FLIP and RMS from the run).
#pragma once

#include <string>

#include "matrix/matrix.h"
#include "run/results.h"

namespace stipple::validation {

inline constexpr const char* kStudyFolder = "perceptual-study";

// Needs the cells' EXRs in <reportDir>/exr (a run writes them; --merge does not copy them). Returns false and
// says why on stderr when a render is missing; throws on a write error.
bool writeStudyExperiment(const std::string& reportDir, const Matrix& matrix, const Results& results);

} // namespace stipple::validation
