#include "report.h"

#include "verdicts_report.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace stipple::validation {

namespace fs = std::filesystem;

namespace {

std::string fmt(const char* format, auto... args) {
    char buf[1024];
    std::snprintf(buf, sizeof buf, format, args...);
    return buf;
}

std::string html(const std::string& s) {
    std::string o;
    for (char c : s) {
        switch (c) {
        case '<': o += "&lt;"; break;
        case '>': o += "&gt;"; break;
        case '&': o += "&amp;"; break;
        case '"': o += "&quot;"; break;
        default: o += c;
        }
    }
    return o;
}

// Single-quoted gnuplot string.
std::string gq(const std::string& s) {
    std::string o = "'";
    for (char c : s) o += c == '\'' ? std::string("''") : std::string(1, c);
    return o + "'";
}

bool writePlots(const std::string& dir, const ReportInputs& in) {
    const Matrix& m = *in.matrix;
    fs::create_directories(fs::path(dir) / "plots");
    std::string script;
    for (const auto& scene : m.scenes) {
        const std::string base = safeName(scene.name);
        std::ostringstream dat;
        dat << "# spp mean_rms lo hi median_render_seconds (one block per pattern: "
            << [&] { std::string s; for (auto& p : m.patterns) s += p + " "; return s; }() << ")\n";
        for (const auto& pattern : m.patterns) {
            dat << "# " << pattern << "\n";
            for (const auto& c : in.cells) {
                if (c.scene != scene.name || c.pattern != pattern || !(c.rms.mean > 0)) continue;
                double h = std::isfinite(c.rms.halfWidth) ? c.rms.halfWidth : 0;
                // Log axes cannot show a lower bound ≤ 0: clamp it to a hundredth of the mean.
                double lo = std::max(c.rms.mean - h, 0.01 * c.rms.mean);
                dat << c.spp << " " << jsonNumber(c.rms.mean) << " " << jsonNumber(lo) << " "
                    << jsonNumber(c.rms.mean + h) << " " << jsonNumber(c.medianRenderSeconds) << "\n";
            }
            dat << "\n\n";
        }
        writeTextFile((fs::path(dir) / "plots" / (base + ".dat")).string(), dat.str());

        auto plotCommand = [&](bool bySeconds) {
            std::string cmd = "plot ";
            for (size_t i = 0; i < m.patterns.size(); ++i) {
                if (i) cmd += ", \\\n     ";
                cmd += gq(base + ".dat") + fmt(" index %zu ", i) +
                       (bySeconds ? "using 5:2 with linespoints" : "using 1:2:3:4 with yerrorlines") + " lw 2 title " +
                       gq(m.patterns[i]);
            }
            return cmd + "\n";
        };
        for (int kind = 0; kind < 2; ++kind) {
            const bool bySeconds = kind == 1;
            const std::string stem = base + (bySeconds ? "-rms-seconds" : "-rms-spp");
            std::string common = "set logscale xy\nset grid\nset key top right noenhanced\nset format y '10^{%L}'\n"
                                 "set ylabel 'RMS (eq. 1, reference floor removed)'\n";
            common += bySeconds ? "set xlabel 'median render seconds'\n" : "set xlabel 'samples per pixel'\n";
            common += "set title " + gq(scene.name + (bySeconds ? ": RMS vs render time" : ": RMS vs spp")) +
                      " noenhanced\n";
            script += "reset\n" + common;
            script += "set terminal pngcairo size 720,520 enhanced font ',10'\nset output " + gq(stem + ".png") + "\n" +
                      plotCommand(bySeconds);
            script += "set terminal svg size 720,520 enhanced\nset output " + gq(stem + ".svg") + "\n" +
                      plotCommand(bySeconds) + "unset output\n";
        }
    }
    writeTextFile((fs::path(dir) / "plots" / "plots.gp").string(), script);
    // gnuplot runs inside plots/ so the script names files relative to it.
    std::string cmd = "cd '" + (fs::path(dir) / "plots").string() + "' && gnuplot plots.gp 2> gnuplot.log";
    int rc = std::system(cmd.c_str());
    if (rc != 0) {
        std::cerr << "stipple-validate: gnuplot failed (exit " << rc << "); see " << dir
                  << "/plots/gnuplot.log. Tables and data are written; plots are missing.\n";
        return false;
    }
    return true;
}

std::string cellTable(const Matrix& m, const std::vector<CellAggregate>& cells, uint32_t onlySpp) {
    std::ostringstream o;
    o << "<table><tr><th>scene</th><th>pattern</th><th>spp</th><th>mean RMS</th><th>± 95%</th>"
         "<th>RMS measured</th><th>floor-limited seeds</th><th>median render s</th><th>median sampler s</th>"
         "<th>efficiency 1/(MSE·s)</th><th>non-finite px</th></tr>\n";
    for (const auto& scene : m.scenes)
        for (const auto& c : cells) {
            if (c.scene != scene.name || (onlySpp && c.spp != onlySpp)) continue;
            o << "<tr><td>" << html(c.scene) << "</td><td>" << html(c.pattern) << "</td><td>" << c.spp << "</td>"
              << fmt("<td>%.5g</td><td>%.2g</td><td>%.5g</td><td>%d/%zu</td><td>%.4f</td><td>%.4f</td><td>%.4g</td><td>%llu</td>",
                     c.rms.mean, c.rms.halfWidth, c.meanRmsMeasured, c.floorLimitedSeeds, c.seeds,
                     c.medianRenderSeconds, c.medianSamplerSeconds, c.efficiency, (unsigned long long)c.nonFinitePixels)
              << "</tr>\n";
        }
    o << "</table>\n";
    return o.str();
}

} // namespace

std::string safeName(const std::string& name) {
    std::string s;
    for (char c : name) s += (std::isalnum((unsigned char)c) || c == '-' || c == '_') ? c : '_';
    return s;
}

std::string cropFile(const std::string& scene, const std::string& pattern) {
    return "crops/" + safeName(scene) + "-" + safeName(pattern) + ".png";
}

std::string summaryTable(const Matrix& m, const std::vector<CellAggregate>& cells, uint32_t spp) {
    std::string s = fmt("%-16s %-13s %6s %12s %10s %10s %10s %12s\n", "scene", "pattern", "spp", "mean RMS", "±95%",
                        "render s", "sampler s", "1/(MSE·s)");
    for (const auto& scene : m.scenes)
        for (const auto& pattern : m.patterns)
            if (const CellAggregate* c = findCell(cells, scene.name, pattern, spp))
                s += fmt("%-16s %-13s %6u %12.5g %10.2g %10.4f %10.4f %12.4g%s\n", scene.name.c_str(), pattern.c_str(),
                         spp, c->rms.mean, c->rms.halfWidth, c->medianRenderSeconds, c->medianSamplerSeconds,
                         c->efficiency, c->floorLimitedSeeds ? "  floor-limited" : "");
    return s;
}

bool writeReport(const std::string& dir, const ReportInputs& in) {
    const Matrix& m = *in.matrix;
    const Results& r = *in.results;
    fs::create_directories(dir);
    writeResultsCsv((fs::path(dir) / "results.csv").string(), r.rows);
    writeCellsCsv((fs::path(dir) / "cells.csv").string(), in.cells);
    writeResultsJson((fs::path(dir) / "results.json").string(), r, in.cells, in.slopes, outcomesJson(in.outcomes));
    bool plotsOk = writePlots(dir, in);

    std::ostringstream o;
    o << "<!doctype html>\n<html><head><meta charset=\"utf-8\"><title>stipple-validate: " << html(m.name)
      << "</title>\n<style>body{font-family:sans-serif;margin:2em;max-width:1400px}table{border-collapse:collapse;"
         "margin:1em 0}td,th{border:1px solid #ccc;padding:2px 8px;text-align:right}th{background:#eee}"
         "td:first-child,td:nth-child(2){text-align:left}.PASS{color:#080}.FAIL{color:#c00;font-weight:bold}"
         ".NOT{color:#a60}pre{background:#f6f6f6;padding:1em;overflow:auto}img.crop{image-rendering:pixelated}"
         ".headline{background:#f4f7fb;border-left:4px solid #456;padding:0.2em 1em}.grid{display:flex;flex-wrap:wrap;"
         "gap:8px}.grid figure{margin:0}figcaption{text-align:center;font-size:90%}"
         "</style></head><body>\n";
    o << "<h1>stipple-validate: " << html(m.name) << "</h1>\n<p>Renderer " << html(r.rendererVersion) << "; "
      << r.rows.size() << " rows (cell × seed); " << m.seeds.size() << " seeds per cell"
      << (in.wallSeconds > 0 ? fmt("; run took %.1f s", in.wallSeconds) : std::string()) << ". "
      << html(in.note) << "</p>\n";
    o << "<p>RMS is the study's equation 1, sqrt((1/(H·W)) Σ<sub>pixels</sub> Σ<sub>rgb</sub> (I<sub>ref</sub> − I)²), "
         "over finite pixels; the figures subtract the reference's noise floor from the MSE (MSE<sub>corrected</sub> = "
         "max(MSE − floor, 0)) and flag a seed <em>floor-limited</em> when its corrected MSE ≤ 2 × floor. Intervals "
         "are 95% Student-t over the seeds. Times are render seconds without scene load or BVH build; medians over "
         "seeds.</p>\n";

    o << verdictsHtml(in);

    o << "<h2>Checks</h2>\n<table><tr><th>status</th><th>claim</th><th>figures</th><th>where</th></tr>\n";
    for (const auto& c : in.outcomes) {
        std::string status = checkStatusName(c.status);
        o << "<tr><td class=\"" << status.substr(0, status.find(' ')) << "\">" << status
          << (c.status == CheckStatus::NotSeparated ? (c.failsRun ? " (fails)" : " (tolerated)") : "")
          << "</td><td style=\"text-align:left\">" << html(c.claim) << "</td><td style=\"text-align:left\"><pre>";
        for (const auto& f : c.figures) o << html(f) << "\n";
        o << "</pre></td><td>" << html(c.check.where) << "</td></tr>\n";
    }
    o << "</table>\n";
    if (in.baseline) {
        o << "<h2>Baseline " << html(in.baselinePath) << ": " << (in.baseline->failed ? "FAIL" : "PASS") << "</h2>\n<pre>"
          << in.baseline->compared << " cells compared\n";
        for (const auto& l : in.baseline->lines) o << html(l) << "\n";
        o << "</pre>\n";
    }

    o << "<h2>Scenes</h2>\n<table><tr><th>scene</th><th>file</th><th>integrator</th><th>size</th><th>triangles</th>"
         "<th>load s</th><th>BVH build s</th><th>warm-up s</th><th>reference spp</th><th>reference s</th><th>noise floor (MSE)</th>"
         "<th>reference key</th></tr>\n";
    for (const auto& s : r.scenes)
        o << "<tr><td>" << html(s.name) << "</td><td style=\"text-align:left\">" << html(s.file) << "</td><td>"
          << html(s.integrator) << "</td><td>" << s.width << "×" << s.height << "</td><td>" << s.triangles << "</td>"
          << fmt("<td>%.3f</td><td>%.3f</td><td>%.3f</td><td>%u</td><td>%s</td><td>%.4g</td>", s.loadSeconds, s.buildSeconds, s.warmupSeconds,
                 s.referenceSpp, s.referenceSeconds > 0 ? fmt("%.2f", s.referenceSeconds).c_str() : "cached",
                 s.noiseFloor)
          << "<td>" << html(s.referenceKey) << "</td></tr>\n";
    o << "</table>\n";

    o << "<h2>At " << m.spp.back() << " spp</h2>\n" << cellTable(m, in.cells, m.spp.back());

    o << "<h2>Slopes of log RMS vs log spp</h2>\n<p>Least squares over per-seed points; 95% interval on the slope "
         "(t, n − 2 dof). Independent sampling converges at −0.5; stratified between −0.75 (edges) and −1 (smooth) "
         "in 2D, less in a full renderer's many dimensions.</p>\n<table><tr><th>scene</th>";
    for (const auto& p : m.patterns) o << "<th>" << html(p) << "</th>";
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
    o << "</table>\n";

    o << "<h2>Plots</h2>\n";
    if (!plotsOk) o << "<p>gnuplot failed; see plots/gnuplot.log. Data: plots/*.dat.</p>\n";
    for (const auto& scene : m.scenes) {
        std::string b = safeName(scene.name);
        o << "<p><img src=\"plots/" << b << "-rms-spp.png\" alt=\"" << html(scene.name) << " RMS vs spp\"> <img src=\"plots/"
          << b << "-rms-seconds.png\" alt=\"" << html(scene.name) << " RMS vs seconds\"><br>SVG: <a href=\"plots/" << b
          << "-rms-spp.svg\">RMS vs spp</a>, <a href=\"plots/" << b << "-rms-seconds.svg\">RMS vs seconds</a></p>\n";
    }

    const uint32_t cropSpp = m.crop.spp ? m.crop.spp : m.spp.back();
    o << "<h2>Crops at " << cropSpp << " spp (seed " << m.seeds.front() << ")</h2>\n<p>The same region under each "
      << "pattern, as the study's Table 1; nearest-neighbour magnified ×" << m.crop.scale << ".</p>\n<table><tr><th>scene</th>";
    for (const auto& p : m.patterns) o << "<th>" << html(p) << "</th>";
    o << "<th>reference</th></tr>\n";
    for (const auto& scene : m.scenes) {
        o << "<tr><td>" << html(scene.name) << "</td>";
        std::vector<std::string> columns = m.patterns;
        columns.push_back("reference");
        for (const auto& p : columns) {
            std::string f = cropFile(scene.name, p);
            if (fs::exists(fs::path(dir) / f)) o << "<td><img class=\"crop\" src=\"" << f << "\"></td>";
            else o << "<td>–</td>";
        }
        o << "</tr>\n";
    }
    o << "</table>\n";

    o << "<h2>All cells</h2>\n" << cellTable(m, in.cells, 0);
    o << "<p>Per seed: <a href=\"results.csv\">results.csv</a>, <a href=\"results.json\">results.json</a>; per cell: <a href=\"cells.csv\">cells.csv</a>.</p>\n";
    o << "<h2>Matrix " << html(m.path) << "</h2>\n<pre>" << html(m.text) << "</pre>\n</body></html>\n";
    writeTextFile((fs::path(dir) / "index.html").string(), o.str());
    return plotsOk;
}

} // namespace stipple::validation
