// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// shim_bench.cpp — values/s of every sampling call per pattern x arity x N (one value = one point of `arity` floats).
//
// BM_FillPixel/<pattern>/<arity>/<N>: the batch call, one call per iteration, each for the next pixel; items = N.
// BM_Sample: random access (stipple_sampler_sample), N calls per iteration, one per sample index of one pixel.
// BM_Stream: the streaming call (stipple_sampler_stream, no declared layout), N calls per iteration in the order a
//   call-order host makes them: for each sample index, dimension indices 0..7 (8 values, so items = 8 N).
// BM_StreamFill: the streaming batch call (stipple_sampler_stream_fill), N samples of one stream per call.
// shim/bench/ratios.py turns one run's JSON into per-value cost ratios against independent.
// For poisson the cache of the (arity, N) family is warmed before the timed loop; that warm-up (generating every
// set of the family) is measured apart by BM_PoissonWarmup/<arity>/<N> on a fresh family. pmj02's families are
// warmed likewise; generating one sequence of 2^m points is BM_Pmj02Sequence/<m> ((x, y)) and BM_Pmj02Depth/<m>
// (its z for 3D sets, given (x, y)).
// Links the internal objects only to reach the cache for warming and to pick the batch kernels' ISA
// (--isa=baseline|avx2|avx512: at most what the CPU runs; default the widest, as the library picks; recorded in the
// JSON context as batch_isa); samplers are made through stipple.hpp, the timed calls are the C API's.
#include <stipple/stipple.hpp>

#include "batch_isa.h"
#include "pmj02_family.h"
#include "pmj02_generator.h"
#include "poisson_cache.h"

#include <benchmark/benchmark.h>

#include <bit>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

// Generates the cached sets a pattern serves from (poisson sets, pmj02 sequences) before timing.
void warmPoisson(uint32_t pattern, uint32_t arity, uint32_t n) {
    if (pattern == STIPPLE_PATTERN_PMJ02) {
        auto family = stipple::detail::Pmj02Family::acquire(static_cast<uint32_t>(std::bit_width(n - 1)));
        for (uint32_t j = 0; j < family->setCount(); ++j) family->sequence(j);
        return;
    }
    if (pattern != STIPPLE_PATTERN_POISSON) return;
    auto family = stipple::detail::PoissonCache::global().acquire(arity, n);
    for (uint32_t j = 0; j < family->setCount(); ++j) family->set(j);
}

void label(benchmark::State& state, uint32_t pattern) {
    const char* name = "?";
    stipple_pattern_name(pattern, &name);
    state.SetLabel(name);
}

// Samplers through stipple.hpp (the timed loops below call the C ABI directly: that is what they measure).
stipple::Sampler makeStreamSampler(uint32_t pattern, uint32_t n) {
    const char* name = "";
    stipple_pattern_name(pattern, &name);
    stipple::Sampler sampler;
    (void)stipple::Sampler::create(sampler, name, n, 7); // a failure is in sampler.status()
    return sampler;
}

stipple::Sampler makeSampler(uint32_t pattern, uint32_t arity, uint32_t n, uint32_t flags = 0) {
    const char* name = "";
    stipple_pattern_name(pattern, &name);
    stipple::Sampler sampler;
    (void)stipple::Sampler::create(sampler, name, n, 7, {{arity, 1, ""}}, flags);
    return sampler;
}

// fill_pixel over pixels along rows of the image, so consecutive calls cross 64-pixel tiles as a renderer's do.
void timeFillPixel(benchmark::State& state, stipple_sampler s, uint32_t arity, uint32_t n) {
    std::vector<float> out(size_t(n) * arity);
    uint32_t pixel = 0;
    for (auto _ : state) {
        if (stipple_sampler_fill_pixel(s, pixel % 1024, pixel / 1024, 0, out.data(), out.size()) != STIPPLE_OK) {
            state.SkipWithError(stipple_last_error_message());
            break;
        }
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
        ++pixel;
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * n);
}

void BM_FillPixel(benchmark::State& state) {
    const auto pattern = static_cast<uint32_t>(state.range(0));
    const auto arity = static_cast<uint32_t>(state.range(1));
    const auto n = static_cast<uint32_t>(state.range(2));
    const stipple::Sampler sampler = makeSampler(pattern, arity, n);
    if (!sampler) return state.SkipWithError(sampler.status().message().c_str());
    warmPoisson(pattern, arity, n);
    timeFillPixel(state, sampler.handle(), arity, n);
    label(state, pattern);
}

// BM_BlueNoiseFill/<pattern>/<arity>/<N>/<blue>: fill_pixel with and without STIPPLE_SAMPLER_FLAG_BLUE_NOISE, the
// two rows of one (pattern, arity, N) side by side (--benchmark_enable_random_interleaving mixes them further);
// shim/bench/blue_noise_ratios.py turns one run into blue / plain per value.
void BM_BlueNoiseFill(benchmark::State& state) {
    const auto pattern = static_cast<uint32_t>(state.range(0));
    const auto arity = static_cast<uint32_t>(state.range(1));
    const auto n = static_cast<uint32_t>(state.range(2));
    const uint32_t flags = state.range(3) != 0 ? STIPPLE_SAMPLER_FLAG_BLUE_NOISE : 0u;
    const stipple::Sampler sampler = makeSampler(pattern, arity, n, flags);
    if (!sampler) return state.SkipWithError(sampler.status().message().c_str());
    timeFillPixel(state, sampler.handle(), arity, n);
    label(state, pattern);
}

void BM_Sample(benchmark::State& state) {
    const auto pattern = static_cast<uint32_t>(state.range(0));
    const auto arity = static_cast<uint32_t>(state.range(1));
    const auto n = static_cast<uint32_t>(state.range(2));
    const stipple::Sampler sampler = makeSampler(pattern, arity, n);
    if (!sampler) return state.SkipWithError(sampler.status().message().c_str());
    stipple_sampler s = sampler.handle();
    warmPoisson(pattern, arity, n);
    float out[3];
    uint32_t pixel = 0;
    for (auto _ : state) {
        for (uint32_t i = 0; i < n; ++i) {
            stipple_sampler_sample(s, pixel % 1024, pixel / 1024, i, 0, out, 3);
            benchmark::DoNotOptimize(out);
        }
        ++pixel;
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * n);
    label(state, pattern);
}

void BM_Stream(benchmark::State& state) {
    const auto pattern = static_cast<uint32_t>(state.range(0));
    const auto arity = static_cast<uint32_t>(state.range(1));
    const auto n = static_cast<uint32_t>(state.range(2));
    const stipple::Sampler sampler = makeStreamSampler(pattern, n);
    if (!sampler) return state.SkipWithError(sampler.status().message().c_str());
    stipple_sampler s = sampler.handle();
    warmPoisson(pattern, arity, n);
    float out[3];
    uint32_t pixel = 0;
    for (auto _ : state) {
        for (uint32_t i = 0; i < n; ++i)
            for (uint32_t d = 0; d < 8; ++d) {
                stipple_sampler_stream(s, pixel % 1024, pixel / 1024, i, d, arity, out, 3);
                benchmark::DoNotOptimize(out);
            }
        ++pixel;
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * n * 8);
    label(state, pattern);
}

void BM_StreamFill(benchmark::State& state) {
    const auto pattern = static_cast<uint32_t>(state.range(0));
    const auto arity = static_cast<uint32_t>(state.range(1));
    const auto n = static_cast<uint32_t>(state.range(2));
    const stipple::Sampler sampler = makeStreamSampler(pattern, n);
    if (!sampler) return state.SkipWithError(sampler.status().message().c_str());
    stipple_sampler s = sampler.handle();
    warmPoisson(pattern, arity, n);
    std::vector<float> out(size_t(n) * arity);
    uint32_t pixel = 0;
    for (auto _ : state) {
        stipple_sampler_stream_fill(s, pixel % 1024, pixel / 1024, 0, n, 0, arity, out.data(), out.size());
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
        ++pixel;
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * n);
    label(state, pattern);
}

void BM_PoissonWarmup(benchmark::State& state) {
    const auto arity = static_cast<uint32_t>(state.range(0));
    const auto n = static_cast<uint32_t>(state.range(1));
    const uint32_t sets = stipple::detail::PoissonCache::setCountFor(arity, n);
    for (auto _ : state) {
        stipple::detail::PoissonFamily family(arity, n, sets); // fresh, outside the cache
        for (uint32_t j = 0; j < sets; ++j) benchmark::DoNotOptimize(family.set(j));
    }
    state.counters["sets"] = sets;
    state.SetItemsProcessed(int64_t(state.iterations()) * sets * n);
}

void BM_Pmj02Sequence(benchmark::State& state) {
    const auto m = static_cast<uint32_t>(state.range(0));
    uint64_t seed = 0;
    for (auto _ : state) benchmark::DoNotOptimize(stipple::detail::generatePmj02(m, seed++));
    state.SetItemsProcessed(int64_t(state.iterations()) << m);
}

void BM_Pmj02Depth(benchmark::State& state) {
    const auto m = static_cast<uint32_t>(state.range(0));
    const std::vector<stipple::detail::FixedPoint2> points = stipple::detail::generatePmj02(m, 1);
    uint64_t seed = 0;
    for (auto _ : state) benchmark::DoNotOptimize(stipple::detail::generatePmj02Depth(points, seed++));
    state.SetItemsProcessed(int64_t(state.iterations()) << m);
}

// Every pattern the library lists.
uint32_t libraryPatternCount() {
    uint32_t count = 0;
    return stipple_pattern_count(&count) == STIPPLE_OK ? count : 0;
}

uint32_t acceptedFlags(uint32_t pattern) {
    stipple_pattern_limits limits{};
    limits.struct_size = sizeof limits;
    return stipple_pattern_get_limits(pattern, &limits) == STIPPLE_OK ? limits.flags : 0;
}

// N = 100 besides the powers of two: the sizes whose grids and sequences are not the power-of-two ones.
void fillArguments(benchmark::internal::Benchmark* b) {
    for (int64_t pattern = 0; pattern < int64_t(libraryPatternCount()); ++pattern)
        for (int64_t arity = 1; arity <= 3; ++arity)
            for (int64_t n : {16, 100, 256, 4096}) b->Args({pattern, arity, n});
}

// The patterns whose limits accept the blue-noise flag, plain (0) and flagged (1) next to each other.
void blueNoiseArguments(benchmark::internal::Benchmark* b) {
    for (int64_t pattern = 0; pattern < int64_t(libraryPatternCount()); ++pattern)
        if (acceptedFlags(uint32_t(pattern)) & STIPPLE_SAMPLER_FLAG_BLUE_NOISE)
            for (int64_t arity = 1; arity <= 3; ++arity)
                for (int64_t n : {16, 256, 4096})
                    for (int64_t blue : {0, 1}) b->Args({pattern, arity, n, blue});
}

// Per-value calls: poisson-seed generates its whole set on every call by design, so it is left out here.
void accessArguments(benchmark::internal::Benchmark* b) {
    for (int64_t pattern = 0; pattern < int64_t(libraryPatternCount()); ++pattern)
        if (pattern != STIPPLE_PATTERN_POISSON_SEED)
            for (int64_t arity = 1; arity <= 3; ++arity)
                for (int64_t n : {16, 256, 4096}) b->Args({pattern, arity, n});
}

} // namespace

BENCHMARK(BM_FillPixel)->ArgNames({"pattern", "arity", "N"})->Apply(fillArguments)->MinTime(0.2);
BENCHMARK(BM_BlueNoiseFill)->ArgNames({"pattern", "arity", "N", "blue"})->Apply(blueNoiseArguments)->MinTime(0.2);
BENCHMARK(BM_Sample)->ArgNames({"pattern", "arity", "N"})->Apply(accessArguments)->MinTime(0.2);
BENCHMARK(BM_Stream)->ArgNames({"pattern", "arity", "N"})->Apply(accessArguments)->MinTime(0.2);
BENCHMARK(BM_StreamFill)->ArgNames({"pattern", "arity", "N"})->Apply(accessArguments)->MinTime(0.2);
BENCHMARK(BM_PoissonWarmup)
    ->ArgNames({"arity", "N"})
    ->ArgsProduct({{1, 2, 3}, {16, 256, 4096}})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(0.2);

BENCHMARK(BM_Pmj02Sequence)->ArgName("m")->DenseRange(7, 16, 3)->Unit(benchmark::kMillisecond)->MinTime(0.2);
BENCHMARK(BM_Pmj02Depth)->ArgName("m")->DenseRange(7, 16, 3)->Unit(benchmark::kMillisecond)->MinTime(0.2);

int main(int argc, char** argv) {
    const char* names[] = {"baseline", "avx2", "avx512"};
    for (int i = 1; i < argc; ++i) {
        if (std::strncmp(argv[i], "--isa=", 6) != 0) continue;
        const std::string wanted = argv[i] + 6;
        bool known = false;
        for (uint32_t isa = 0; isa < 3; ++isa)
            if (wanted == names[isa])
                stipple::detail::forceBatchIsa(static_cast<stipple::detail::BatchIsa>(isa)), known = true;
        if (!known) {
            std::fprintf(stderr, "shim_shim_bench: --isa=%s; expected baseline, avx2 or avx512\n", wanted.c_str());
            return 2;
        }
        for (int j = i; j + 1 < argc; ++j) argv[j] = argv[j + 1];
        --argc;
        --i;
    }
    benchmark::AddCustomContext("batch_isa", names[static_cast<uint32_t>(stipple::detail::batchIsa())]);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
