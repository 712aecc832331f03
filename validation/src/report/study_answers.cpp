// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "report/study_answers.h"
#include "base/text.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "matrix/check_kind.h"
#include "claims/comparison_claims.h"
#include "report/verdicts_report.h"

namespace stipple::validation {

ClaimCounts countClaims(const std::vector<CheckOutcome>& outcomes) {
    ClaimCounts n;
    for (const auto& o : outcomes) {
        ++n.total;
        if (o.failsRun)
            ++n.fail;
        else if (o.status == CheckStatus::Pass)
            ++n.pass;
        else if (o.status == CheckStatus::NotSeparated)
            ++n.notSeparated;
        else if (!o.check.study.empty())
            ++n.refuted;
        else
            ++n.reported;
    }
    return n;
}

namespace {

// What a reader knows the pattern as: the study's Poisson disk and the library's are told apart by name.
std::string patternLabel(const std::string& p) {
    if (p == "poisson-seed") return "the study's Poisson disk (" + patternHeader(p) + ")";
    if (p == "poisson") return "stipple's Poisson disk (" + patternHeader(p) + ")";
    return patternHeader(p);
}

// A verdict as a comparison of A with B, in words; `b` empty: B was named in the clause already.
std::string verdictWords(Verdict v, const std::string& b) {
    const bool named = !b.empty();
    switch (v) {
    case Verdict::Equivalent: return named ? "as good as " + b : "as good";
    case Verdict::Better: return named ? "better than " + b : "better";
    case Verdict::Worse: return named ? "worse than " + b : "worse";
    case Verdict::NotSeparated: return named ? "not separated from " + b : "not separated";
    case Verdict::Unmeasured: return named ? "not measured against " + b : "not measured";
    }
    return "?";
}

// "0.93×" or "0.93–1.04×" over the ratios given.
std::string ratioRange(std::vector<double> r) {
    std::sort(r.begin(), r.end());
    if (r.empty()) return "";
    if (r.front() == r.back() || fmt("%.2g", r.front()) == fmt("%.2g", r.back())) return fmt("%.2g×", r.front());
    return fmt("%.2g–%.2g×", r.front(), r.back());
}

// Where a verdict was measured: the scene, and its region when it is not the whole image.
std::string placeOf(const VerdictRow& v) { return html(v.scene) + (v.region.empty() ? "" : ", " + html(v.region)); }

// "worse than stratified in 4 of 4 scenes (7.2–17×)" or "… in veach-mis (1.3×)", one group per verdict word (the
// one that decided the row against its check's expectation), then whether the statement holds.
std::string verdictSummary(const std::vector<const VerdictRow*>& vs, const std::string& b, bool tagged) {
    const std::vector<Verdict> order = {Verdict::Equivalent, Verdict::Better, Verdict::Worse, Verdict::NotSeparated,
                                        Verdict::Unmeasured};
    std::string s;
    const bool regions = std::any_of(vs.begin(), vs.end(), [](const VerdictRow* v) { return !v->region.empty(); });
    const char* unit = regions ? "places" : "scenes";
    for (Verdict word : order) {
        std::vector<double> ratios;
        std::vector<std::string> places;
        for (const VerdictRow* v : vs)
            if (v->decidedAs.value_or(v->comparison.verdict) == word) {
                ratios.push_back(v->comparison.ratio);
                places.push_back(placeOf(*v));
            }
        if (ratios.empty()) continue;
        s += (s.empty() ? "" : "; ") + verdictWords(word, s.empty() ? patternLabel(b) : "");
        if (ratios.size() == vs.size() && vs.size() > 1)
            s += fmt(" in %zu of %zu %s", vs.size(), vs.size(), unit);
        else if (ratios.size() > 2)
            s += fmt(" in %zu of %zu %s", ratios.size(), vs.size(), unit);
        else {
            s += " in ";
            for (size_t i = 0; i < places.size(); ++i) s += (i ? " and " : "") + places[i];
        }
        s += " (" + ratioRange(ratios) + ")";
    }
    if (!tagged) return s;
    size_t holds = 0, refuted = 0, undecided = 0;
    for (const VerdictRow* v : vs)
        (v->status == CheckStatus::Pass ? holds : v->status == CheckStatus::Fail ? refuted : undecided)++;
    if (holds == vs.size()) return s + ": <strong class=\"PASS\">holds</strong>";
    if (refuted == vs.size()) return s + ": <strong class=\"FAIL\">refuted</strong>";
    std::string t;
    if (holds) t += fmt("holds in %zu", holds);
    if (refuted) t += (t.empty() ? "" : ", ") + fmt("refuted in %zu", refuted);
    if (undecided) t += (t.empty() ? "" : ", ") + fmt("undecided in %zu", undecided);
    return s + ": <strong class=\"NOT\">" + t + "</strong>";
}

// "holds", "refuted" or "undecided", marked up.
std::string statusWord(CheckStatus status) {
    const char* word = status == CheckStatus::Pass ? "holds" : status == CheckStatus::Fail ? "refuted" : "undecided";
    const char* cls = status == CheckStatus::Pass ? "PASS" : status == CheckStatus::Fail ? "FAIL" : "NOT";
    return std::string("<strong class=\"") + cls + "\">" + word + "</strong>";
}

// The clauses of a check as its kind states them (check_kind.h), in the report's words.
std::string checkClauses(const CheckOutcome& o) {
    static const SentenceWords words{html, patternHeader, patternLabel, statusWord, verdictSummary};
    if (o.check.kind->sentence) return o.check.kind->sentence(o, words);
    return html(o.claim) + ": " + statusWord(o.status);
}

// Stratified against independent on every scene's whole image, per sample and at equal time, from the rows
// (whether or not a check asks).
std::string stratifiedSentence(const ReportInputs& in) {
    const Matrix& m = *in.matrix;
    auto has = [&](const char* p) { return std::find(m.patterns.begin(), m.patterns.end(), p) != m.patterns.end(); };
    if (!has("stratified") || !has("independent")) return "";
    std::string s;
    for (bool equalTime : {false, true}) {
        std::vector<VerdictRow> rows;
        for (const auto& scene : m.scenes) {
            VerdictRow v;
            v.scene = scene.name;
            v.a = "stratified";
            v.b = "independent";
            v.equalTime = equalTime;
            v.comparison = comparePatterns(in.results->rows, scene, v.a, v.b, m.spp.back(), -1, false, equalTime);
            if (v.comparison.verdict != Verdict::Unmeasured) rows.push_back(v);
        }
        if (rows.empty()) continue;
        std::vector<const VerdictRow*> vs;
        for (const auto& v : rows) vs.push_back(&v);
        s += (s.empty() ? patternHeader("stratified") + " " : "; ") +
             std::string(equalTime ? "at equal CPU time" : "per sample") + " is " +
             verdictSummary(vs, "independent", false);
    }
    return s.empty() ? ""
                     : "<p class=\"answer\"><strong>Stratified against independent</strong> (the library's own "
                       "footing): " +
                           s + ".</p>\n";
}

} // namespace

std::string studyAnswersHtml(const ReportInputs& in) {
    const Matrix& m = *in.matrix;
    // The statements in the order the matrix first names them, each with its checks.
    std::vector<std::string> statements;
    std::map<std::string, std::vector<const CheckOutcome*>> checksOf;
    for (const auto& o : in.outcomes) {
        if (o.check.study.empty()) continue;
        if (!checksOf.count(o.check.study)) statements.push_back(o.check.study);
        checksOf[o.check.study].push_back(&o);
    }
    std::ostringstream o;
    for (const auto& st : statements) {
        std::string clauses;
        for (const CheckOutcome* c : checksOf[st])
            if (const std::string t = checkClauses(*c); !t.empty()) clauses += (clauses.empty() ? "" : ". ") + t;
        o << "<p class=\"answer\"><strong>Study: “" << html(st) << "”.</strong> " << clauses << ".</p>\n";
    }
    const std::string stratified = stratifiedSentence(in);
    if (statements.empty() && stratified.empty()) return "";
    return "<div class=\"answers\" id=\"answers\"><h2>Answers at " + std::to_string(m.spp.back()) + " spp</h2>\n" +
           o.str() + stratified +
           "<p class=\"note\">Ratios: A's error over B's over the scenes' whole images (regions where a statement "
           "names one), 1 = equal; the error is the verdicts' own, the relative squared error weighted by the "
           "reference's noise (<a href=\"#deciding\">how it is measured</a>), or mean FLIP where it says so. "
           "“As good as”: inside the margin 0.8–1.25 with 90% confidence; better / worse: the 95% interval "
           "excludes 1.</p></div>\n";
}

} // namespace stipple::validation
