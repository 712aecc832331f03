// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// output_digest.cpp — one line that changes when any value the library serves changes: a 64-bit FNV-1a hash of
// the bits of every pattern's batch, stream and array calls (with and without the flags each pattern accepts) over
// arities 1-3, power-of-two and other N, several pixels (negative ones too), blocks past N, and of every pattern's
// limits. ci/doc_tables.py keys the documentation's sample-quality tables by it: a change that moves no served bit
// (a refactor, a faster kernel) leaves those tables true, one that moves any bit makes them stale. A table that
// measures a few patterns is keyed by those alone (--select), so a change to another pattern leaves it true.
//   stipple-link: shared
//   usage: shim_output_digest [--plain | --select NAME[+blue-noise],...]
//          prints "stipple output digest <16 hex digits>": every pattern with every flag it accepts, every pattern
//          without flags (--plain), or only the listed patterns with exactly the listed flags (as the tools spell
//          them; a flag the pattern refuses is hashed as its refusal)
#include <stipple/stipple.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

struct Fnv {
    uint64_t h = 0xcbf29ce484222325ull;
    void bytes(const void* p, size_t n) {
        const auto* b = static_cast<const unsigned char*>(p);
        for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 0x100000001b3ull;
    }
    void word(uint64_t v) { bytes(&v, sizeof v); }
};

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "shim_output_digest: %s: %s\n", what, stipple_last_error_message());
    std::exit(1);
}

void check(stipple_status s, const char* what) {
    if (s != STIPPLE_OK) fail(what);
}

// (pattern, flags) pairs to hash: every pattern with each flag set its limits accept, or those --select names.
std::vector<std::pair<uint32_t, uint32_t>> selection(int argc, char** argv) {
    std::vector<std::pair<uint32_t, uint32_t>> out;
    const bool plain = argc == 2 && std::strcmp(argv[1], "--plain") == 0;
    if (argc == 1 || plain) {
        uint32_t patterns = 0;
        check(stipple_pattern_count(&patterns), "stipple_pattern_count");
        for (uint32_t pattern = 0; pattern < patterns; ++pattern) {
            stipple_pattern_limits limits{};
            limits.struct_size = sizeof limits;
            check(stipple_pattern_get_limits(pattern, &limits), "stipple_pattern_get_limits");
            for (uint32_t flags : {0u, uint32_t(STIPPLE_SAMPLER_FLAG_BLUE_NOISE)})
                if ((flags & limits.flags) == flags && !(plain && flags)) out.emplace_back(pattern, flags);
        }
        return out;
    }
    if (argc != 3 || std::strcmp(argv[1], "--select") != 0) {
        std::fprintf(stderr, "usage: shim_output_digest [--plain | --select NAME[+blue-noise],...]\n");
        std::exit(2);
    }
    std::stringstream list(argv[2]);
    for (std::string name; std::getline(list, name, ',');) {
        uint32_t pattern = 0, flags = 0;
        if (stipple_pattern_parse(name.c_str(), &pattern, &flags) != STIPPLE_OK) fail(("--select " + name).c_str());
        out.emplace_back(pattern, flags);
    }
    if (out.empty()) fail("--select names no pattern");
    return out;
}

} // namespace

int main(int argc, char** argv) {
    Fnv fnv;
    const uint32_t ns[] = {1, 7, 16, 100, 256};
    const int32_t pixels[][2] = {{0, 0}, {5, -3}, {1000, 7}, {63, 64}};
    uint32_t lastPattern = ~0u;
    for (const auto& [pattern, flags] : selection(argc, argv)) {
        stipple_pattern_limits limits{};
        limits.struct_size = sizeof limits;
        check(stipple_pattern_get_limits(pattern, &limits), "stipple_pattern_get_limits");
        if (pattern != lastPattern) { // once per pattern
            // A selection is keyed by what its pairs serve: whether a flag is accepted shows below, as values or
            // as a refusal, so the flags a pattern accepts count only in the whole digest.
            stipple_pattern_limits keyed = limits;
            if (argc > 1) keyed.flags = 0;
            fnv.bytes(&keyed, sizeof keyed);
        }
        lastPattern = pattern;
        if ((flags & limits.flags) != flags) { // a refused flag: the refusal is what the table shows
            fnv.word(0xfeedull ^ pattern);
            continue;
        }
        {
            for (uint32_t n : ns) {
                stipple_dimension_desc dims[3]{};
                for (uint32_t a = 0; a < 3; ++a) {
                    dims[a].struct_size = sizeof dims[a];
                    dims[a].arity = a + 1;
                    dims[a].count = a == 1 && 3 * n <= limits.max_set_size ? 3 : 1;
                }
                stipple_sampler_desc desc{};
                desc.struct_size = sizeof desc;
                desc.pattern = pattern;
                desc.samples_per_pixel = n;
                desc.dimension_count = 3;
                desc.dimensions = dims;
                desc.seed = 0xba77e12ull + n;
                desc.flags = flags;
                stipple_sampler sampler = nullptr;
                check(stipple_sampler_create(&desc, &sampler), "stipple_sampler_create");
                std::vector<float> out;
                for (const auto& p : pixels) {
                    const uint32_t x = uint32_t(p[0]), y = uint32_t(p[1]);
                    for (uint32_t d = 0; d < 3; ++d) {
                        out.assign(size_t(n) * dims[d].count * dims[d].arity, 0.0f);
                        check(stipple_sampler_fill_pixel(sampler, x, y, d, out.data(), out.size()), "fill_pixel");
                        fnv.bytes(out.data(), out.size() * sizeof(float));
                    }
                    for (uint32_t arity = 1; arity <= 3; ++arity) {
                        out.assign(size_t(3) * n * arity, 0.0f); // blocks 0, 1 and 2
                        check(stipple_sampler_stream_fill(sampler, x, y, 0, 3 * n, 5, arity, out.data(), out.size()),
                              "stream_fill");
                        fnv.bytes(out.data(), out.size() * sizeof(float));
                        if (2 * n <= limits.max_set_size) {
                            out.assign(size_t(2) * n * 2 * arity, 0.0f); // array 1 with k = 2, blocks 0 and 1
                            check(stipple_sampler_array_fill(sampler, x, y, 0, 2 * n, 1, arity, 2, out.data(),
                                                             out.size()),
                                  "array_fill");
                            fnv.bytes(out.data(), out.size() * sizeof(float));
                        }
                    }
                    float independent[4];
                    check(stipple_sampler_sample_independent(sampler, x, y, n + 1, 9, independent, 4),
                          "sample_independent");
                    fnv.bytes(independent, sizeof independent);
                }
                stipple_sampler_release(sampler);
            }
        }
    }
    std::printf("stipple output digest %016llx\n", static_cast<unsigned long long>(fnv.h));
    return 0;
}
