// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// stipple-validate: runs a YAML matrix of scenes × patterns × spp × seeds through the renderer in-process,
// measures RMS against a cached reference and render time, checks the matrix's claims and writes a report.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <optional>
#include <tuple>
#include <vector>

#include <stipple/render/temp_files.h>

#include "claims/baseline.h"
#include "claims/checks.h"
#include "matrix/external_command.h"
#include "run/external_renderer.h"
#include "matrix/cli_args.h"
#include "matrix/matrix.h"
#include "claims/identical_renders.h"
#include "run/merge.h"
#include "run/preflight.h"
#include "run/progress.h"
#include "report/report_publish.h"
#include "report/report.h"
#include "run/results.h"
#include "run/runner.h"
#include "report/verdicts_report.h"
#include "perceptual/experiment.h"
#include "perceptual/study_report.h"
#include "perceptual/study_server.h"
#include "perceptual/votes.h"

#include <stipple/render/renderer.h>
#include <stipple/version.h>

using namespace stipple::validation;
namespace fs = std::filesystem;

namespace {

constexpr int kExitChecksFailed = 1, kExitUsage = 2, kExitError = 3;

} // namespace

int main(int argc, char** argv) {
    stipple::render::installTempCleanupOnSignals();
    Args args;
    try {
        args = parseArgs(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const UsageError& e) {
        std::cerr << "stipple-validate: " << e.what() << "\n" << kValidateUsage;
        return kExitUsage;
    }
    if (args.help) {
        std::cout << kValidateUsage;
        return 0;
    }
    if (args.version) {
        std::cout << stipple::versionLine("stipple-validate") << "\n";
        return 0;
    }
    if (args.quiet) {
        // Nothing on stdout (tables, summary), no progress; warnings and errors still go to stderr.
        std::cout.setstate(std::ios::badbit);
        if (!std::freopen("/dev/null", "w", stdout)) std::fclose(stdout);
        Progress::setQuiet(true);
    }
    if (!args.serveStudy.empty()) return serveStudy(args.serveStudy, args.port);
    if (!args.analyseStudy.empty()) return analyseStudyCommand(args.analyseStudy, args.extraVotes);
    if (!args.study.empty()) {
        // Bad votes are found now, not after the renders.
        try {
            const StudyKey key = loadStudyKey(args.study);
            loadVotes({(fs::path(args.study) / kStudyVotesDir).string()}, key);
        } catch (const std::exception& e) {
            std::cerr << "stipple-validate: --study: " << e.what() << "\n";
            return kExitUsage;
        }
    }
    Matrix matrix;
    try {
        // Pattern and integrator names come from their owners: the loaded shim and the renderer's registry.
        matrix = loadMatrix(args.matrix, {stipple::render::patternNames(""), stipple::render::integratorNames()});
    } catch (const MatrixError& e) {
        std::cerr << "stipple-validate: " << e.what() << "\n";
        return kExitUsage;
    } catch (const std::bad_alloc&) {
        std::cerr << "stipple-validate: " << args.matrix << ": out of memory while loading the matrix\n";
        return kExitUsage;
    } catch (const std::exception& e) {
        std::cerr << "stipple-validate: " << args.matrix << ": " << e.what() << "\n";
        return kExitUsage;
    }
    // External renderers: what the command line allows is checked against the matrix before anything runs.
    RendererPermission permission{args.allowRenderer, args.renderer, {}, args.rendererTimeout};
    if (!args.rendererCommand.empty() && args.merge.empty()) {
        try {
            permission.commands = readTrustedCommands(args.rendererCommand);
        } catch (const std::exception& e) {
            std::cerr << "stipple-validate: --renderer-command: " << e.what() << "\n";
            return kExitUsage;
        }
        bool external = false;
        for (const MatrixScene& s : matrix.scenes) {
            if (s.renderer.empty()) continue;
            external = true;
            if (const std::string why = checkRendererPermission(s, permission); !why.empty()) {
                std::cerr << "stipple-validate: " << why << "\n";
                return kExitUsage;
            }
        }
        // An option that checks nothing must not let a CI line pass.
        if (!external) {
            std::cerr << "stipple-validate: " << (args.renderer.empty() ? "--allow-renderer" : "--renderer")
                      << " was given but no scene of " << args.matrix << " has an external renderer\n";
            return kExitUsage;
        }
    }
    const bool shard = args.shardCount > 1;
    std::string cache = !args.cache.empty() ? args.cache
                        : !matrix.cacheDir.empty()
                            ? matrix.cacheDir
                            : (fs::absolute(args.out).lexically_normal().parent_path() / ".stipple-cache").string();
    // Fail fast: the baseline, the cache, the report folder and the scene files are checked before any rendering.
    std::map<std::string, std::string> unloadable;
    std::optional<ReportStaging> staging;
    try {
        PreflightInputs pre;
        pre.matrix = args.merge.empty() ? &matrix : nullptr;
        pre.cacheDir = args.merge.empty() ? cache : "";
        pre.baselinePath = args.baseline;
        pre.reportDir = args.referencesOnly ? "" : args.out;
        pre.mergeDirs = args.merge;
        pre.resultsMaxBytes = resultsFileByteLimit(matrix);
        unloadable = preflight(pre);
        if (!args.referencesOnly) staging.emplace(args.out);
    } catch (const std::exception& e) {
        std::cerr << "stipple-validate: " << e.what() << "\n";
        return kExitUsage;
    }
    for (const auto& [name, error] : unloadable)
        std::cerr << "stipple-validate: scene " << name << " cannot be loaded and will be skipped: " << error << "\n";
    const std::string reportDir = staging ? staging->dir() : args.out;
    auto start = std::chrono::steady_clock::now();
    try {
        Results results;
        if (!args.merge.empty())
            results = mergeShards(matrix, args.merge, reportDir);
        else {
            RunOptions o;
            o.unloadable = unloadable;
            o.reportDir = reportDir;
            o.cacheDir = cache;
            o.threads = args.threads;
            o.shardIndex = args.shardIndex;
            o.shardCount = args.shardCount;
            o.referencesOnly = args.referencesOnly;
            o.renderer = permission;
            results = runMatrix(matrix, o);
        }
        if (args.referencesOnly) {
            // Ready only when every scene's reference is: a failed one is named and the status says so.
            for (const auto& k : results.skipped)
                std::cerr << "stipple-validate: no reference for scene " << k.name << ": " << k.error << "\n";
            if (!results.skipped.empty()) return kExitError;
            std::cout << "references ready in " << cache << "\n";
            return 0;
        }
        double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

        ReportInputs in;
        in.matrix = &matrix;
        in.results = &results;
        in.cells = aggregate(results.rows);
        in.slopes = fitSlopes(results.rows, matrix);
        if (!shard) in.outcomes = evaluateChecks(matrix, results.rows, in.cells, in.slopes);
        in.wallSeconds = args.merge.empty() ? wall : 0;
        in.note = args.merge.size() == 1 ? "Written from the results of " + args.merge[0] + " (nothing rendered again)."
                  : !args.merge.empty() ? "Merged from " + std::to_string(args.merge.size()) + " shard folders."
                  : shard ? "Shard " + std::to_string(args.shardIndex) + "/" + std::to_string(args.shardCount) +
                                " only: checks are evaluated by --merge."
                          : "";
        for (const auto& k : results.skipped) in.note += " ERROR, scene skipped: " + k.error + ".";
        const std::vector<std::string> identical = identicalSeedRenders(results.rows);
        for (const auto& line : identical) in.note += " ERROR: " + line + ".";
        BaselineComparison baseline;
        if (!args.baseline.empty()) {
            Results base = readResultsJson(args.baseline, resultsFileByteLimit(matrix));
            sortRows(base.rows, matrix);
            baseline = compareToBaseline(in.cells, aggregate(base.rows), matrix.baselineTimeFactor);
            in.baseline = &baseline;
            in.baselinePath = args.baseline;
        }
        in.studyDir = args.study;
        if (args.merge.empty() && !shard) writeStudyExperiment(reportDir, matrix, results);
        writeReport(reportDir, in);
        staging->publish();

        std::cout << "\n" << summaryTable(matrix, in.cells, matrix.spp.back());
        std::cout << "\nslopes of log RMS vs log spp (95% interval):\n";
        for (const auto& s : in.slopes)
            std::printf("  %-16s %-13s %7.3f ± %.3f\n", s.scene.c_str(), s.pattern.c_str(), s.fit.slope,
                        s.fit.slopeHalfWidth);
        if (!shard) std::cout << "\n" << verdictsText(in);
        bool failed = false;
        if (shard)
            std::cout << "\nshard " << args.shardIndex << "/" << args.shardCount
                      << ": checks are evaluated when the shards are merged (--merge)\n";
        else if (!in.outcomes.empty()) {
            std::cout << "\nchecks:\n";
            for (const auto& o : in.outcomes) {
                std::cout << formatOutcome(o);
                failed |= o.failsRun;
            }
        }
        if (in.baseline) {
            std::cout << "\nbaseline " << args.baseline << ": " << (baseline.failed ? "FAIL" : "PASS") << " ("
                      << baseline.compared << " cells compared)\n";
            for (const auto& l : baseline.lines) std::cout << "  " << l << "\n";
            failed |= baseline.failed;
        }
        size_t failures = 0;
        for (const auto& o : in.outcomes) failures += o.failsRun;
        std::printf("\n%zu checks, %zu failed%s; %.1f s\nreport: %s\n", in.outcomes.size(), failures,
                    in.baseline ? (baseline.failed ? ", baseline failed" : ", baseline passed") : "", wall,
                    (fs::path(args.out) / "index.html").string().c_str());
        for (const auto& k : results.skipped) std::cerr << "stipple-validate: scene skipped: " << k.error << "\n";
        for (const auto& line : identical) std::cerr << "stipple-validate: " << line << "\n";
        if (!results.skipped.empty() || !identical.empty()) return kExitError;
        return failed ? kExitChecksFailed : 0;
    } catch (const std::bad_alloc&) {
        std::cerr << "stipple-validate: out of memory\n";
        return kExitError;
    } catch (const std::exception& e) {
        // A full disk often reaches here without errno (OIIO, gnuplot): name it when the report's or the cache's
        // file system is out of space.
        std::string note = stipple::render::fullDiskNote(args.out);
        if (note.empty()) note = stipple::render::fullDiskNote(cache);
        std::cerr << "stipple-validate: " << e.what() << note << "\n";
        return kExitError;
    }
}
