// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Deciding "better", "worse" and "as good as" between two patterns' errors with few seeds.
//
// A pattern's error in a scene is the mean over K seeds of a per-pixel error summed over the image (squared error
// or FLIP). Where the pixels are sampled independently (every pattern without the blue-noise flag: each pixel's
// set is seeded by the pixel), disjoint blocks of pixels are independent, so the variance of the image total is the
// sum of the blocks' variances, and each block's variance is estimated from its K seeds. With hundreds of blocks
// this has far more degrees of freedom than the K − 1 of the seeds' totals, and the image's own structure (bright
// and dark blocks) does not enter the variance, as it would if the blocks were treated as a sample. Units that are
// not independent (a blue-noise tile's pixels share one set) are merged into one unit first.
//
// Two patterns are compared on the log of the ratio of their errors (delta method, Welch–Satterthwaite degrees of
// freedom), optionally times the paired per-seed ratio of their CPU seconds (equal-time comparison). The verdict:
// EQUIVALENT when the 90% interval lies inside the margin (two one-sided tests at 5% each, Schuirmann 1987);
// BETTER / WORSE when the 95% interval excludes 1; NOT SEPARATED otherwise. Coverage is checked by simulation with
// heavy-tailed errors in validation/tests/equivalence_test.cpp.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace stipple::validation {

// A pattern's mean error per pixel over its seeds, with the variance of that mean and its degrees of freedom.
struct ErrorEstimate {
    double mean = 0;     // mean over seeds of Σ error / pixels, minus `floor`
    double variance = 0; // variance of `mean`
    double dof = 0;      // Satterthwaite degrees of freedom of `variance`
    size_t seeds = 0, units = 0;
    bool valid() const { return seeds >= 2 && mean > 0 && variance >= 0 && dof > 0; }
};

// perSeed[k][b]: seed k's error summed over block b (all seeds the same block list). unitOf[b]: the independent
// unit block b belongs to (empty: every block its own unit). `pixels`: the pixels the blocks cover; `floor`: per
// pixel error to subtract (the reference's noise floor; 0 for FLIP).
ErrorEstimate estimateFromBlocks(const std::vector<std::vector<double>>& perSeed, const std::vector<int>& unitOf,
                                 double pixels, double floor = 0);

// The equivalence margin on a ratio of errors: [lo, hi], e.g. [0.8, 1.25].
struct Margin {
    double lo = 0.8, hi = 1.25;
};

enum class Verdict { Equivalent, Better, Worse, NotSeparated, Unmeasured };
const char* verdictName(Verdict v); // "EQUIVALENT", "BETTER", "WORSE", "NOT SEPARATED", "UNMEASURED"

// A ratio of A's error to B's (< 1: A has less error) with its intervals and verdict.
struct Comparison {
    double ratio = 0, lo95 = 0, hi95 = 0, lo90 = 0, hi90 = 0;
    double dof = 0;
    bool separated = false;  // the 95% interval excludes 1
    bool equivalent = false; // the 90% interval lies inside the margin
    Verdict verdict = Verdict::Unmeasured;
};

// From the log ratio, its variance and degrees of freedom.
Comparison judgeLogRatio(double logRatio, double variance, double dof, const Margin& margin);

// A paired per-seed log ratio (e.g. of CPU seconds): its mean, the variance of the mean, K − 1 dof.
struct LogShift {
    double mean = 0, variance = 0, dof = 0;
};
LogShift pairedLogRatio(const std::vector<double>& a, const std::vector<double>& b);

// A's error over B's, times exp(shift.mean) (the time ratio at equal time; default: none).
Comparison compareErrors(const ErrorEstimate& a, const ErrorEstimate& b, const Margin& margin,
                         const LogShift& shift = {});

// "0.83× (95% 0.78–0.89)".
std::string ratioText(const Comparison& c);

} // namespace stipple::validation
