// stipple-validate: runs a YAML matrix of scenes × patterns × spp × seeds through the renderer in-process,
// measures RMS against a cached reference and render time, checks the matrix's claims and writes a report.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <set>
#include <string>
#include <tuple>
#include <optional>
#include <vector>

#include <stipple/render/temp_files.h>

#include "baseline.h"
#include "checks.h"
#include "cli_args.h"
#include "matrix.h"
#include "preflight.h"
#include "report_publish.h"
#include "report.h"
#include "results.h"
#include "runner.h"

using namespace stipple::validation;
namespace fs = std::filesystem;

namespace {

constexpr int kExitChecksFailed = 1, kExitUsage = 2, kExitError = 3;

// Combines the results.json of shard folders; every cell × seed of the matrix must be there exactly once.
Results mergeShards(const Matrix& m, const std::vector<std::string>& dirs, const std::string& out) {
    Results merged;
    merged.matrixName = m.name;
    std::set<std::tuple<std::string, std::string, uint32_t, uint64_t>> seen;
    for (const auto& dir : dirs) {
        Results r = readResultsJson((fs::path(dir) / "results.json").string());
        if (merged.rendererVersion.empty()) merged.rendererVersion = r.rendererVersion;
        else if (r.rendererVersion != merged.rendererVersion)
            throw std::runtime_error(dir + ": renderer version '" + r.rendererVersion + "' differs from '" +
                                     merged.rendererVersion + "' of the other shards");
        for (const auto& k : r.skipped) merged.skipped.push_back({k.name, dir + ": " + k.error});  // stays reported
        for (const auto& s : r.scenes) {
            bool known = false;
            for (const auto& k : merged.scenes) known |= k.name == s.name;
            if (!known) merged.scenes.push_back(s);
        }
        for (const auto& row : r.rows) {
            if (!seen.insert({row.scene, row.pattern, row.spp, row.seed}).second)
                throw std::runtime_error(dir + ": " + row.scene + " " + row.pattern + " " + std::to_string(row.spp) +
                                         " spp seed " + std::to_string(row.seed) + " appears in two shards");
            merged.rows.push_back(row);
        }
        // Crops travel with the shard that rendered them.
        fs::path crops = fs::path(dir) / "crops";
        if (fs::is_directory(crops) && fs::absolute(crops) != fs::absolute(fs::path(out) / "crops")) {
            fs::create_directories(fs::path(out) / "crops");
            for (const auto& e : fs::directory_iterator(crops))
                fs::copy_file(e.path(), fs::path(out) / "crops" / e.path().filename(),
                              fs::copy_options::overwrite_existing);
        }
    }
    size_t missing = 0;
    std::string example;
    for (const auto& s : m.scenes) {
        if (std::any_of(merged.skipped.begin(), merged.skipped.end(), [&](const SkippedScene& k) { return k.name == s.name; }))
            continue;  // its rows are missing because it failed, which the merged run reports as an error
        for (const auto& p : m.patterns)
            for (uint32_t spp : m.spp)
                for (uint64_t seed : m.seeds)
                    if (!seen.count({s.name, p, spp, seed}) && missing++ == 0)
                        example = s.name + " " + p + " " + std::to_string(spp) + " spp seed " + std::to_string(seed);
    }
    if (missing)
        throw std::runtime_error("merge: " + std::to_string(missing) + " cell × seed rows of " + m.path +
                                 " are in none of the folders (e.g. " + example + "): did every shard finish?");
    std::vector<SceneInfo> ordered;
    for (const auto& s : m.scenes)
        for (const auto& k : merged.scenes)
            if (k.name == s.name) ordered.push_back(k);
    merged.scenes = ordered;
    sortRows(merged.rows, m);
    return merged;
}

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
    Matrix matrix;
    try {
        matrix = loadMatrix(args.matrix);
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
        if (!args.merge.empty()) results = mergeShards(matrix, args.merge, reportDir);
        else {
            RunOptions o;
            o.unloadable = unloadable;
            o.reportDir = reportDir;
            o.cacheDir = cache;
            o.threads = args.threads;
            o.shardIndex = args.shardIndex;
            o.shardCount = args.shardCount;
            o.referencesOnly = args.referencesOnly;
            results = runMatrix(matrix, o);
        }
        if (args.referencesOnly) {
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
        in.note = !args.merge.empty() ? "Merged from " + std::to_string(args.merge.size()) + " shard folders."
                  : shard ? "Shard " + std::to_string(args.shardIndex) + "/" + std::to_string(args.shardCount) +
                                " only: checks are evaluated by --merge."
                          : "";
        for (const auto& k : results.skipped) in.note += " ERROR, scene skipped: " + k.error + ".";
        BaselineComparison baseline;
        if (!args.baseline.empty()) {
            Results base = readResultsJson(args.baseline);
            sortRows(base.rows, matrix);
            baseline = compareToBaseline(in.cells, aggregate(base.rows), matrix.baselineTimeFactor);
            in.baseline = &baseline;
            in.baselinePath = args.baseline;
        }
        writeReport(reportDir, in);
        staging->publish();

        std::cout << "\n" << summaryTable(matrix, in.cells, matrix.spp.back());
        std::cout << "\nslopes of log RMS vs log spp (95% interval):\n";
        for (const auto& s : in.slopes)
            std::printf("  %-16s %-13s %7.3f ± %.3f\n", s.scene.c_str(), s.pattern.c_str(), s.fit.slope,
                        s.fit.slopeHalfWidth);
        bool failed = false;
        if (shard) std::cout << "\nshard " << args.shardIndex << "/" << args.shardCount
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
        if (!results.skipped.empty()) return kExitError;
        return failed ? kExitChecksFailed : 0;
    } catch (const std::bad_alloc&) {
        std::cerr << "stipple-validate: out of memory\n";
        return kExitError;
    } catch (const std::exception& e) {
        std::cerr << "stipple-validate: " << e.what() << "\n";
        return kExitError;
    }
}
