// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "perceptual/study_report.h"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "run/results.h"
#include "base/gnuplot.h"
#include "base/text.h"
#include "report/verdicts_report.h"
#include "perceptual/experiment.h"

namespace stipple::validation {

namespace fs = std::filesystem;

namespace {

std::string plotStem(size_t set) { return "perceptual-set-" + std::to_string(set + 1); }

// One plot per set: each pattern's JOD (relative to the set's first) with its 95% bootstrap interval.
bool writeStudyPlots(const std::string& plotsDir, const StudyKey& key, const StudyAnalysis& a) {
    fs::create_directories(plotsDir);
    std::string script;
    for (size_t si = 0; si < key.sets.size(); ++si) {
        const StudySet& set = key.sets[si];
        const SetAnalysis& sa = a.sets[si];
        std::ostringstream dat;
        dat << "# index pattern jod lo95 hi95\n";
        for (size_t i = 0; i < set.crops.size(); ++i)
            // gnuplot's data files quote strings with " only.
            dat << i << " \"" << set.crops[i].pattern << "\" "
                << fmt("%.9g %.9g %.9g", sa.score[i], sa.lo95[i], sa.hi95[i]) << "\n";
        const std::string stem = plotStem(si);
        writeTextFile((fs::path(plotsDir) / (stem + ".dat")).string(), dat.str());
        double lo = -0.5, hi = 0.5;
        for (size_t i = 0; i < set.crops.size(); ++i) // no interval (fewer than 2 observers kept): the scores alone
            for (double v : {sa.lo95[i], sa.hi95[i], sa.score[i]})
                if (std::isfinite(v)) {
                    lo = std::min(lo, v);
                    hi = std::max(hi, v);
                }
        script += "reset\nset terminal pngcairo size 420,320 enhanced font ',10'\nset output " +
                  gnuplotQuoted(stem + ".png") + "\nset title " + gnuplotQuoted(set.name + fmt(", %u spp", set.spp)) +
                  " noenhanced\n" +
                  "set ylabel 'quality, JOD (95% interval over observers)'\nset grid ytics\nunset key\n" +
                  fmt("set xrange [-0.5:%zu.5]\nset yrange [%g:%g]\n", set.crops.size() - 1, lo - 0.3, hi + 0.3) +
                  "set xtics noenhanced\nset arrow from -0.5,0 to " + fmt("%zu.5", set.crops.size() - 1) +
                  ",0 nohead dt 2 lc rgb '#888888'\nplot ";
        for (size_t i = 0; i < set.crops.size(); ++i)
            script += (i ? ", " : "") + gnuplotQuoted(stem + ".dat") +
                      fmt(" every ::%zu::%zu using 1:3:4:5:xtic(2)", i, i) +
                      " with yerrorbars pt 7 ps 1.4 lw 2 lc rgb " + gnuplotQuoted(patternColor(set.crops[i].pattern));
        script += "\nunset output\n";
    }
    writeTextFile((fs::path(plotsDir) / "perceptual.gp").string(), script);
    const int rc = runGnuplot(plotsDir, "perceptual.gp", "perceptual.gp.log");
    if (rc != 0)
        std::cerr << "stipple-validate: gnuplot failed on the perceptual plots (exit " << rc << "); see " << plotsDir
                  << "/perceptual.gp.log\n";
    return rc == 0;
}

std::string verdictCell(const StudySet& set, const PairVerdict& p) {
    std::string word = pairVerdictName(p.verdict);
    if (p.verdict == PairVerdictKind::PreferredA) word = set.crops[p.a].pattern + " PREFERRED";
    if (p.verdict == PairVerdictKind::PreferredB) word = set.crops[p.b].pattern + " PREFERRED";
    return fmt("%+.2f JOD <small>(%+.2f – %+.2f)</small><br><strong>%s</strong><br><small>%d observers; decided "
               "at ~%s</small>",
               p.difference, p.lo95, p.hi95, html(word).c_str(), p.observers,
               p.observersNeeded ? std::to_string(p.observersNeeded).c_str() : "?");
}

} // namespace

std::string studyFigureHtml(const StudyKey& key, const StudyAnalysis& a, const std::string& plotsDir,
                            const std::string& plotsHref) {
    const bool plotted = writeStudyPlots(plotsDir, key, a);
    std::ostringstream o;
    o << "<div class=\"wide\"><table class=\"study\" id=\"perceptual-verdicts\"><tr><th>test set</th><th>pair A / B</th>"
         "<th>people: A − B (95%), verdict</th><th>mean FLIP A / B</th></tr>\n";
    for (size_t si = 0; si < key.sets.size(); ++si)
        for (const auto& p : a.sets[si].pairs) {
            const StudySet& set = key.sets[si];
            const StudyCrop &ca = set.crops[p.a], &cb = set.crops[p.b];
            o << "<tr><td>" << html(set.name) << fmt(", %u spp", set.spp) << "</td><td>" << patternHeader(ca.pattern)
              << " / " << patternHeader(cb.pattern) << "</td><td class=\"v\">" << verdictCell(set, p) << "</td><td>"
              << (std::isfinite(ca.flip) && std::isfinite(cb.flip) && cb.flip > 0 ? fmt("%.3g×", ca.flip / cb.flip)
                                                                                  : std::string("–"))
              << "</td></tr>\n";
        }
    o << "</table></div>\n<p class=\"note\">People's quality scale from rankings (Thurstone Case V by maximum "
         "likelihood; 1 JOD: 75% of observers prefer the better), 95% interval from a bootstrap over the kept "
         "observers (estimate ± t(n−1) × the resamples' standard deviation × √(n/(n−1)); "
      << a.bootstrapSamples << " resamples, seed " << a.seed
      << "). <strong>PREFERRED</strong>: the interval excludes 0; <strong>EQUIVALENT</strong>: the 90% interval lies "
         "within ±"
      << fmt("%g", key.margin)
      << " JOD; else <strong>NOT SEPARATED</strong>. <em>decided at</em>: the observers a decided verdict would need "
         "at the measured difference (80% power).</p>\n";
    o << "<h3 id=\"figure-8\">The study's Figure 8, redone</h3>\n<div class=\"grid\">";
    for (size_t si = 0; si < key.sets.size(); ++si) {
        const StudySet& set = key.sets[si];
        const SetAnalysis& sa = a.sets[si];
        o << "<figure>";
        if (plotted)
            o << "<img src=\"" << plotsHref << "/" << plotStem(si) << ".png\" alt=\"" << html(set.name)
              << ": people's JOD per pattern with 95% intervals\">";
        o << "<table><tr><th>pattern</th><th>JOD (95%)</th><th>mean FLIP</th><th>RMS</th></tr>";
        for (size_t i = 0; i < set.crops.size(); ++i)
            o << "<tr><td>" << patternHeader(set.crops[i].pattern) << "</td><td>"
              << fmt("%+.2f <small>(%+.2f – %+.2f)</small>", sa.score[i], sa.lo95[i], sa.hi95[i]) << "</td><td>"
              << fmt("%.4f", set.crops[i].flip) << "</td><td>" << fmt("%.4g", set.crops[i].rms) << "</td></tr>";
        o << "</table><figcaption>" << html(set.name) << fmt(", %u spp; ", set.spp) << sa.observers
          << " observers; Kendall τ of people's order with FLIP's " << fmt("%.2f", sa.kendallFlip) << ", with RMS's "
          << fmt("%.2f", sa.kendallRms) << "</figcaption></figure>";
    }
    o << "</div>\n<p class=\"note\" id=\"perceptual-agreement\">";
    if (a.agreementPairs == 0)
        o << "People ordered no pair (no observer kept). Observers: ";
    else
        o << "People and mean FLIP order " << fmt("%.0f%%", 100 * a.agreementFlip) << " of " << a.agreementPairs
          << " pairs the same way (RMS: " << fmt("%.0f%%", 100 * a.agreementRms) << "). Observers: ";
    for (size_t i = 0; i < a.screens.size(); ++i) {
        const auto& s = a.screens[i];
        o << (i ? ", " : "") << html(s.observer) << (s.excluded ? " (<strong>excluded</strong>: " + html(s.reason) + ")" : "");
    }
    o << ".</p>\n";
    return o.str();
}

std::string withPeopleVerdict(const std::string& cell, const ReportInputs& in, const std::string& scene,
                              const std::string& region, const std::string& p, const std::string& q) {
    if (in.studyDir.empty() || region.empty() || cell.size() < 5 || !cell.ends_with("</td>")) return cell;
    // One analysis per study folder and report (the table asks once per cell).
    struct Cached {
        std::string dir;
        StudyKey key;
        StudyAnalysis analysis;
        bool ok = false;
    };
    static Cached cache;
    if (cache.dir != in.studyDir) {
        cache = Cached{};
        cache.dir = in.studyDir;
        try {
            cache.key = loadStudyKey(in.studyDir);
            cache.analysis = analyseStudy(cache.key, loadVotes({(fs::path(in.studyDir) / kStudyVotesDir).string()}, cache.key));
            cache.ok = true;
        } catch (const std::exception&) {
            // perceptualStudyHtml names the error; the cell stays FLIP's
        }
    }
    if (!cache.ok) return cell;
    for (size_t si = 0; si < cache.key.sets.size(); ++si) {
        const StudySet& set = cache.key.sets[si];
        if (set.scene != scene || set.region != region) continue;
        for (const auto& v : cache.analysis.sets[si].pairs) {
            const std::string &a = set.crops[v.a].pattern, &b = set.crops[v.b].pattern;
            if (!((a == p && b == q) || (a == q && b == p))) continue;
            const double sign = a == p ? 1 : -1; // oriented A = p: a positive difference prefers A
            const double d = sign * v.difference, lo = sign > 0 ? v.lo95 : -v.hi95, hi = sign > 0 ? v.hi95 : -v.lo95;
            std::string word = pairVerdictName(v.verdict);
            if (v.verdict == PairVerdictKind::PreferredA || v.verdict == PairVerdictKind::PreferredB)
                word = ((v.verdict == PairVerdictKind::PreferredA) == (a == p) ? p : q) + " PREFERRED";
            return cell.substr(0, cell.size() - 5) +
                   fmt("<br><span class=\"people\">people: %+.2f JOD <small>(%+.2f – %+.2f)</small> <strong>%s</strong> "
                       "<small>%d observers, <a href=\"#perceptual\">%u spp</a></small></span></td>",
                       d, lo, hi, html(word).c_str(), v.observers, set.spp);
        }
    }
    return cell;
}

std::string perceptualStudyHtml(const ReportInputs& in) {
    if (!in.matrix || in.matrix->perceptual.sets.empty()) return "";
    std::ostringstream o;
    o << "<h2 id=\"perceptual\">The study's perceptual half: people</h2>\n";
    if (in.studyDir.empty() && !fs::exists(fs::path(in.reportDir) / kStudyFolder / "index.html")) {
        o << "<p id=\"perceptual-status\">No votes given, and no experiment folder here: a run of the matrix "
             "writes it (a <code>--merge</code> does not); <code>--study FOLDER</code> adds its votes.</p>\n";
        return o.str();
    }
    if (in.studyDir.empty()) {
        o << "<p id=\"perceptual-status\">No votes yet. The ranking experiment is in <a href=\"" << kStudyFolder
          << "/index.html\">" << kStudyFolder
          << "/</a>; copy it out of the report, collect votes (README: <em>The perceptual experiment</em>) and give "
             "the folder with <code>--study</code> to a run or a <code>--merge</code>.</p>\n";
        return o.str();
    }
    try {
        const StudyKey key = loadStudyKey(in.studyDir);
        const auto votes = loadVotes({(fs::path(in.studyDir) / kStudyVotesDir).string()}, key);
        const StudyAnalysis a = analyseStudy(key, votes);
        o << "<p id=\"perceptual-status\">" << votes.size() << " observers' votes, " << a.included
          << " kept (a failed control or a reversed repeat excludes: README).</p>\n";
        o << studyFigureHtml(key, a, (fs::path(in.reportDir) / "plots").string(), "plots");
    } catch (const std::exception& e) {
        o << "<p id=\"perceptual-status\" class=\"FAIL\">The votes could not be read: " << html(e.what()) << "</p>\n";
    }
    return o.str();
}

int analyseStudyCommand(const std::string& folder, const std::vector<std::string>& extraVotes) {
    try {
        const StudyKey key = loadStudyKey(folder);
        std::vector<std::string> sources;
        const fs::path own = fs::path(folder) / kStudyVotesDir;
        if (fs::is_directory(own)) sources.push_back(own.string());
        sources.insert(sources.end(), extraVotes.begin(), extraVotes.end());
        const auto votes = loadVotes(sources, key);
        if (votes.empty()) {
            std::cerr << "stipple-validate: --analyse-study: no votes in " << own.string() << " or the files given\n";
            return 3;
        }
        const StudyAnalysis a = analyseStudy(key, votes);
        const std::string text = studyAnalysisText(key, a);
        std::cout << text;
        const fs::path out = fs::path(folder) / "analysis";
        fs::create_directories(out);
        writeTextFile((out / "analysis.json").string(), studyAnalysisJson(key, a));
        writeTextFile((out / "analysis.txt").string(), text);
        const std::string body = studyFigureHtml(key, a, (out / "plots").string(), "plots");
        writeTextFile((out / "index.html").string(),
                      "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>Perceptual experiment " +
                          html(key.study) +
                          "</title><style>body{font:15px/1.4 system-ui,sans-serif;margin:1em}table{border-collapse:"
                          "collapse}td,th{border:1px solid #ccc;padding:3px 6px}.grid{display:flex;flex-wrap:wrap;"
                          "gap:1em}.sw{display:inline-block;width:.8em;height:.8em;margin-right:.3em}</style></head>"
                          "<body><h1>Perceptual experiment of " +
                          html(key.matrix) + "</h1>\n" + body + "</body></html>\n");
        std::cout << "analysis: " << (out / "index.html").string() << "\n";
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "stipple-validate: --analyse-study: " << e.what() << "\n";
        return 3;
    }
}

} // namespace stipple::validation
