// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Evaluates the matrix's claims against a run's results: PASS, FAIL or NOT SEPARATED, with the figures.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "metrics/equivalence.h"
#include "matrix/matrix.h"
#include "run/results.h"

namespace stipple::validation {

enum class CheckStatus { Pass, Fail, NotSeparated };
const char* checkStatusName(CheckStatus status); // "PASS", "FAIL", "NOT SEPARATED"
// Worst status wins: FAIL > NOT SEPARATED > PASS.
inline void worsen(CheckStatus& s, CheckStatus t) {
    if (t == CheckStatus::Fail || (t == CheckStatus::NotSeparated && s == CheckStatus::Pass)) s = t;
}

// One comparison of a compare check: pattern A's error over pattern B's in one scene and region.
struct VerdictRow {
    std::string scene, region; // region empty: the whole image
    std::string a, b;
    uint32_t spp = 0;
    bool equalTime = false, flip = false;
    Comparison comparison;
    CheckStatus status = CheckStatus::Pass; // against the check's expectation
    // The verdict that decided status, for the report's words, where it is not comparison.verdict: a gain inside
    // the margin but separated from 1 is BETTER (WORSE) to a check that expects better (worse).
    std::optional<Verdict> decidedAs;
};

struct CheckOutcome {
    Check check;
    CheckStatus status = CheckStatus::Pass;
    bool failsRun = false;            // FAIL, or NOT SEPARATED when the check says not_separated: fail
    std::string claim;                // one line: what was claimed
    std::vector<std::string> figures; // one line per cell / scene measured, marked when it is the culprit
    std::vector<VerdictRow> verdicts; // compare checks: one per scene × region × pair
};

// What a check is evaluated on.
struct CheckInputs {
    const Matrix& matrix;
    const std::vector<ResultRow>& rows;
    const std::vector<CellAggregate>& cells; // per scene × pattern × spp
    const std::vector<SlopeFit>& slopes;     // per scene × pattern
};

// One check by its kind (matrix/check_kind.h): the outcome, and whether it fails the run.
CheckOutcome evaluateCheck(const Check& check, const CheckInputs& inputs);
std::vector<CheckOutcome> evaluateChecks(const Matrix& matrix, const std::vector<ResultRow>& rows,
                                         const std::vector<CellAggregate>& cells, const std::vector<SlopeFit>& slopes);

// "PASS  ordering cornell-box spp ≥ 64: stratified < independent" followed by indented figures.
std::string formatOutcome(const CheckOutcome& outcome);
// The fields of an outcome in results.json's "checks" (written only).
const Fields<CheckOutcome>& outcomeFields();
Json outcomesJson(const std::vector<CheckOutcome>& outcomes);

} // namespace stipple::validation
