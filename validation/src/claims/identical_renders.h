// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Two seeds of one cell that rendered the same image: the renderer ignored {seed}, or mapped both seeds to one
// value (a host that keeps 32 bits of it, say). Every interval would then be built from copies of one render and
// every verdict would be confident and wrong, so a run that finds them is an error naming the seeds.
#pragma once

#include <string>
#include <vector>

#include "run/results.h"

namespace stipple::validation {

// One line per (scene, pattern, spp) whose seeds rendered bitwise-equal images, naming the seeds that did; empty
// when every seed differs. Equal images give equal per-block squared errors (block_sse): with hundreds of blocks,
// equal lists that are not all zero mean equal images.
std::vector<std::string> identicalSeedRenders(const std::vector<ResultRow>& rows);

} // namespace stipple::validation
