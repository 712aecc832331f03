// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// --merge: the results of shard folders (stipple-validate --shard i/n) combined into the results a single run
// makes, checked for completeness: every cell × seed of the matrix exactly once, one renderer version.
#pragma once

#include <string>
#include <vector>

#include "matrix/matrix.h"
#include "run/results.h"

namespace stipple::validation {

// Reads <dir>/results.json of each folder, copies their crops/ into <out>/crops, and returns the rows in the
// matrix's order. Throws std::runtime_error naming the folder on a duplicate row, a renderer version that
// differs, or rows of the matrix found in no folder (scenes a shard skipped excepted: they stay reported).
Results mergeShards(const Matrix& matrix, const std::vector<std::string>& dirs, const std::string& out);

} // namespace stipple::validation
