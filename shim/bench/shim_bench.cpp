// shim_bench.cpp — samples/s of the batch call (stipple_sampler_fill_pixel) per pattern x arity x N.
//
// BM_FillPixel/<pattern>/<arity>/<N>: one call per iteration, each for the next pixel; items = N samples.
// For poisson the cache of the (arity, N) family is warmed before the timed loop; that warm-up (generating every
// set of the family) is measured apart by BM_PoissonWarmup/<arity>/<N> on a fresh family.
// Links the internal objects only to reach the cache for warming; sampling goes through the C API.
#include <stipple/stipple.h>

#include "poisson_cache.h"

#include <benchmark/benchmark.h>

#include <vector>

namespace {

stipple_sampler makeSampler(uint32_t pattern, uint32_t arity, uint32_t n) {
    stipple_dimension_desc dim{};
    dim.struct_size = sizeof dim;
    dim.arity = arity;
    dim.count = 1;
    stipple_sampler_desc desc{};
    desc.struct_size = sizeof desc;
    desc.pattern = pattern;
    desc.samples_per_pixel = n;
    desc.dimension_count = 1;
    desc.seed = 7;
    desc.dimensions = &dim;
    stipple_sampler s = nullptr;
    return stipple_sampler_create(&desc, &s) == STIPPLE_OK ? s : nullptr;
}

void BM_FillPixel(benchmark::State& state) {
    const auto pattern = static_cast<uint32_t>(state.range(0));
    const auto arity = static_cast<uint32_t>(state.range(1));
    const auto n = static_cast<uint32_t>(state.range(2));
    stipple_sampler s = makeSampler(pattern, arity, n);
    if (!s) {
        state.SkipWithError(stipple_last_error_message());
        return;
    }
    if (pattern == STIPPLE_PATTERN_POISSON) {
        auto family = stipple::PoissonCache::global().acquire(arity, n);
        for (uint32_t j = 0; j < family->setCount(); ++j) family->set(j);
    }
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
    const char* name = "?";
    stipple_pattern_name(pattern, &name);
    state.SetLabel(name);
    stipple_sampler_release(s);
}

void BM_PoissonWarmup(benchmark::State& state) {
    const auto arity = static_cast<uint32_t>(state.range(0));
    const auto n = static_cast<uint32_t>(state.range(1));
    const uint32_t sets = stipple::PoissonCache::setCountFor(arity, n);
    for (auto _ : state) {
        stipple::PoissonFamily family(arity, n, sets); // fresh, outside the cache
        for (uint32_t j = 0; j < sets; ++j) benchmark::DoNotOptimize(family.set(j));
    }
    state.counters["sets"] = sets;
    state.SetItemsProcessed(int64_t(state.iterations()) * sets * n);
}

void fillArguments(benchmark::internal::Benchmark* b) {
    for (int64_t pattern = 0; pattern < STIPPLE_PATTERN_COUNT; ++pattern)
        for (int64_t arity = 1; arity <= 3; ++arity)
            for (int64_t n : {16, 256, 4096}) b->Args({pattern, arity, n});
}

} // namespace

BENCHMARK(BM_FillPixel)->ArgNames({"pattern", "arity", "N"})->Apply(fillArguments)->MinTime(0.2);
BENCHMARK(BM_PoissonWarmup)
    ->ArgNames({"arity", "N"})
    ->ArgsProduct({{1, 2, 3}, {16, 256, 4096}})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(0.2);

BENCHMARK_MAIN();
