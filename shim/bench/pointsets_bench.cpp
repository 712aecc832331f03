// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pointsets_bench.cpp — fresh generation of one Poisson set: poisson vs poisson-seed, 1D/2D/3D, N = 16 ... 100000.
//
// BM_Generate/<generator>/<dim>/<N>: one set per iteration, a new seed each time (fresh, never cached).
// Counters: points/s (items), rho (mean relative radius of the sets generated, measured outside the timer).
// The speed-up claims of shim/POINTSETS.md are ratios of these rows from one run.
#include "pointsets/pointsets.h"

#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

namespace {

enum Generator : int64_t { kPoisson = 0, kPoissonSeed = 1 };

void BM_Generate(benchmark::State& state) {
    const auto generator = Generator(state.range(0));
    const int dim = int(state.range(1));
    const auto n = uint32_t(state.range(2));
    uint64_t seed = 1;
    double rhoSum = 0.0;
    int64_t measured = 0;
    for (auto _ : state) {
        std::vector<float> pts = generator == kPoisson ? stipple::detail::pointsets::generatePoisson(dim, n, seed)
                                                       : stipple::detail::pointsets::generatePoissonSeed(dim, n, seed);
        benchmark::DoNotOptimize(pts.data());
        ++seed;
        if (measured < 8) { // rho of the first few sets, off the clock
            state.PauseTiming();
            rhoSum += stipple::detail::pointsets::relativeRadius(dim, pts.data(), n);
            ++measured;
            state.ResumeTiming();
        }
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * n);
    state.counters["rho"] = measured ? rhoSum / double(measured) : 0.0;
    state.SetLabel(generator == kPoisson ? "poisson" : "poisson-seed");
}

void sizes(benchmark::internal::Benchmark* b) {
    for (int64_t generator : {kPoisson, kPoissonSeed})
        for (int64_t dim : {1, 2, 3})
            for (int64_t n : {16, 256, 4096, 100000}) b->Args({generator, dim, n});
}

} // namespace

BENCHMARK(BM_Generate)->Apply(sizes)->Unit(benchmark::kMicrosecond)->ArgNames({"gen", "dim", "N"});

BENCHMARK_MAIN();
