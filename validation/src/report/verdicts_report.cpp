// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "report/verdicts_report.h"
#include "base/file_names.h"
#include "base/text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "claims/efficiency.h"
#include "perceptual/study_report.h"
#include "claims/comparison_claims.h"
#include "claims/efficiency_claims.h"
#include "metrics/equivalence.h"
#include "metrics/image_metrics.h"
#include "metrics/regions.h"
#include "metrics/statistics.h"
#include "report/study_answers.h"

namespace stipple::validation {

namespace fs = std::filesystem;

namespace {



// The 1-, 5- and 15-minute load averages as the kernel reports them (empty where there is no /proc).
std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    double a = 0, b = 0, c = 0;
    if (!(in >> a >> b >> c)) return "";
    return fmt("%.2f, %.2f, %.2f", a, b, c);
}

// Whole image first, then each region of the scene.
std::vector<EfficiencyRanking> rankingsOf(const ReportInputs& in, const MatrixScene& s, uint32_t spp) {
    const auto& rows = in.results->rows;
    const auto& patterns = in.matrix->patterns;
    std::vector<EfficiencyRanking> out;
    out.push_back(rankEfficiency(rows, s.name, spp, patterns, floorFromRows(rows, s.name)));
    for (size_t ri = 0; ri < s.regions.size(); ++ri) {
        EfficiencyRanking r =
            rankEfficiency(rows, s.name, spp, patterns, floorFromRows(rows, s.name, int(ri)), true,
                           [ri](const ResultRow& row) { return ri < row.regionMse.size() ? row.regionMse[ri] : NAN; });
        r.region = s.regions[ri].name;
        out.push_back(r);
    }
    return out;
}

// Mean FLIP ± 95% and the geometric mean of the error spectrum's high/low ratio over the seeds of a cell;
// region < 0: the whole image.
struct Perceptual {
    Interval flip;
    double spectrum = NAN;
};
Perceptual perceptualOf(const std::vector<ResultRow>& rows, const std::string& scene, const std::string& pattern,
                        uint32_t spp, int region) {
    std::vector<double> flip, logSpectrum;
    for (const auto& r : rows) {
        if (r.scene != scene || r.pattern != pattern || r.spp != spp) continue;
        const size_t i = size_t(region);
        const double f = region < 0 ? r.flip : i < r.regionFlip.size() ? r.regionFlip[i] : NAN;
        const double q = region < 0                         ? r.spectrumRatio
                         : i < r.regionSpectrumRatio.size() ? r.regionSpectrumRatio[i]
                                                            : NAN;
        if (std::isfinite(f)) flip.push_back(f);
        if (std::isfinite(q) && q > 0) logSpectrum.push_back(std::log(q));
    }
    Perceptual p;
    p.flip = meanInterval(flip);
    if (!logSpectrum.empty()) p.spectrum = std::exp(mean(logSpectrum));
    return p;
}

} // namespace

std::string patternColor(const std::string& pattern) {
    // Okabe–Ito: distinguishable with the common colour-vision deficiencies; the plots use the same.
    static const std::pair<const char*, const char*> colors[] = {
        {"independent", "#E69F00"},  {"stratified", "#0072B2"}, {"poisson", "#009E73"},
        {"poisson-seed", "#CC79A7"}, {"sobol", "#D55E00"},      {"pmj02", "#56B4E9"},
        {"sobol+blue-noise", "#000000"}, {"stratified+blue-noise", "#999933"}, // black; Tol's olive
        {"lattice", "#44AA99"},          {"halton", "#882255"}};                // Tol's teal and wine
    for (const auto& [name, color] : colors)
        if (pattern == name) return color;
    // A pattern the table does not name (a new one of the library's list) still gets a colour of its own, never
    // black: one of Tol's muted colours not above, chosen by its name (FNV-1a), the same on every page and plot.
    static const char* const more[] = {"#332288", "#88CCEE", "#117733", "#DDCC77", "#CC6677", "#AA4499", "#DDDDDD"};
    uint32_t h = 2166136261u;
    for (unsigned char c : pattern) h = (h ^ c) * 16777619u;
    return more[h % (sizeof more / sizeof more[0])];
}

std::string patternHeader(const std::string& pattern) {
    return "<span class=\"sw\" style=\"background:" + patternColor(pattern) + "\"></span>" + html(pattern);
}

namespace {

// "0.83× (0.78–0.89) BETTER", oriented A / B; `flipped` shows B / A instead (interval and direction swapped).
std::string comparisonCell(const Comparison& c, CheckStatus status, bool flipped) {
    if (c.verdict == Verdict::Unmeasured) return "<td>–</td>";
    double r = c.ratio, lo = c.lo95, hi = c.hi95;
    Verdict v = c.verdict;
    if (flipped) {
        r = 1 / c.ratio;
        lo = 1 / c.hi95;
        hi = 1 / c.lo95;
        v = v == Verdict::Better ? Verdict::Worse : v == Verdict::Worse ? Verdict::Better : v;
    }
    const char* study = status == CheckStatus::Pass ? "holds" : status == CheckStatus::Fail ? "refuted" : "undecided";
    const char* cls = status == CheckStatus::Pass ? "PASS" : status == CheckStatus::Fail ? "FAIL" : "NOT";
    return fmt("<td class=\"v\">%.3g× <small>(%.3g–%.3g)</small><br><strong>%s</strong> <span class=\"%s\">%s</span>"
               "</td>",
               r, lo, hi, verdictName(v), cls, study);
}

struct StudyColumn {
    bool equalTime, flip;
    const char* title;
};
constexpr StudyColumn kStudyColumns[] = {{false, false, "per sample: error ratio"},
                                         {true, false, "equal CPU time: error·s ratio"},
                                         {false, true, "perceptual: mean FLIP ratio"}};

// The study-tagged verdict of a column for (scene, region, {p, q}), and whether it is oriented q / p.
const VerdictRow* studyVerdict(const std::vector<CheckOutcome>& outcomes, const StudyColumn& col,
                               const std::string& scene, const std::string& region, const std::string& p,
                               const std::string& q, bool& flipped, std::string& statement) {
    for (const auto& o : outcomes) {
        if (o.check.study.empty()) continue;
        for (const auto& v : o.verdicts) {
            if (v.equalTime != col.equalTime || v.flip != col.flip || v.scene != scene || v.region != region) continue;
            if ((v.a == p && v.b == q) || (v.a == q && v.b == p)) {
                flipped = v.a == q;
                statement = o.check.study;
                return &v;
            }
        }
    }
    return nullptr;
}

// The perceptual column of the first screen's table for (scene, region, A = p, B = q): the study-tagged FLIP verdict
// where a check asks for one (with holds / refuted), else the mean-FLIP comparison measured from the rows (per
// sample, no statement to judge). One function, so a perceptual measure can be added in one place.
std::string perceptualStudyCell(const ReportInputs& in, const MatrixScene& scene, int region, const std::string& p,
                                const std::string& q, const VerdictRow* tagged, bool flipped) {
    if (tagged) return comparisonCell(tagged->comparison, tagged->status, flipped);
    const Comparison c = comparePatterns(in.results->rows, scene, p, q, in.matrix->spp.back(), region, true, false);
    if (c.verdict == Verdict::Unmeasured) return "<td>–</td>";
    return fmt("<td class=\"v\">%.3g× <small>(%.3g–%.3g)</small><br><strong>%s</strong> <small>measured, no "
               "statement</small></td>",
               c.ratio, c.lo95, c.hi95, verdictName(c.verdict));
}

// The first screen's table: per study statement's pair, scene and region, the three measurements.
std::string studyTableHtml(const ReportInputs& in) {
    const Matrix& m = *in.matrix;
    // The pairs the study's statements name, oriented as first written (e.g. poisson-seed / stratified).
    std::vector<std::pair<std::string, std::string>> pairs;
    std::vector<std::string> statements[3];
    for (const auto& o : in.outcomes) {
        // A study-tagged check that compared one pair (its verdict rows share it, and their basis and metric).
        if (o.check.study.empty() || o.verdicts.empty()) continue;
        const VerdictRow& first = o.verdicts.front();
        if (std::any_of(o.verdicts.begin(), o.verdicts.end(),
                        [&](const VerdictRow& v) { return v.a != first.a || v.b != first.b; }))
            continue;
        bool known = false;
        for (const auto& [p, q] : pairs)
            known |= (p == first.a && q == first.b) || (p == first.b && q == first.a);
        if (!known) pairs.emplace_back(first.a, first.b);
        for (int c = 0; c < 3; ++c)
            if (kStudyColumns[c].equalTime == first.equalTime && kStudyColumns[c].flip == first.flip &&
                std::find(statements[c].begin(), statements[c].end(), o.check.study) == statements[c].end())
                statements[c].push_back(o.check.study);
    }
    if (pairs.empty()) return "";
    std::ostringstream o;
    o << "<h2 id=\"study\">The study's statements, measured at " << m.spp.back() << " spp</h2>\n<div class=\"wide\"><table class=\"study\"><tr><th>scene, region</th><th>pair A / B</th>";
    for (int c = 0; c < 3; ++c) {
        o << "<th>" << kStudyColumns[c].title;
        for (const auto& st : statements[c]) o << "<br><small><em>study: " << html(st) << "</em></small>";
        o << "</th>";
    }
    o << "</tr>\n";
    for (const auto& s : m.scenes)
        for (int ri = -1; ri < int(s.regions.size()); ++ri) {
            const std::string region = ri < 0 ? "" : s.regions[size_t(ri)].name;
            for (const auto& [p, q] : pairs) {
                std::string cells;
                bool any = false;
                for (const auto& col : kStudyColumns) {
                    bool flipped = false;
                    std::string statement;
                    const VerdictRow* v = studyVerdict(in.outcomes, col, s.name, region, p, q, flipped, statement);
                    any |= v != nullptr;
                    if (col.flip) cells += withPeopleVerdict(perceptualStudyCell(in, s, ri, p, q, v, flipped), in, s.name, region, p, q);
                    else cells += v ? comparisonCell(v->comparison, v->status, flipped) : "<td>–</td>";
                }
                if (!any) continue;
                o << "<tr><td><a href=\"#scene-" << safeName(s.name) << "\">" << html(s.name) << "</a>, "
                  << html(region.empty() ? "whole image" : region) << "</td><td>" << patternHeader(p) << " / "
                  << patternHeader(q) << "</td>" << cells << "</tr>\n";
            }
        }
    o << "</table></div>\n<p class=\"note\">Ratio of A's error to B's (below 1: A better), 95% interval; error: "
         "the verdicts' relative squared error, weighted by the reference's noise (<a href=\"#deciding\">how</a>; "
         "the checks' figures give the study's plain MSE beside it, labelled, without a verdict), or mean FLIP; "
         "<strong>EQUIVALENT</strong>: the 90% interval lies inside the margin (two one-sided tests at 5%), "
         "<strong>BETTER</strong> / <strong>WORSE</strong>: the 95% interval excludes 1, else <strong>NOT "
         "SEPARATED</strong>. <em>holds / refuted / undecided</em>: the study's statement of the column against that "
         "verdict. Intervals from the seeds and the image's "
      << kErrorBlockSize << "-pixel blocks (see the README, <em>Deciding</em>).</p>\n";
    return o.str();
}

// The best pattern of a scene (whole image) per sample or at equal time, and its margin over the runner-up.
std::string bestPatternText(const ReportInputs& in, const MatrixScene& s, bool equalTime) {
    const auto& rows = in.results->rows;
    const uint32_t spp = in.matrix->spp.back();
    const double floor = errorFloor(rows, s.name, -1, false, true);
    std::vector<std::pair<double, std::string>> ranked;
    for (const auto& p : in.matrix->patterns) {
        const ErrorEstimate e = patternError(rows, s, p, spp, -1, false, floor);
        if (!e.valid()) continue;
        double logCost = 0;
        size_t n = 0;
        for (const auto& r : rows)
            if (r.scene == s.name && r.pattern == p && r.spp == spp && r.cpuSeconds > 0) {
                logCost += std::log(r.cpuSeconds);
                ++n;
            }
        ranked.emplace_back(std::log(e.mean) + (equalTime && n ? logCost / double(n) : 0.0), p);
    }
    if (ranked.size() < 2) return "–";
    std::sort(ranked.begin(), ranked.end());
    const Comparison c = comparePatterns(rows, s, ranked[0].second, ranked[1].second, spp, -1, false, equalTime);
    return patternHeader(ranked[0].second) +
           fmt(" <small>%.3g× %s's error%s (95%% %.3g–%.3g)</small> <strong>%s</strong>", c.ratio,
               ranked[1].second.c_str(), equalTime ? "·time" : "", c.lo95, c.hi95, verdictName(c.verdict));
}

} // namespace

std::string verdictHeadlineHtml(const ReportInputs& in) {
    std::ostringstream o;
    const ClaimCounts n = countClaims(in.outcomes);
    o << "<div class=\"headline\"><p class=\"counts\"><strong><span id=\"claims-total\">" << n.total
      << "</span> claims: <span class=\"PASS\" id=\"claims-pass\">" << n.pass << "</span> PASS, <span class=\"FAIL\" "
      << "id=\"claims-fail\">" << n.fail << "</span> failed (they fail the run), <span id=\"claims-refuted\">"
      << n.refuted << "</span> study statements refuted, <span id=\"claims-reported\">" << n.reported
      << "</span> findings reported, <span class=\"NOT\" id=\"claims-not-separated\">" << n.notSeparated
      << "</span> NOT SEPARATED.</strong></p></div>\n";
    o << studyAnswersHtml(in);
    return o.str();
}

std::string studyDetailsHtml(const ReportInputs& in) {
    const Matrix& m = *in.matrix;
    std::ostringstream o;
    size_t verdicts = 0, undecided = 0;
    for (const auto& c : in.outcomes)
        for (const auto& v : c.verdicts) {
            ++verdicts;
            undecided += v.comparison.verdict == Verdict::NotSeparated || v.comparison.verdict == Verdict::Unmeasured;
        }
    o << "<p class=\"note\">" << verdicts << " comparisons, " << undecided << " not separated. Matrix " << html(m.name)
      << ": " << m.scenes.size() << " scenes × " << m.patterns.size() << " patterns × " << m.spp.size() << " spp × "
      << m.seeds.size() << " seeds. Machine: " << std::thread::hardware_concurrency()
      << " hardware threads; load average (1, 5, 15 min) when the report was written: " << html(loadAverage())
      << ".<span id=\"figure3\"> The study's Figure 3 (generation time against N), made by <code>ci/main.sh</code> "
         "after this report: <a href=\"figure3/figure3.png\" data-made-after=\"1\">figure3/figure3.png</a>, <a "
         "href=\"figure3/summary.md\" data-made-after=\"1\">its tables</a>.<img src=\"figure3/figure3.png\" "
         "alt=\"Figure 3\" data-made-after=\"1\" hidden onerror=\"document.getElementById('figure3').remove()\"></span></p>\n";
    o << studyTableHtml(in) << perceptualStudyHtml(in);
    o << "<h2 id=\"best\">Best pattern per scene at " << m.spp.back()
      << " spp (whole image)</h2>\n<div class=\"wide\"><table><tr><th>scene</th><th>per sample (least "
         "error)</th><th>at "
         "equal CPU time (least error·s)</th></tr>\n";
    for (const auto& s : m.scenes)
        o << "<tr><td><a href=\"#scene-" << safeName(s.name) << "\">" << html(s.name) << "</a></td><td>"
          << bestPatternText(in, s, false) << "</td><td>" << bestPatternText(in, s, true) << "</td></tr>\n";
    o << "</table></div>\n<p class=\"note\">The margin is the best pattern's error over the runner-up's, with its "
         "verdict (EQUIVALENT: the two are within the margin of each other).</p>\n";
    return o.str();
}

std::string sceneVerdictsHtml(const ReportInputs& in, const MatrixScene& s) {
    const Matrix& m = *in.matrix;
    const uint32_t spp = m.spp.back();
    std::ostringstream o;
    o << "<h3>Equal-time efficiency and perceptual error at " << spp
      << " spp</h3>\n<p class=\"note\">Efficiency "
         "1/(MSE<sub>corrected</sub> · CPU s) per seed, geometric mean over seeds relative to the row's most efficient "
         "pattern, Welch's 95% interval. <em>floor</em>: reference noise floor / the cell's corrected MSE (⚑ above "
      << fmt("%.0f", 100 * kFloorShareLimit) << "%). <em>heavy</em>: worst seed's RMS ≥ "
      << fmt("%.0f", kHeavyTailFactor)
      << "× its best seed's, with the trimmed mean RMS (lowest and highest seed dropped). FLIP: mean LDR-FLIP ± 95% "
         "(67 pixels per degree); spectrum: "
         "error power at 0.25–0.5 over below 0.125 cycles per pixel (1 white, above 1 blue).</p>\n"
         "<div class=\"wide\"><table><tr><th>region</th><th>measure</th>";
    for (const auto& p : m.patterns) o << "<th>" << patternHeader(p) << "</th>";
    o << "</tr>\n";
    const auto rankings = rankingsOf(in, s, spp);
    for (size_t ri = 0; ri < rankings.size(); ++ri) {
        const auto& r = rankings[ri];
        const std::string region = r.region.empty() ? "whole image" : r.region;
        o << "<tr><td rowspan=\"2\">" << html(region) << "</td><td>efficiency</td>";
        for (const auto& p : m.patterns) {
            const PatternEfficiency* e = nullptr;
            for (const auto& x : r.ranked)
                if (x.pattern == p) e = &x;
            if (!e) {
                o << "<td>–</td>";
                continue;
            }
            double lo = 1, hi = 1;
            const double ratio = e == &r.ranked[0] ? 1.0 : r.ratioOf(p, r.ranked[0].pattern, &lo, &hi);
            o << "<td>"
              << (e == &r.ranked[0] ? "<strong>best</strong>"
                                    : fmt("%.3g<br><small>(%.3g–%.3g)</small>", ratio, lo, hi))
              << fmt("<br><small>floor %.1f%%%s</small>", 100 * e->floorShare,
                     e->floorShare > kFloorShareLimit ? " ⚑" : "")
              << (e->rms.heavyTailed
                      ? fmt("<br><small>heavy ×%.1f, trimmed RMS %.3g</small>", e->rms.maxOverMin, e->rms.trimmedMean)
                      : "")
              << "</td>";
        }
        o << "</tr>\n<tr><td>FLIP, spectrum</td>";
        for (const auto& p : m.patterns) {
            const Perceptual q = perceptualOf(in.results->rows, s.name, p, spp, int(ri) - 1);
            o << "<td>" << fmt("%.4f<br><small>± %.2g; %.2f</small>", q.flip.mean, q.flip.halfWidth, q.spectrum)
              << "</td>";
        }
        o << "</tr>\n";
    }
    o << "</table></div>\n";

    const uint32_t cropSpp = m.crop.spp ? m.crop.spp : m.spp.back();
    for (const auto& rg : s.regions) {
        o << "<h3>Region " << html(rg.name) << fmt(" (x %.2f–%.2f, y %.2f–%.2f)", rg.x0, rg.x1, rg.y0, rg.y1) << " at "
          << cropSpp << " spp, seed " << m.seeds.front() << "</h3>\n";
        const std::string scaleFile = regionErrorMapFile(s.name, rg.name, "scale") + ".txt";
        double scale = NAN;
        if (std::ifstream f(in.reportDir + "/" + scaleFile); f) f >> scale;
        o << "<p class=\"note\">Each crop magnified with nearest neighbour (click: the PNG at its own size, pixel "
             "for pixel); beside it the error per pixel, sqrt(Σ<sub>rgb</sub>(I<sub>ref</sub> − I)²), in false colour "
             "on one scale for all patterns: <img src=\""
          << kErrorBarFile << "\" alt=\"error colour scale, dark blue 0 to yellow\" style=\"width:128px;height:10px\"> 0 to "
          << fmt("%.3g", scale) << " (the largest pattern's 99th percentile).</p>\n<div class=\"maps\">";
        std::vector<std::string> columns = {"reference"};
        columns.insert(columns.end(), m.patterns.begin(), m.patterns.end());
        for (const auto& c : columns) {
            const std::string crop = regionCropFile(s.name, rg.name, c), map = regionErrorMapFile(s.name, rg.name, c);
            const std::string exr = cellExrFile(s.name, c, cropSpp, m.seeds.front());
            o << "<figure><a href=\"" << crop << "\"><img class=\"crop\" src=\"" << crop << "\" alt=\""
              << html(s.name + " " + rg.name + ", " + c) << "\"></a>";
            if (c != "reference")
                o << "<a href=\"" << map << "\"><img class=\"crop\" src=\"" << map << "\" alt=\""
                  << html("error map of " + c + ", " + rg.name) << "\"></a>";
            o << "<figcaption>" << (c == "reference" ? std::string("reference") : patternHeader(c));
            if (c != "reference" && fs::exists(fs::path(in.reportDir) / exr))
                o << " · <a href=\"" << exr << "\">EXR</a>";
            o << "</figcaption></figure>";
        }
        o << "</div>\n";
    }
    return o.str();
}

std::string verdictsText(const ReportInputs& in) {
    const Matrix& m = *in.matrix;
    const uint32_t spp = m.spp.back();
    std::string s =
        fmt("equal-time efficiency at %u spp (1/(MSE·CPU s), relative to the best of the row, 95%%):\n", spp);
    for (const auto& scene : m.scenes)
        for (const auto& r : rankingsOf(in, scene, spp)) {
            s += fmt("  %-13s %-16s", scene.name.c_str(), r.region.empty() ? "whole image" : r.region.c_str());
            for (const auto& e : r.ranked) {
                double lo = 1, hi = 1;
                const double ratio = &e == &r.ranked[0] ? 1.0 : r.ratioOf(e.pattern, r.ranked[0].pattern, &lo, &hi);
                s += fmt("  %s %.3g (%.3g-%.3g)%s%s", e.pattern.c_str(), ratio, lo, hi,
                         e.floorShare > kFloorShareLimit ? fmt(" [floor %.0f%%]", 100 * e.floorShare).c_str() : "",
                         e.rms.heavyTailed ? " [heavy]" : "");
            }
            s += "\n";
        }
    s += fmt("perceptual error at %u spp (mean LDR-FLIP ± 95%%; error spectrum high/low: 1 white, > 1 blue):\n", spp);
    for (const auto& scene : m.scenes)
        for (int ri = -1; ri < int(scene.regions.size()); ++ri) {
            s += fmt("  %-13s %-16s", scene.name.c_str(),
                     ri < 0 ? "whole image" : scene.regions[size_t(ri)].name.c_str());
            for (const auto& p : m.patterns) {
                const Perceptual q = perceptualOf(in.results->rows, scene.name, p, spp, ri);
                s += fmt("  %s %.4f ± %.2g [%.2f]", p.c_str(), q.flip.mean, q.flip.halfWidth, q.spectrum);
            }
            s += "\n";
        }
    return s;
}

} // namespace stipple::validation
