#include "cli_args.h"

#include <cstdio>
#include <cstdlib>

namespace stipple::validation {

const char* const kValidateUsage =
    "usage: stipple-validate MATRIX.yaml [-o DIR] [--threads T] [--cache DIR] [--baseline results.json]\n"
    "                        [--shard i/n] [--references-only] [--merge DIR1 DIR2 ...]\n"
    "                        [--allow-renderer | --renderer PROGRAM]\n"
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
    "  --allow-renderer   run the external renderer commands the matrix names (a matrix alone runs no program)\n"
    "  --renderer PROGRAM run PROGRAM as the external renderer, in place of the program of the matrix's commands\n"
    "exit status: 0 all checks pass, 1 a check or the baseline failed, 2 bad arguments or matrix, 3 other error\n";

Args parseArgs(const std::vector<std::string>& argv) {
    const size_t argc = argv.size();
    Args a;
    auto value = [&](size_t& i) -> std::string {
        if (i + 1 >= argc) throw UsageError(argv[i] + " needs a value");
        return argv[++i];
    };
    for (size_t i = 0; i < argc; ++i) {
        std::string s = argv[i];
        if (s == "-h" || s == "--help") {
            a.help = true;
            return a;
        } else if (s == "--version") {
            a.version = true;
            return a;
        } else if (s == "-o" || s == "--output")
            a.out = value(i);
        else if (s == "--cache")
            a.cache = value(i);
        else if (s == "--baseline")
            a.baseline = value(i);
        else if (s == "--threads") {
            std::string v = value(i);
            char* end = nullptr;
            long t = std::strtol(v.c_str(), &end, 10);
            if (v.empty() || *end || t < 0 || t > 1024)
                throw UsageError("--threads: expected a count in [0, 1024], got '" + v + "'");
            a.threads = int(t);
        } else if (s == "--shard") {
            std::string v = value(i);
            int n1 = 0, n2 = 0;
            char extra;
            if (std::sscanf(v.c_str(), "%d/%d%c", &n1, &n2, &extra) != 2 || n2 < 1 || n1 < 1 || n1 > n2)
                throw UsageError("--shard: expected i/n with 1 ≤ i ≤ n, got '" + v + "'");
            a.shardIndex = n1;
            a.shardCount = n2;
        } else if (s == "--references-only")
            a.referencesOnly = true;
        else if (s == "--allow-renderer")
            a.allowRenderer = true;
        else if (s == "--renderer") {
            a.renderer = value(i);
            if (a.renderer.empty()) throw UsageError("--renderer: expected a program, got ''");
        } else if (s == "--merge") {
            while (i + 1 < argc && (argv[i + 1].empty() || argv[i + 1][0] != '-')) a.merge.push_back(argv[++i]);
            if (a.merge.empty()) throw UsageError("--merge needs at least one report folder");
        } else if (!s.empty() && s[0] == '-')
            throw UsageError("unknown option '" + s + "'");
        else if (a.matrix.empty())
            a.matrix = s;
        else
            throw UsageError("unexpected argument '" + s + "' (the matrix is '" + a.matrix + "')");
    }
    if (a.matrix.empty()) throw UsageError("no matrix file given");
    if (!a.merge.empty() && (a.shardCount > 1 || a.referencesOnly))
        throw UsageError("--merge combines finished shards; it cannot be used with --shard or --references-only");
    return a;
}

} // namespace stipple::validation
