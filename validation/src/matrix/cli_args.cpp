// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "matrix/cli_args.h"

#include <stipple/render/input_limits.h>

#include <cstdio>
#include <cstdlib>

namespace stipple::validation {

const char* const kValidateUsage =
    "usage: stipple-validate MATRIX.yaml [-o DIR] [--threads T] [--cache DIR] [--baseline results.json]\n"
    "                        [--shard i/n] [--references-only] [--quiet] [--merge DIR1 DIR2 ...]\n"
    "                        [--renderer-command FILE (--allow-renderer | --renderer PROGRAM)]\n"
    "                        [--study FOLDER]\n"
    "       stipple-validate --serve-study FOLDER [--port N]\n"
    "       stipple-validate --analyse-study FOLDER [VOTES.json | VOTES-FOLDER ...]\n"
    "       stipple-validate --version | --help\n"
    "Runs the matrix's scenes x patterns x spp x seeds, measures RMS against cached references and render time,\n"
    "checks the matrix's claims and writes an HTML report. An option's value may follow as the next argument or\n"
    "after '=' (--threads=4).\n"
    "  -o, --output DIR   report folder (default: report). Replaced whole by each run; only an empty folder or\n"
    "                     one stipple-validate made (it holds .stipple-report) is accepted. A symlink is followed\n"
    "  --threads T        render threads, 0..1024 (default: the matrix's 'threads', else 0 = all hardware threads)\n"
    "  --cache DIR        reference cache (default: the matrix's 'cache', else .stipple-cache beside the report\n"
    "                     folder)\n"
    "  --baseline FILE    compare with a stored results.json (default: none): RMS beyond the intervals or time\n"
    "                     beyond the matrix's baseline.time_factor fails\n"
    "  --shard i/n        run the i-th of n deterministic subsets of the (scene, spp, seed) groups; checks are\n"
    "                     left to --merge (default: 1/1, the whole matrix)\n"
    "  --references-only  make the references (of this shard's scenes) in the cache and stop (default: off)\n"
    "  --merge DIR...     combine shard report folders into the report a single run makes (default: off)\n"
    "  --renderer-command FILE  the command templates a matrix may run (one argument per line, a blank line\n"
    "                     between templates): a matrix's external renderer command runs only when byte-equal to one\n"
    "  --allow-renderer   run the matrix's external renderer commands that are templates of FILE (default: off; a\n"
    "                     matrix alone runs no program)\n"
    "  --renderer PROGRAM run PROGRAM in place of the first argument of the matrix's commands whose other arguments\n"
    "                     are a template of FILE (default: none)\n"
    "  --renderer-timeout S  seconds one image of an external renderer may take; past it the program and its\n"
    "                     children are killed and the cell named (default: the matrix's renderer timeout, else none)\n"
    "  --study FOLDER     a perceptual experiment folder (made by a run of a matrix with 'perceptual'): its votes/\n"
    "                     fill the report's perceptual block and Figure 8 (default: none)\n"
    "  --serve-study FOLDER  serve the experiment on 127.0.0.1 and store each observer's votes in FOLDER/votes\n"
    "  --port N           --serve-study's port, 0..65535 (default: 8765; 0: any free port)\n"
    "  --analyse-study FOLDER  scale FOLDER/votes (and any votes files or folders given after it) and write\n"
    "                     FOLDER/analysis/\n"
    "  -q, --quiet        no progress, tables or summary: only warnings, errors and the exit status (default: off)\n"
    "  -h, --help         this text; --version: the version line\n"
    "exit status: 0 all checks pass, 1 a check or the baseline failed, 2 bad arguments or matrix, 3 other error\n";

Args parseArgs(const std::vector<std::string>& argv) {
    const size_t argc = argv.size();
    Args a;
    for (size_t i = 0; i < argc; ++i) {
        std::string s = argv[i];
        // "--opt=value" is "--opt value"; "-o=x" is not split (a short option takes its value apart).
        std::optional<std::string> attached;
        if (s.starts_with("--"))
            if (const size_t eq = s.find('='); eq != std::string::npos) {
                attached = s.substr(eq + 1);
                s.resize(eq);
            }
        // A path or count given empty is an error, never "the default".
        auto value = [&]() -> std::string {
            std::string v;
            if (attached)
                v = *attached;
            else if (i + 1 >= argc)
                throw UsageError(s + " needs a value");
            else
                v = argv[++i];
            if (v.empty()) throw UsageError(s + ": expected a value, got an empty one");
            return v;
        };
        auto flag = [&] {
            if (attached) throw UsageError(s + " takes no value, got '" + *attached + "'");
        };
        if (s == "-h" || s == "--help") {
            flag();
            a.help = true;
            return a;
        } else if (s == "--version") {
            flag();
            a.version = true;
            return a;
        } else if (s == "-o" || s == "--output")
            a.out = value();
        else if (s == "--cache")
            a.cache = value();
        else if (s == "--baseline")
            a.baseline = value();
        else if (s == "--threads") {
            std::string v = value();
            char* end = nullptr;
            long t = std::strtol(v.c_str(), &end, 10);
            if (*end || t < 0 || t > render::limits::kMaxThreads)
                throw UsageError("--threads: expected a count in [0, " + std::to_string(render::limits::kMaxThreads) +
                                 "], got '" + v + "'");
            a.threads = int(t);
        } else if (s == "--shard") {
            std::string v = value();
            int n1 = 0, n2 = 0;
            char extra;
            if (std::sscanf(v.c_str(), "%d/%d%c", &n1, &n2, &extra) != 2 || n2 < 1 || n1 < 1 || n1 > n2)
                throw UsageError("--shard: expected i/n with 1 ≤ i ≤ n, got '" + v + "'");
            a.shardIndex = n1;
            a.shardCount = n2;
        } else if (s == "--references-only") {
            flag();
            a.referencesOnly = true;
        } else if (s == "-q" || s == "--quiet") {
            flag();
            a.quiet = true;
        } else if (s == "--allow-renderer") {
            flag();
            a.allowRenderer = true;
        } else if (s == "--renderer") {
            a.renderer = value();
        } else if (s == "--study") {
            a.study = value();
        } else if (s == "--serve-study") {
            a.serveStudy = value();
        } else if (s == "--port") {
            const std::string v = value();
            char* end = nullptr;
            const long p = std::strtol(v.c_str(), &end, 10);
            if (*end || p < 0 || p > 65535) throw UsageError("--port: expected a port in [0, 65535], got '" + v + "'");
            a.port = int(p);
        } else if (s == "--analyse-study") {
            a.analyseStudy = value();
            while (i + 1 < argc && !argv[i + 1].empty() && argv[i + 1][0] != '-') a.extraVotes.push_back(argv[++i]);
        } else if (s == "--renderer-timeout") {
            const std::string v = value();
            char* end = nullptr;
            const double t = std::strtod(v.c_str(), &end);
            if (*end || !(t > 0 && t <= 1e6))
                throw UsageError("--renderer-timeout: expected seconds in (0, 1000000], got '" + v + "'");
            a.rendererTimeout = t;
        } else if (s == "--renderer-command") {
            a.rendererCommand = value();
        } else if (s == "--merge") {
            if (attached) a.merge.push_back(value());
            while (i + 1 < argc && (argv[i + 1].empty() || argv[i + 1][0] != '-')) {
                if (argv[i + 1].empty()) throw UsageError("--merge: expected a folder, got an empty argument");
                a.merge.push_back(argv[++i]);
            }
            if (a.merge.empty()) throw UsageError("--merge needs at least one report folder");
        } else if (!s.empty() && s[0] == '-')
            throw UsageError("unknown option '" + argv[i] + "'");
        else if (s.empty())
            throw UsageError("an empty argument where the matrix file was expected");
        else if (a.matrix.empty())
            a.matrix = s;
        else
            throw UsageError("unexpected argument '" + s + "' (the matrix is '" + a.matrix + "')");
    }
    if (!a.serveStudy.empty() || !a.analyseStudy.empty()) {
        if (!a.matrix.empty() || (!a.serveStudy.empty() && !a.analyseStudy.empty()))
            throw UsageError("--serve-study and --analyse-study take an experiment folder only, one of them");
        return a;
    }
    if (a.matrix.empty()) throw UsageError("no matrix file given");
    if ((a.allowRenderer || !a.renderer.empty()) != !a.rendererCommand.empty())
        throw UsageError(a.rendererCommand.empty()
                             ? "--allow-renderer and --renderer need --renderer-command FILE: the templates a matrix's "
                               "command must equal (a matrix cannot add arguments of its own)"
                             : "--renderer-command needs --allow-renderer or --renderer PROGRAM");
    if (a.allowRenderer && !a.renderer.empty())
        throw UsageError("--allow-renderer runs the matrix's programs, --renderer PROGRAM replaces them: give one");
    if (!a.merge.empty() && (a.shardCount > 1 || a.referencesOnly))
        throw UsageError("--merge combines finished shards; it cannot be used with --shard or --references-only");
    return a;
}

} // namespace stipple::validation
