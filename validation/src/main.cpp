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
#include <vector>

#include "baseline.h"
#include "checks.h"
#include "matrix.h"
#include "merge.h"
#include "report.h"
#include "results.h"
#include "runner.h"
#include "shard_fingerprint.h"

#include <stipple/render/renderer.h>
#include <stipple/version.h>
#include "verdicts_report.h"

using namespace stipple::validation;
namespace fs = std::filesystem;

namespace {

constexpr int kExitChecksFailed = 1, kExitUsage = 2, kExitError = 3;

const char* kUsage =
    "usage: stipple-validate MATRIX.yaml [-o DIR] [--threads T] [--cache DIR] [--baseline results.json]\n"
    "                        [--shard i/n] [--references-only] [--merge DIR1 DIR2 ...]\n"
    "       stipple-validate --version | --help\n"
    "  -o DIR             report folder (default: report)\n"
    "  --threads T        render threads (default: the matrix's, else all hardware threads)\n"
    "  --cache DIR        reference cache (default: the matrix's 'cache', else DIR/../.stipple-cache)\n"
    "  --baseline FILE    compare with a stored results.json: RMS beyond the intervals or time beyond the\n"
    "                     matrix's baseline.time_factor fails\n"
    "  --shard i/n        run the i-th of n deterministic subsets of the (scene, spp, seed) groups; checks are\n"
    "                     left to --merge\n"
    "  --references-only  make the references (of this shard's scenes) in the cache and stop\n"
    "  --merge DIR...     combine shard report folders into the report a single run makes\n"
    "exit status: 0 all checks pass, 1 a check or the baseline failed, 2 bad arguments or matrix, 3 other error\n";

struct Args {
    std::string matrix, out = "report", cache, baseline;
    int threads = 0, shardIndex = 1, shardCount = 1;
    bool referencesOnly = false;
    std::vector<std::string> merge;
};

[[noreturn]] void usageError(const std::string& what) {
    std::cerr << "stipple-validate: " << what << "\n" << kUsage;
    std::exit(kExitUsage);
}

Args parseArgs(int argc, char** argv) {
    Args a;
    auto value = [&](int& i) -> std::string {
        if (i + 1 >= argc) usageError(std::string(argv[i]) + " needs a value");
        return argv[++i];
    };
    for (int i = 1; i < argc; ++i) {
        std::string s = argv[i];
        if (s == "-h" || s == "--help") {
            std::cout << kUsage;
            std::exit(0);
        } else if (s == "--version") {
            std::cout << stipple::versionLine("stipple-validate") << "\n";
            std::exit(0);
        } else if (s == "-o" || s == "--output") a.out = value(i);
        else if (s == "--cache") a.cache = value(i);
        else if (s == "--baseline") a.baseline = value(i);
        else if (s == "--threads") {
            std::string v = value(i);
            char* end = nullptr;
            long t = std::strtol(v.c_str(), &end, 10);
            if (*end || t < 0 || t > 1024) usageError("--threads: expected a count in [0, 1024], got '" + v + "'");
            a.threads = int(t);
        } else if (s == "--shard") {
            std::string v = value(i);
            int n1 = 0, n2 = 0;
            char extra;
            if (std::sscanf(v.c_str(), "%d/%d%c", &n1, &n2, &extra) != 2 || n2 < 1 || n1 < 1 || n1 > n2)
                usageError("--shard: expected i/n with 1 ≤ i ≤ n, got '" + v + "'");
            a.shardIndex = n1;
            a.shardCount = n2;
        } else if (s == "--references-only") a.referencesOnly = true;
        else if (s == "--merge") {
            while (i + 1 < argc && argv[i + 1][0] != '-') a.merge.push_back(argv[++i]);
            if (a.merge.empty()) usageError("--merge needs at least one report folder");
        } else if (!s.empty() && s[0] == '-') usageError("unknown option '" + s + "'");
        else if (a.matrix.empty()) a.matrix = s;
        else usageError("unexpected argument '" + s + "' (the matrix is '" + a.matrix + "')");
    }
    if (a.matrix.empty()) usageError("no matrix file given");
    if (!a.merge.empty() && (a.shardCount > 1 || a.referencesOnly))
        usageError("--merge combines finished shards; it cannot be used with --shard or --references-only");
    return a;
}

} // namespace

int main(int argc, char** argv) {
    Args args = parseArgs(argc, argv);
    Matrix matrix;
    try {
        // Pattern and integrator names come from their owners: the loaded shim and the renderer's registry.
        matrix = loadMatrix(args.matrix, {stipple::render::patternNames(""), stipple::render::integratorNames()});
    } catch (const MatrixError& e) {
        std::cerr << "stipple-validate: " << e.what() << "\n";
        return kExitUsage;
    } catch (const std::exception& e) {
        std::cerr << "stipple-validate: " << e.what() << "\n";
        return kExitError;
    }
    const bool shard = args.shardCount > 1;
    std::string cache = !args.cache.empty() ? args.cache
                        : !matrix.cacheDir.empty()
                            ? matrix.cacheDir
                            : (fs::absolute(args.out).lexically_normal().parent_path() / ".stipple-cache").string();
    auto start = std::chrono::steady_clock::now();
    try {
        Results results;
        if (!args.merge.empty()) results = mergeShards(matrix, args.merge, args.out);
        else {
            RunOptions o;
            o.reportDir = args.out;
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
        writeReport(args.out, in);

        std::cout << "\n" << summaryTable(matrix, in.cells, matrix.spp.back());
        std::cout << "\nslopes of log RMS vs log spp (95% interval):\n";
        for (const auto& s : in.slopes)
            std::printf("  %-16s %-13s %7.3f ± %.3f\n", s.scene.c_str(), s.pattern.c_str(), s.fit.slope,
                        s.fit.slopeHalfWidth);
        if (!shard) std::cout << "\n" << verdictsText(in);
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
    } catch (const std::exception& e) {
        std::cerr << "stipple-validate: " << e.what() << "\n";
        return kExitError;
    }
}
