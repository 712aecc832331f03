// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "claims/checks.h"
#include "matrix/check_kind.h"
#include "claims/comparison_claims.h" // verdictsJson
#include "base/text.h"

namespace stipple::validation {

const char* checkStatusName(CheckStatus status) {
    switch (status) {
    case CheckStatus::Pass: return "PASS";
    case CheckStatus::Fail: return "FAIL";
    case CheckStatus::NotSeparated: return "NOT SEPARATED";
    }
    return "?";
}

CheckOutcome evaluateCheck(const Check& k, const CheckInputs& in) {
    CheckOutcome o;
    o.check = k;
    k.kind->evaluate(k, in, o);
    o.failsRun = (o.status == CheckStatus::Fail && k.failFails) ||
                 (o.status == CheckStatus::NotSeparated && k.notSeparatedFails);
    return o;
}

std::vector<CheckOutcome> evaluateChecks(const Matrix& matrix, const std::vector<ResultRow>& rows,
                                         const std::vector<CellAggregate>& cells, const std::vector<SlopeFit>& slopes) {
    const CheckInputs inputs{matrix, rows, cells, slopes};
    std::vector<CheckOutcome> out;
    for (const auto& k : matrix.checks) out.push_back(evaluateCheck(k, inputs));
    return out;
}

std::string formatOutcome(const CheckOutcome& o) {
    std::string s = fmt("%-13s %s   [%s]", checkStatusName(o.status), o.claim.c_str(), o.check.where.c_str());
    if (o.status != CheckStatus::Pass && !o.failsRun) s += " (does not fail the run)";
    if (o.status == CheckStatus::NotSeparated && o.failsRun) s += " (fails the run)";
    s += "\n";
    for (const auto& f : o.figures) s += "      " + f + "\n";
    return s;
}

const Fields<CheckOutcome>& outcomeFields() {
    using O = CheckOutcome;
    auto text = [](const char* name, std::string (*get)(const O&)) {
        Field<O> f;
        f.name = name;
        f.toJson = [get](const O& o) { return Json(get(o)); };
        f.toCsv = [get](const O& o) { return csvField(get(o)); };
        return f;
    };
    static const Fields<O> fields = {
        text("type", [](const O& o) { return std::string(o.check.kind->name); }),
        text("where", [](const O& o) { return o.check.where; }),
        text("status", [](const O& o) { return std::string(checkStatusName(o.status)); }),
        field("fails_run", &O::failsRun),
        text("study", [](const O& o) { return o.check.study; }),
        field("claim", &O::claim),
        {"figures",
         [](const O& o) { return Json(o.figures); },
         {},
         [](const O& o) {
             std::string all;
             for (const auto& f : o.figures) all += (all.empty() ? "" : "; ") + f;
             return csvField(all);
         }},
        {"verdicts", [](const O& o) { return verdictsJson(o.verdicts); }, {}, {}},
    };
    return fields;
}

Json outcomesJson(const std::vector<CheckOutcome>& outcomes) {
    Json a = Json::array();
    for (const auto& o : outcomes) a.push_back(toJson(o, outcomeFields()));
    return a;
}

} // namespace stipple::validation
