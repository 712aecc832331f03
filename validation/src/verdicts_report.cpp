#include "verdicts_report.h"
#include "text.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

#include "efficiency.h"
#include "efficiency_claims.h"
#include "regions.h"
#include "statistics.h"

namespace stipple::validation {

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

// "stratified is the most efficient at equal time, 1.9× poisson (95% 1.6-2.3)" or "... not separated from ...".
std::string sentence(const EfficiencyRanking& r) {
    if (r.ranked.empty()) return "no cells";
    if (r.ranked.size() == 1) return r.ranked[0].pattern + " alone";
    const auto& st = r.steps[0];
    std::string s = st.separated
                        ? fmt("%s is the most efficient at equal time, %.2f× %s (95%% %.2f-%.2f)",
                              r.ranked[0].pattern.c_str(), st.ratio, r.ranked[1].pattern.c_str(), st.lo, st.hi)
                        : fmt("%s and %s lead, not separated (%.2f×, 95%% %.2f-%.2f)", r.ranked[0].pattern.c_str(),
                              r.ranked[1].pattern.c_str(), st.ratio, st.lo, st.hi);
    double lo = 0, hi = 0;
    const auto& last = r.ranked.back();
    const double worst = r.ratioOf(r.ranked[0].pattern, last.pattern, &lo, &hi);
    if (r.ranked.size() > 2) s += fmt("; %.3g× %s (95%% %.3g-%.3g)", worst, last.pattern.c_str(), lo, hi);
    return s;
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

std::string studyOf(const Matrix& m, const std::string& scene) {
    for (const auto& k : m.checks)
        if (k.type == CheckType::EqualTime && (k.scene == scene || k.scene == "all") && !k.study.empty())
            return k.study;
    return "";
}

} // namespace

std::string patternColor(const std::string& pattern) {
    // Okabe–Ito: distinguishable with the common colour-vision deficiencies; the plots use the same.
    static const std::pair<const char*, const char*> colors[] = {
        {"independent", "#E69F00"},  {"stratified", "#0072B2"}, {"poisson", "#009E73"},
        {"poisson-seed", "#CC79A7"}, {"sobol", "#D55E00"},      {"pmj02", "#56B4E9"}};
    for (const auto& [name, color] : colors)
        if (pattern == name) return color;
    return "#000000";
}

std::string patternHeader(const std::string& pattern) {
    return "<span class=\"sw\" style=\"background:" + patternColor(pattern) + "\"></span>" + html(pattern);
}

std::string verdictHeadlineHtml(const ReportInputs& in) {
    const Matrix& m = *in.matrix;
    const uint32_t spp = m.spp.back();
    std::ostringstream o;
    size_t pass = 0, fail = 0, ns = 0;
    for (const auto& c : in.outcomes)
        (c.status == CheckStatus::Pass ? pass : c.status == CheckStatus::Fail ? fail : ns)++;
    o << "<div class=\"headline\"><p class=\"counts\"><strong><span id=\"claims-total\">" << in.outcomes.size()
      << "</span> claims: <span class=\"PASS\" id=\"claims-pass\">" << pass << "</span> PASS, <span class=\"FAIL\" "
      << "id=\"claims-fail\">" << fail << "</span> FAIL, <span class=\"NOT\" id=\"claims-not-separated\">" << ns
      << "</span> NOT SEPARATED.</strong></p>\n<p>Matrix " << html(m.name) << ": " << m.scenes.size() << " scenes × "
      << m.patterns.size() << " patterns × " << m.spp.size() << " spp × " << m.seeds.size()
      << " seeds. Machine: " << std::thread::hardware_concurrency()
      << " hardware threads; load average (1, 5, 15 min) when the report was "
      << "written: " << html(loadAverage()) << ".</p>\n<p>At equal render time (CPU seconds), " << spp
      << " spp:</p><ul>\n";
    for (const auto& s : m.scenes) {
        const auto rankings = rankingsOf(in, s, spp);
        o << "<li><a href=\"#scene-" << safeName(s.name) << "\"><strong>" << html(s.name)
          << "</strong></a>: " << html(sentence(rankings[0])) << ".";
        const std::string study = studyOf(m, s.name);
        if (!study.empty()) o << " <em>Study: " << html(study) << ".</em>";
        for (size_t i = 1; i < rankings.size(); ++i)
            o << " Region " << html(rankings[i].region) << ": " << html(sentence(rankings[i])) << ".";
        o << "</li>\n";
    }
    o << "</ul></div>\n";
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
         "<table><tr><th>region</th><th>measure</th>";
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
    o << "</table>\n";

    const uint32_t cropSpp = m.crop.spp ? m.crop.spp : m.spp.back();
    for (const auto& rg : s.regions) {
        o << "<h3>Region " << html(rg.name) << fmt(" (x %.2f–%.2f, y %.2f–%.2f)", rg.x0, rg.x1, rg.y0, rg.y1) << " at "
          << cropSpp << " spp, seed " << m.seeds.front() << "</h3>\n<div class=\"grid\">";
        std::vector<std::string> columns = {"reference"};
        columns.insert(columns.end(), m.patterns.begin(), m.patterns.end());
        for (const auto& c : columns)
            o << "<figure><img class=\"crop\" src=\"" << regionCropFile(s.name, rg.name, c) << "\" alt=\""
              << html(s.name + " " + rg.name + ", " + c) << "\"><figcaption>"
              << (c == "reference" ? "reference" : patternHeader(c)) << "</figcaption></figure>";
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
