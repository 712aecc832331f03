// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// stipple-citygen: writes the Italian City's geometry (binary PLY prototypes + an includable YAML of instances).
//   stipple-citygen [--seed N] [--out DIR] [--name NAME] | --version
#include "town.h"

#include <stipple/version.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

namespace {

int usage(const char* msg, const char* arg) {
    std::fprintf(stderr, "stipple-citygen: %s%s%s\n", msg, arg ? ": " : "", arg ? arg : "");
    std::fprintf(stderr,
                 "usage: stipple-citygen [--seed N] [--out DIR] [--name NAME] | --version\n"
                 "  writes DIR/NAME.yaml and DIR/NAME/*.ply (defaults: seed 1, DIR ., NAME italian-city-town)\n");
    return 2;
}

} // namespace

int main(int argc, char** argv) {
    unsigned long long seed = 1;
    std::string out = ".", name = "italian-city-town";
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "-h" || a == "--help") return usage("help", nullptr), 0;
        if (a == "--version") return std::printf("%s\n", stipple::versionLine("stipple-citygen").c_str()), 0;
        if (i + 1 >= argc) return usage("missing value after", argv[i]);
        const char* v = argv[++i];
        if (a == "--seed") {
            char* end = nullptr;
            errno = 0;
            seed = std::strtoull(v, &end, 10);
            if (!*v || *end || *v == '-' || *v == '+' || errno == ERANGE)
                return usage("--seed expects an integer in [0, 2^64), got", v);
        } else if (a == "--out") {
            out = v;
        } else if (a == "--name") {
            name = v;
            if (name.empty() || name.find('/') != std::string::npos)
                return usage("--name expects a plain file stem, got", v);
        } else {
            return usage("unknown argument", argv[i - 1]);
        }
    }
    try {
        auto stats = stipple::citygen::generateTown(seed, out, name);
        std::printf("stipple-citygen: seed %llu: %llu instances, %llu triangles after instancing, "
                    "%llu prototype triangles in %llu PLY files -> %s/%s.yaml\n",
                    seed, (unsigned long long)stats.instances, (unsigned long long)stats.instancedTriangles,
                    (unsigned long long)stats.prototypeTriangles, (unsigned long long)stats.plyFiles, out.c_str(),
                    name.c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "stipple-citygen: %s\n", e.what());
        return 1;
    }
    return 0;
}
