// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Thurstone Case V scaling of pairwise comparisons by maximum likelihood, in JOD units (just-objectionable
// differences: two conditions 1 JOD apart are told apart by 75% of observers, as in pwcmp): P(i preferred to j)
// = Φ((q_i − q_j) / σ) with σ = 1 / Φ⁻¹(0.75). A weak Gaussian prior on the centred scores (sd kPriorJod) keeps
// unanimous pairs finite; with a few observers per pair it moves scores by a few percent at most.
#pragma once

#include <vector>

namespace stipple::validation {

inline constexpr double kPriorJod = 5.0;

// wins[i][j]: how often i was preferred to j (ties counted half each way). Returns the scores, q[0] = 0, higher
// is better. Concave in q: Newton's method with step halving converges from 0.
std::vector<double> thurstoneScores(const std::vector<std::vector<double>>& wins);

} // namespace stipple::validation
