// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "report/report.h"
#include "base/gnuplot.h"
#include "base/text.h"

#include "claims/comparison_claims.h"
#include "metrics/image_metrics.h"
#include "report/verdicts_report.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace stipple::validation {

namespace fs = std::filesystem;

namespace {

// A number in a gnuplot data file: full precision; gnuplot skips the non-finite "null".
std::string plotNumber(double v) { return std::isfinite(v) ? fmt("%.17g", v) : std::string("null"); }

// gnuplot point type of the i-th pattern: filled and open squares, circles, triangles, diamonds.
int patternPointType(size_t i) {
    static const int types[] = {5, 7, 9, 11, 13, 4, 6, 8, 10, 12};
    return types[i % (sizeof types / sizeof types[0])];
}

// A pattern's verdict error at one spp as the plots show it: sqrt of the mean relative squared error (so that
// slopes read as RMS slopes), with its 95% interval.
struct PlottedError {
    double value = NAN, lo = NAN, hi = NAN;
};
PlottedError plottedError(const std::vector<ResultRow>& rows, const MatrixScene& scene, const std::string& pattern,
                          uint32_t spp, double floor) {
    const ErrorEstimate e = patternError(rows, scene, pattern, spp, -1, false, floor);
    if (!e.valid()) return {};
    const double h = 1.96 * std::sqrt(e.variance);
    // Log axes cannot show a lower bound ≤ 0: clamp it to a hundredth of the mean.
    return {std::sqrt(e.mean), std::sqrt(std::max(e.mean - h, 1e-4 * e.mean)), std::sqrt(e.mean + h)};
}

// Per scene, two panels of small multiples (error against spp, error against median CPU seconds): one panel per
// pattern, the pattern in its colour with its intervals over the others in grey, so that no line hides another.
bool writePlots(const std::string& dir, const ReportInputs& in) {
    const Matrix& m = *in.matrix;
    fs::create_directory(fs::path(dir) / "plots"); // never its parent: see writeReport
    std::string script;
    const size_t n = m.patterns.size();
    const size_t columns = n <= 4 ? n : (n + 1) / 2, rows = (n + columns - 1) / columns;
    for (const auto& scene : m.scenes) {
        const std::string base = safeName(scene.name);
        const double floor = errorFloor(in.results->rows, scene.name, -1, false, true);
        std::ostringstream dat;
        dat << "# spp error lo95 hi95 median_cpu_seconds; error: sqrt of the verdicts' mean relative squared error "
               "(one block per pattern: ";
        for (auto& p : m.patterns) dat << p << " ";
        dat << ")\n";
        // The axes are fitted to the data: the plotted points' range, widened by a sixth of a decade each side.
        double xMin = INFINITY, xMax = 0, tMin = INFINITY, tMax = 0, yMin = INFINITY, yMax = 0;
        for (const auto& pattern : m.patterns) {
            dat << "# " << pattern << "\n";
            for (const uint32_t spp : m.spp) {
                const PlottedError e = plottedError(in.results->rows, scene, pattern, spp, floor);
                const CellAggregate* c = findCell(in.cells, scene.name, pattern, spp);
                if (!(e.value > 0) || !c) continue;
                const double seconds = c->medianCpuSeconds > 0 ? c->medianCpuSeconds : c->medianRenderSeconds;
                dat << spp << " " << plotNumber(e.value) << " " << plotNumber(e.lo) << " " << plotNumber(e.hi) << " "
                    << plotNumber(seconds) << "\n";
                xMin = std::min(xMin, double(spp));
                xMax = std::max(xMax, double(spp));
                if (seconds > 0) {
                    tMin = std::min(tMin, seconds);
                    tMax = std::max(tMax, seconds);
                }
                yMin = std::min(yMin, e.lo);
                yMax = std::max(yMax, e.hi);
            }
            dat << "\n\n";
        }
        writeTextFile((fs::path(dir) / "plots" / (base + ".dat")).string(), dat.str());
        const double pad = std::pow(10.0, 1.0 / 6);
        // The range and labelled tics at 1, 2 and 5 × 10^k inside it (a log axis labels only decades otherwise, and
        // a fitted range may hold one or none).
        auto range = [&](const char* axis, double lo, double hi) {
            if (!(std::isfinite(lo) && lo > 0 && hi > 0)) return std::string();
            lo /= pad;
            hi *= pad;
            std::string tics;
            for (int k = int(std::floor(std::log10(lo))); k <= int(std::ceil(std::log10(hi))); ++k)
                for (double mant : {1.0, 2.0, 5.0})
                    if (const double v = mant * std::pow(10.0, k); v >= lo && v <= hi)
                        tics += (tics.empty() ? "" : ", ") + fmt("%g", v);
            return fmt("set %srange [%.6g:%.6g]\n", axis, lo, hi) +
                   (tics.empty() ? std::string() : fmt("set %stics (%s)\n", axis, tics.c_str()));
        };
        // One panel per pattern: every other pattern in light grey, this one in its colour with its intervals.
        auto panels = [&](bool bySeconds) {
            std::string cmd;
            for (size_t i = 0; i < n; ++i) {
                cmd += "set title " + gnuplotQuoted(m.patterns[i]) + " noenhanced textcolor rgb " +
                       gnuplotQuoted(patternColor(m.patterns[i])) + "\nplot ";
                for (size_t j = 0; j < n; ++j)
                    if (j != i)
                        cmd += gnuplotQuoted(base + ".dat") +
                               fmt(" index %zu using %s with lines lc rgb '#c8c8c8' lw 1 notitle, ", j,
                                   bySeconds ? "5:2" : "1:2");
                cmd += gnuplotQuoted(base + ".dat") + fmt(" index %zu ", i) +
                       (bySeconds ? "using 5:2 with linespoints" : "using 1:2:3:4 with yerrorlines") +
                       fmt(" lw 2 pt %d ps 0.9 lc rgb ", patternPointType(i)) +
                       gnuplotQuoted(patternColor(m.patterns[i])) + " notitle\n";
            }
            return cmd;
        };
        for (int kind = 0; kind < 2; ++kind) {
            const bool bySeconds = kind == 1;
            const std::string stem = base + (bySeconds ? "-error-seconds" : "-error-spp");
            std::string common = "set logscale xy\nset grid\nunset key\nset format y '%g'\nset format x '%g'\n"
                                 "set tmargin 2\nset bmargin 3\nset lmargin 9\nset rmargin 1\nset ylabel 'relative RMS' offset 1,0\n";
            common += bySeconds ? "set xlabel 'median CPU seconds' offset 0,0.5\n"
                                : "set xlabel 'samples per pixel' offset 0,0.5\n";
            common += bySeconds ? range("x", tMin, tMax) : range("x", xMin, xMax);
            if (!bySeconds) {
                std::string tics;
                for (uint32_t spp : m.spp) tics += (tics.empty() ? "" : ", ") + std::to_string(spp);
                common += "set xtics (" + tics + ")\n";
            }
            common += range("y", yMin, yMax);
            for (const char* terminal : {"pngcairo size 1200,%zu font ',9'", "svg size 1200,%zu font ',9'"}) {
                const bool png = terminal[0] == 'p';
                script += "reset\nset terminal " + fmt(terminal, 250 * rows) + "\nset output " +
                          gnuplotQuoted(stem + (png ? ".png" : ".svg")) + "\n" +
                          fmt("set multiplot layout %zu,%zu\n", rows, columns) + common + panels(bySeconds) +
                          "unset multiplot\nunset output\n";
            }
        }
    }
    writeTextFile((fs::path(dir) / "plots" / "plots.gp").string(), script);
    // gnuplot runs inside plots/ so the script names files relative to it.
    const int rc = runGnuplot((fs::path(dir) / "plots").string(), "plots.gp", "gnuplot.log");
    if (rc != 0) {
        std::cerr << "stipple-validate: gnuplot failed (exit " << rc << "); see " << dir
                  << "/plots/gnuplot.log. Tables and data are written; plots are missing.\n";
        return false;
    }
    return true;
}

// Where a pattern's error is: the share of its whole-image error (mean over seeds, per block) that the largest 1%
// of blocks hold, in the verdicts' error and in plain MSE, and the block plain MSE puts first. A share near 1% is
// an error spread over the image; near 100%, a few blocks decide it (README: Deciding).
std::string errorConcentrationHtml(const ReportInputs& in, const MatrixScene& scene) {
    const Matrix& m = *in.matrix;
    const uint32_t spp = m.spp.back();
    std::ostringstream o;
    bool any = false;
    for (const auto& p : m.patterns) {
        std::vector<double> rse, sse;
        int width = 0;
        size_t seeds = 0;
        for (const auto& r : in.results->rows) {
            if (r.scene != scene.name || r.pattern != p || r.spp != spp || r.blockRse.empty() ||
                r.blockRse.size() != r.blockSse.size())
                continue;
            if (rse.empty()) rse.assign(r.blockRse.size(), 0.0), sse.assign(r.blockSse.size(), 0.0);
            if (r.blockRse.size() != rse.size()) continue;
            for (size_t b = 0; b < rse.size(); ++b) rse[b] += r.blockRse[b], sse[b] += r.blockSse[b];
            width = r.width;
            ++seeds;
        }
        if (!seeds) continue;
        const size_t top = std::max<size_t>(1, rse.size() / 100);
        auto share = [&](std::vector<double> v) {
            double total = 0;
            for (double x : v) total += x;
            std::partial_sort(v.begin(), v.begin() + long(top), v.end(), std::greater<>());
            double head = 0;
            for (size_t i = 0; i < top; ++i) head += v[i];
            return total > 0 ? head / total : NAN;
        };
        const size_t worst = size_t(std::max_element(sse.begin(), sse.end()) - sse.begin());
        const int cols = blockColumns(width);
        const int bx = int(worst % size_t(cols)) * kErrorBlockSize, by = int(worst / size_t(cols)) * kErrorBlockSize;
        if (!any)
            o << "<details><summary>Where the error is, at " << spp << " spp: the share of each pattern's whole-image "
              << "error held by its largest 1% of " << kErrorBlockSize << "×" << kErrorBlockSize << " blocks ("
              << top << " of " << rse.size() << ")</summary><div class=\"wide\"><table><tr><th>pattern</th><th>the "
              << "verdicts' error</th><th>plain MSE (the study's)</th><th>plain MSE's largest block (pixels)</th></tr>\n";
        any = true;
        o << "<tr><td>" << patternHeader(p) << "</td>" << fmt("<td>%.0f%%</td><td>%.0f%%</td>", 100 * share(rse), 100 * share(sse))
          << fmt("<td>x %d–%d, y %d–%d</td></tr>\n", bx, bx + kErrorBlockSize - 1, by, by + kErrorBlockSize - 1);
    }
    if (any)
        o << "</table></div><p class=\"note\">Near 1%: the error is spread over the image; near 100%: a few blocks "
             "(a light's edge, a caustic) would decide a verdict on that error.</p></details>\n";
    return o.str();
}

// Whether a scene is rendered by an external program (its sampler seconds are unknown, its times include start-up).
bool externalScene(const Matrix& m, const std::string& scene) {
    for (const auto& s : m.scenes)
        if (s.name == scene) return !s.renderer.empty();
    return false;
}

std::string cellTable(const std::string& dir, const Matrix& m, const std::vector<CellAggregate>& cells,
                      uint32_t onlySpp) {
    std::ostringstream o;
    o << "<div class=\"wide\"><table><tr><th>scene</th><th>pattern</th><th>spp</th><th>mean RMS (eq. 1)</th><th>± 95%</th>"
         "<th>RMS measured</th><th>floor-limited seeds</th><th>median wall s</th><th>median sampler s</th>"
         "<th>efficiency 1/(MSE·s)</th><th>non-finite px</th><th>seed " << m.seeds.front() << "</th></tr>\n";
    for (const auto& scene : m.scenes)
        for (const auto& c : cells) {
            if (c.scene != scene.name || (onlySpp && c.spp != onlySpp)) continue;
            o << "<tr><td>" << html(c.scene) << "</td><td>" << html(c.pattern) << "</td><td>" << c.spp << "</td>"
              << fmt("<td>%.5g</td><td>%.2g</td><td>%.5g</td><td>%d/%zu</td><td>%.4f</td><td>%s</td><td>%.4g</"
                     "td><td>%llu</td>",
                     c.rms.mean, c.rms.halfWidth, c.meanRmsMeasured, c.floorLimitedSeeds, c.seeds,
                     c.medianRenderSeconds,
                     externalScene(m, c.scene) ? "–" : fmt("%.4f", c.medianSamplerSeconds).c_str(), c.efficiency,
                     (unsigned long long)c.nonFinitePixels);
            const std::string exr = cellExrFile(c.scene, c.pattern, c.spp, m.seeds.front());
            o << (fs::exists(fs::path(dir) / exr) ? "<td><a href=\"" + exr + "\">EXR</a></td>" : std::string("<td>–</td>"))
              << "</tr>\n";
        }
    o << "</table></div>\n";
    return o.str();
}

} // namespace

std::string summaryTable(const Matrix& m, const std::vector<CellAggregate>& cells, uint32_t spp) {
    std::string s = fmt("%-16s %-13s %6s %12s %10s %10s %10s %12s\n", "scene", "pattern", "spp", "mean RMS", "±95%",
                        "render s", "sampler s", "1/(MSE·s)");
    for (const auto& scene : m.scenes)
        for (const auto& pattern : m.patterns)
            if (const CellAggregate* c = findCell(cells, scene.name, pattern, spp))
                s += fmt("%-16s %-13s %6u %12.5g %10.2g %10.4f %10s %12.4g%s\n", scene.name.c_str(), pattern.c_str(),
                         spp, c->rms.mean, c->rms.halfWidth, c->medianRenderSeconds,
                         scene.renderer.empty() ? fmt("%.4f", c->medianSamplerSeconds).c_str() : "-", c->efficiency,
                         c->floorLimitedSeeds ? "  floor-limited" : "");
    return s;
}

namespace {

const char* const kReportStyle =
    "body{font-family:sans-serif;margin:1.5em auto;max-width:1240px;padding:0 1em;line-height:1.35}"
    "table{border-collapse:collapse;margin:0.6em 0;font-size:90%}td,th{border:1px solid #ccc;padding:2px 6px;"
    "text-align:right;vertical-align:top}th{background:#eee}td:first-child{text-align:left}"
    ".PASS{color:#080}.FAIL{color:#c00;font-weight:bold}.NOT{color:#a60}"
    "pre{background:#f6f6f6;padding:0.6em;white-space:pre-wrap;overflow-wrap:anywhere;font-size:85%;margin:0.3em 0}"
    "img{max-width:100%;height:auto}img.crop{image-rendering:pixelated}img.plot{width:100%;display:block}figure.plot{margin:0}"
    ".answers{margin:0.4em 0}.answers h2{margin:0.3em 0;font-size:120%}.answer{margin:0.35em 0}"
    ".headline{background:#f4f7fb;border-left:4px solid #456;padding:0 1em}.counts{font-size:110%;margin:0.4em 0}"
    ".grid{display:flex;flex-wrap:wrap;gap:8px}.grid figure{margin:0}figcaption{text-align:center;font-size:90%}"
    ".pair{display:flex;flex-wrap:wrap;gap:1%}.pair img{width:49%}.sw{display:inline-block;width:0.8em;height:0.8em;"
    "margin-right:0.3em;border-radius:2px}.claim{margin:0.5em 0}.claim .st{font-weight:bold;margin-right:0.5em}"
    ".note{font-size:90%;color:#333}section.scene{border-top:2px solid #456;margin-top:1.5em}"
    "section.scene>.top{display:flex;gap:1em;align-items:flex-start;flex-wrap:wrap}section.scene>.top>img{width:"
    "320px}"
    "section.scene>.top>div{flex:1 1 420px;min-width:0}"
    ".wide{max-width:100%;overflow-x:auto}table.study{font-size:85%}td.v{white-space:nowrap}"
    ".maps{display:grid;grid-template-columns:repeat(auto-fill,minmax(260px,1fr));gap:8px}"
    ".maps figure{margin:0}.maps img{max-width:100%}"
    "@media print{section.scene{break-before:page}details{display:block}}";

// What the run was: renderer, rows, seeds, time, and how RMS is measured.
std::string runNoteHtml(const ReportInputs& in) {
    const Results& r = *in.results;
    std::ostringstream o;
    bool allExternal = true;
    for (const auto& s : in.matrix->scenes) allExternal &= !s.renderer.empty();
    o << "<p class=\"note\">"
      << (allExternal ? "Renderer: an external program (each scene names it); stipple-validate of "
                      : "Renderer ")
      << html(r.rendererVersion) << "; " << r.rows.size() << " rows (cell × seed); "
      << in.matrix->seeds.size() << " seeds per cell"
      << (in.wallSeconds > 0 ? fmt("; run took %.1f s", in.wallSeconds) : std::string()) << ". " << html(in.note)
      << "</p>\n<p class=\"note\" id=\"deciding\"><strong>Errors.</strong> The verdicts, the answers and the plots "
         "use one error: per pixel the squared error relative to the reference pixel's level (a dark pixel's relative "
         "to the image's mean), capped at " << fmt("%g", 3 * kRelativeErrorCap * kRelativeErrorCap)
      << ", and in the blocks where the reference's own noise is above the median block's, divided by that excess "
         "(a pixel one sample can make or break, at a small light's edge, counts like any other); mean over pixels "
         "and seeds, the reference's noise removed (validation/README.md, <em>Deciding</em>). The tables of cells "
         "and slopes give the study's <em>RMS (eq. 1)</em>, sqrt((1/(H·W)) Σ<sub>pixels</sub> Σ<sub>rgb</sub> "
         "(I<sub>ref</sub> − I)²), over finite pixels, the reference's noise floor removed from the MSE "
         "(<em>floor-limited</em>: corrected MSE ≤ 2 × floor); no verdict is given on it. Intervals are 95%. "
      << [&] {
             size_t external = 0;
             for (const auto& s : in.matrix->scenes) external += !s.renderer.empty();
             if (external == 0) return std::string("Times (stipple-render, in-process) exclude scene load and BVH build.");
             const std::string ext = "an external renderer's are its process's wall and user + system CPU seconds, "
                                     "start-up and scene load included; its sampler seconds are unknown (–)";
             if (external == in.matrix->scenes.size()) return "Times: " + ext + ".";
             return "Times: stipple-render's exclude scene load and BVH build; " + ext + ".";
         }()
      << "</p>\n";
    if (in.baseline) {
        o << "<h2>Baseline " << html(in.baselinePath) << ": " << (in.baseline->failed ? "FAIL" : "PASS")
          << "</h2>\n<pre>" << in.baseline->compared << " cells compared\n";
        for (const auto& l : in.baseline->lines) o << html(l) << "\n";
        o << "</pre>\n";
    }
    return o.str();
}

// One claim with its status and figures; with onlyScene, only the figure lines of that scene.
std::string claimHtml(const CheckOutcome& c, const std::string& onlyScene) {
    const std::string status = checkStatusName(c.status);
    std::ostringstream b;
    b << "<div class=\"claim\"><span class=\"st " << status.substr(0, status.find(' ')) << "\">" << status
      << (c.status == CheckStatus::NotSeparated ? (c.failsRun ? " (fails)" : " (tolerated)") : "") << "</span>"
      << html(c.claim) << " <small>[" << html(c.check.where) << "]</small><pre>";
    bool keep = false;
    for (const auto& f : c.figures) {
        // A figure line starts with its scene's name; indented lines continue the one before.
        if (f.rfind("    ", 0) != 0)
            keep = onlyScene.empty() || f.rfind(onlyScene + " ", 0) == 0 || f.rfind(onlyScene + ":", 0) == 0;
        if (keep) b << html(f) << "\n";
    }
    b << "</pre></div>\n";
    return b.str();
}

// A scene's section: the reference, its claims, the two plots, the verdicts per region, the crops and cells.
std::string sceneSectionHtml(const std::string& dir, const ReportInputs& in, const MatrixScene& scene) {
    const Matrix& m = *in.matrix;
    const std::string b = safeName(scene.name);
    std::ostringstream o;
    o << "<section class=\"scene\" id=\"scene-" << b << "\"><h2>" << html(scene.name) << "</h2>\n";
    o << "<figure class=\"plot\"><img class=\"plot\" src=\"plots/" << b << "-error-spp.png\" alt=\""
      << html(scene.name)
      << ": the verdicts' error against samples per pixel, one panel per pattern (the others in grey), 95% "
         "intervals\"><figcaption>The verdicts' error (relative RMS, <a href=\"#deciding\">what it is</a>) against "
         "samples per pixel, 95% intervals: one panel per pattern, the other patterns in grey.</figcaption></figure>\n"
         "<div class=\"top\">";
    const std::string picture = "crops/" + b + "-reference-full.png";
    if (fs::exists(fs::path(dir) / picture))
        o << "<img src=\"" << picture << "\" alt=\"" << html(scene.name) << ": the reference, tone-mapped\">";
    o << "<div>";
    for (const auto& s : in.results->scenes)
        if (s.name == scene.name)
            o << "<p class=\"note\">" << html(s.integrator) << ", " << s.width << "×" << s.height
              << (scene.renderer.empty() ? ", " + std::to_string(s.triangles) + " triangles" : std::string())
              << "; reference " << s.referenceSpp << " spp (" << html(m.reference.pattern)
              << (scene.renderer.empty() ? "" : ", two halves of different seeds") << "), noise floor "
              << fmt("%.3g", s.noiseFloor) << " (MSE).</p>";
    for (const auto& c : in.outcomes)
        if (c.check.scene == scene.name || c.check.scene == "all") o << claimHtml(c, scene.name);
    o << "</div></div>\n<details><summary>" << html(scene.name) << ": the same error against median CPU seconds"
      << "</summary><img class=\"plot\" src=\"plots/" << b << "-error-seconds.png\" alt=\"" << html(scene.name)
      << ": the verdicts' error against median CPU seconds, one panel per pattern\"></details>\n";
    o << errorConcentrationHtml(in, scene);
    o << sceneVerdictsHtml(in, scene);
    o << "<details><summary>Centre crop and all cells of " << html(scene.name) << "</summary>\n<div class=\"grid\">";
    const uint32_t cropSpp = m.crop.spp ? m.crop.spp : m.spp.back();
    std::vector<std::string> columns = m.patterns;
    columns.push_back("reference");
    for (const auto& p : columns) {
        const std::string f = cropFile(scene.name, p);
        if (fs::exists(fs::path(dir) / f))
            o << "<figure><img class=\"crop\" src=\"" << f << "\" alt=\"" << html(scene.name + " centre crop, " + p)
              << "\"><figcaption>" << html(p) << " (" << cropSpp << " spp)</figcaption></figure>";
    }
    o << "</div>\n";
    std::vector<CellAggregate> mine;
    for (const auto& c : in.cells)
        if (c.scene == scene.name) mine.push_back(c);
    o << cellTable(dir, m, mine, 0) << "</details></section>\n";
    return o.str();
}

// Fitted slopes of log RMS against log spp, scene by pattern.
std::string slopesTableHtml(const ReportInputs& in) {
    const Matrix& m = *in.matrix;
    std::ostringstream o;
    o << "<h2>Slopes of log RMS (eq. 1) vs log spp</h2>\n<p class=\"note\">Least squares over per-seed points; 95% interval "
         "on the slope. Independent sampling converges at −0.5; stratified between −0.75 (edges) and −1 (smooth) in "
         "2D, less in a full renderer's many dimensions.</p>\n<div class=\"wide\"><table><tr><th>scene</th>";
    for (const auto& p : m.patterns) o << "<th>" << patternHeader(p) << "</th>";
    o << "</tr>\n";
    for (const auto& scene : m.scenes) {
        o << "<tr><td>" << html(scene.name) << "</td>";
        for (const auto& p : m.patterns) {
            std::string cell = "–";
            for (const auto& s : in.slopes)
                if (s.scene == scene.name && s.pattern == p)
                    cell = fmt("%.3f ± %.3f", s.fit.slope, s.fit.slopeHalfWidth);
            o << "<td>" << cell << "</td>";
        }
        o << "</tr>\n";
    }
    o << "</table></div>\n";
    return o.str();
}

// Per scene: load and BVH times, the reference's spp, time, floor and cache key.
std::string scenesTableHtml(const Results& r) {
    std::ostringstream o;
    o << "<details><summary>Scenes: load, BVH build, references</summary><div class=\"wide\"><table><tr><th>scene</th><th>file</th>"
         "<th>size</th><th>load s</th><th>BVH s</th><th>warm-up s</th><th>ref. spp</th><th>ref. s</th>"
         "<th>floor (MSE)</th><th>reference key</th></tr>\n";
    for (const auto& s : r.scenes)
        o << "<tr><td>" << html(s.name) << "</td><td>" << html(s.file) << "</td><td>" << s.width << "×" << s.height
          << "</td>"
          << fmt("<td>%.3f</td><td>%.3f</td><td>%.3f</td><td>%u</td><td>%s</td><td>%.3g</td>", s.loadSeconds,
                 s.buildSeconds, s.warmupSeconds, s.referenceSpp,
                 s.referenceSeconds > 0 ? fmt("%.2f", s.referenceSeconds).c_str() : "cached", s.noiseFloor)
          << "<td>" << html(s.referenceKey) << "</td></tr>\n";
    o << "</table></div></details>\n";
    return o.str();
}

} // namespace

bool writeReport(const std::string& dir, const ReportInputs& inputs) {
    ReportInputs in = inputs;
    in.reportDir = dir;
    const Matrix& m = *in.matrix;
    const Results& r = *in.results;
    // dir is the run's staging folder (report_publish.h), made when the run started. Nothing here creates it (or
    // any parent) again: after a SIGTERM the cleanup thread removes it while this thread may still be writing,
    // and a folder brought back then would outlive the process.
    if (!fs::is_directory(dir)) throw std::runtime_error("the report folder " + dir + " is gone");
    writeResultsCsv((fs::path(dir) / "results.csv").string(), r.rows);
    writeCellsCsv((fs::path(dir) / "cells.csv").string(), in.cells);
    writeResultsJson((fs::path(dir) / "results.json").string(), r, in.cells, in.slopes, outcomesJson(in.outcomes));
    const bool plotsOk = writePlots(dir, in);

    std::ostringstream o;
    o << "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><meta name=\"viewport\" "
         "content=\"width=device-width, initial-scale=1\"><title>stipple-validate: "
      << html(m.name) << "</title>\n<style>" << kReportStyle << "</style></head><body>\n";
    o << "<h1>stipple-validate: " << html(m.name) << "</h1>\n";
    o << verdictHeadlineHtml(in) << studyDetailsHtml(in) << runNoteHtml(in);
    if (!plotsOk) o << "<p>gnuplot failed; see plots/gnuplot.log. Data: plots/*.dat.</p>\n";
    for (const auto& scene : m.scenes) o << sceneSectionHtml(dir, in, scene);
    o << "<h2>All claims</h2>\n";
    for (const auto& c : in.outcomes) o << claimHtml(c, "");
    o << slopesTableHtml(in) << scenesTableHtml(r);
    o << "<p>Data: <a href=\"results.csv\">results.csv</a> (per seed), <a href=\"cells.csv\">cells.csv</a> (per cell), "
         "<a href=\"results.json\">results.json</a>; plots as SVG and gnuplot data in <a "
         "href=\"plots/plots.gp\">plots/</a>.</p>\n";
    o << "<details><summary>Matrix " << html(m.path) << "</summary><pre>" << html(m.text)
      << "</pre></details>\n</body></html>\n";
    writeTextFile((fs::path(dir) / "index.html").string(), o.str());
    return plotsOk;
}

} // namespace stipple::validation
