// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// abi_cost.cpp — ns per value of fill_pixel and stream_fill through the C ABI only, for whichever libstipple the
// loader finds. It uses nothing newer than ABI 1.1, so one binary times any build since: run it against two
// libraries in alternation (abi_cost_compare.py) to compare a pattern's cost across versions in one session.
//
//   shim_abi_cost [--patterns a,b,...] [--arities 1,2,3] [--ns 16,256,4096] [--reps R (5)]
//
// Prints one line per pattern x arity x N: "pattern arity N fill_pixel_ns stream_fill_ns" (ns per value, the best
// of R timed passes over enough pixels for about 4M values each; the best, since load only adds time).
//
// stipple-link: shared
#include <stipple/stipple.h>
#include <stipple/stipple.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace {

[[noreturn]] void fail(const std::string& message) {
    std::fprintf(stderr, "shim_abi_cost: %s\n", message.c_str());
    std::exit(2);
}

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream stream(text);
    for (std::string item; std::getline(stream, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

uint32_t parseCount(const std::string& text, const char* what) {
    char* end = nullptr;
    const unsigned long value = std::strtoul(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || value == 0 || value > (1u << 20))
        fail(std::string("bad ") + what + " \"" + text + "\" (a whole number in 1..2^20)");
    return uint32_t(value);
}

// A one-dimension sampler through the kit (stipple.hpp); the timed calls use its handle (the ABI is what is timed).
stipple::Sampler makeSampler(const std::string& pattern, uint32_t arity, uint32_t n) {
    stipple::Sampler sampler;
    const stipple::Status status = stipple::Sampler::create(sampler, pattern, n, 7, {{arity, 1, ""}});
    if (!status.ok()) fail("creating a " + pattern + " sampler: " + status.message());
    return sampler;
}

// Best ns per value over `reps` passes of `call(pixel)`, each pass over `pixels` pixels of `values` values.
template <class Call>
double bestNsPerValue(int reps, uint32_t pixels, uint32_t values, Call&& call) {
    double best = 1e300;
    for (int rep = 0; rep < reps; ++rep) {
        const auto start = std::chrono::steady_clock::now();
        for (uint32_t p = 0; p < pixels; ++p) call(p);
        const std::chrono::duration<double, std::nano> spent = std::chrono::steady_clock::now() - start;
        best = std::min(best, spent.count() / (double(pixels) * values));
    }
    return best;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> patterns = {"independent", "stratified", "poisson", "sobol", "pmj02"};
    std::vector<uint32_t> arities = {1, 2, 3}, ns = {16, 256, 4096};
    int reps = 5;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (i + 1 >= argc) fail("\"" + arg + "\" needs a value");
        const std::string value = argv[++i];
        if (arg == "--patterns") {
            patterns = splitList(value);
        } else if (arg == "--arities" || arg == "--ns") {
            std::vector<uint32_t>& list = arg == "--ns" ? ns : arities;
            list.clear();
            for (const std::string& item : splitList(value)) list.push_back(parseCount(item, arg.c_str() + 2));
        } else if (arg == "--reps") {
            reps = int(parseCount(value, "reps"));
        } else {
            fail("unknown argument \"" + arg + "\" (see the comment at the top of abi_cost.cpp)");
        }
    }
    for (uint32_t arity : arities)
        if (arity > 3) fail("arity " + std::to_string(arity) + " (1..3)");
    for (const std::string& name : patterns) {
        uint32_t pattern = 0;
        if (stipple_pattern_from_name(name.c_str(), &pattern) != STIPPLE_OK)
            fail("unknown pattern \"" + name + "\": " + stipple_last_error_message());
        for (uint32_t arity : arities)
            for (uint32_t n : ns) {
                const stipple::Sampler owner = makeSampler(name, arity, n);
                const stipple_sampler sampler = owner.handle();
                std::vector<float> out(size_t(n) * arity);
                const uint32_t values = n * arity, pixels = std::max(2000u, (4u << 20) / values);
                // One untimed pass: families (poisson's stored sets) are built on first use.
                for (uint32_t p = 0; p < std::min(pixels, 64u); ++p)
                    stipple_sampler_fill_pixel(sampler, p, 0, 0, out.data(), out.size());
                const double fill = bestNsPerValue(reps, pixels, values, [&](uint32_t p) {
                    stipple_sampler_fill_pixel(sampler, p & 1023, p >> 10, 0, out.data(), out.size());
                });
                const double stream = bestNsPerValue(reps, pixels, values, [&](uint32_t p) {
                    stipple_sampler_stream_fill(sampler, p & 1023, p >> 10, 0, n, 0, arity, out.data(), out.size());
                });
                std::printf("%s %u %u %.4f %.4f\n", name.c_str(), arity, n, fill, stream);
                std::fflush(stdout);
            }
    }
    return 0;
}
