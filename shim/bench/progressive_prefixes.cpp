// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// progressive_prefixes.cpp — what a prefix of a set is worth: prints the tables of POINTSETS.md ("Prefixes").
//
// For stratified and poisson (independent as the reference), 2D streams with N = 256 and N = 1024:
//  - rho (relative radius, toroidal) of the prefixes of n = N/4, N/2, N samples of one pixel's set, mean over
//    64 pixels; and rho of a fresh set of n points (a sampler with N = n) for comparison;
//  - MSE over 4096 pixels of the n-sample estimate from a prefix of an N set, and from a fresh n set, for an
//    edged integrand (quarter disk, pi/4) and a smooth one (exp(-x^2 - y^2), (sqrt(pi)/2 erf 1)^2).
// Fixed seeds: the output is the same on every run.
//   usage: shim_progressive_prefixes > prefixes.md
#include <stipple/stipple.h>
#include <stipple/stipple.hpp>

#include "pointsets/pointsets.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

// A streams-only sampler through the kit (stipple.hpp); the measured calls use its handle.
stipple::Sampler streams(uint32_t pattern, uint32_t n, uint64_t seed) {
    const char* name = "";
    stipple_pattern_name(pattern, &name);
    stipple::Sampler s;
    const stipple::Status status = stipple::Sampler::create(s, name, n, seed);
    if (!status.ok()) {
        std::fprintf(stderr, "%s\n", status.message().c_str());
        std::exit(1);
    }
    return s;
}

std::vector<float> prefix(stipple_sampler s, uint32_t pixel, uint32_t n) {
    std::vector<float> v(size_t(n) * 2);
    stipple_sampler_stream_fill(s, pixel % 64, pixel / 64, 0, n, 0, 2, v.data(), v.size());
    return v;
}

double quarterDisk(const std::vector<float>& v) {
    double hits = 0;
    for (size_t i = 0; i < v.size(); i += 2) hits += double(v[i]) * v[i] + double(v[i + 1]) * v[i + 1] < 1.0;
    return hits / double(v.size() / 2);
}

double gaussian(const std::vector<float>& v) {
    double sum = 0;
    for (size_t i = 0; i < v.size(); i += 2) sum += std::exp(-double(v[i]) * v[i] - double(v[i + 1]) * v[i + 1]);
    return sum / double(v.size() / 2);
}

} // namespace

int main() {
    const double pi = 3.14159265358979323846;
    const double exactDisk = pi / 4, exactGauss = std::pow(std::sqrt(pi) / 2 * std::erf(1.0), 2);
    const char* names[] = {"independent", "stratified", "poisson"};
    std::printf("| pattern | N | prefix n | rho prefix | rho fresh n | MSE disk prefix | MSE disk fresh | MSE gauss "
                "prefix | MSE gauss fresh |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|\n");
    for (uint32_t pattern : {STIPPLE_PATTERN_INDEPENDENT, STIPPLE_PATTERN_STRATIFIED, STIPPLE_PATTERN_POISSON})
        for (uint32_t n : {256u, 1024u}) {
            const stipple::Sampler fullSampler = streams(pattern, n, 2026);
            const stipple_sampler full = fullSampler.handle();
            for (uint32_t m : {n / 4, n / 2, n}) {
                const stipple::Sampler freshSampler = streams(pattern, m, 2027);
                const stipple_sampler fresh = freshSampler.handle();
                double rhoPrefix = 0, rhoFresh = 0;
                for (uint32_t p = 0; p < 64; ++p) {
                    rhoPrefix += stipple::detail::pointsets::relativeRadius(2, prefix(full, p, m).data(), m) / 64;
                    rhoFresh += stipple::detail::pointsets::relativeRadius(2, prefix(fresh, p, m).data(), m) / 64;
                }
                double diskPrefix = 0, diskFresh = 0, gaussPrefix = 0, gaussFresh = 0;
                const uint32_t pixels = 4096;
                for (uint32_t p = 0; p < pixels; ++p) {
                    const std::vector<float> a = prefix(full, p, m), b = prefix(fresh, p, m);
                    diskPrefix += std::pow(quarterDisk(a) - exactDisk, 2) / pixels;
                    diskFresh += std::pow(quarterDisk(b) - exactDisk, 2) / pixels;
                    gaussPrefix += std::pow(gaussian(a) - exactGauss, 2) / pixels;
                    gaussFresh += std::pow(gaussian(b) - exactGauss, 2) / pixels;
                }
                std::printf("| %s | %u | %u | %.3f | %.3f | %.3e | %.3e | %.3e | %.3e |\n", names[pattern], n, m,
                            rhoPrefix, rhoFresh, diskPrefix, diskFresh, gaussPrefix, gaussFresh);
            }
        }
    return 0;
}
