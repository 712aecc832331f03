// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// cursor_bench.cpp — what a call-order host pays per value: stipple.hpp's documented PixelSampleCursor against the
// per-pixel stream_fill cache a host would write by hand, and against one C call per value.
//
// The host loop of all three: pixel after pixel, its N samples in a row; per sample the film position (2D) and
// eight values by call order (2D, 1D, 2D, 1D, ...: a path's bounce directions and lobe choices) and, with
// arrays, one array of 4 2D values (direct lighting); the values are summed. items = values per pixel x pixels.
//   BM_Cursor/<pattern>/<N>/<arrays>       the documented cursor (batches each (pixel, stream, arity) on first use)
//   BM_HandBatch/<pattern>/<N>/<arrays>    the per-pixel cache a host writes itself (the adopter's dozen lines):
//                                          each stream's N samples by one stream_fill / array_fill on first use
//                                          in the pixel, then reads by call counter
//   BM_PerValue/<pattern>/<N>/<arrays>     Sampler::stream / Sampler::array per value (the 1.1 cursor's cost)
// Ratios from one run, interleaved (shim/bench/cursor_ratios.py):
//   shim_cursor_bench --benchmark_enable_random_interleaving=true --benchmark_repetitions=5 \
//       --benchmark_format=json > cursor.json && python3 shim/bench/cursor_ratios.py cursor.json
// stipple-link: shared
#include <stipple/stipple.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace {

const char* const kPatterns[] = {"independent", "stratified", "sobol", "pmj02"};
constexpr uint32_t kStreams = 8;   // values by call order per sample
constexpr uint32_t kArrayK = 4;    // the array's k (2D)
constexpr uint32_t kTileWidth = 64;

uint32_t arityOf(uint32_t d) { return d % 2 == 0 ? 2 : 1; }

struct Setup {
    stipple::Sampler sampler;
    uint32_t n;
    bool arrays;
    bool ok(benchmark::State& state) {
        if (sampler) return true;
        state.SkipWithError(sampler.status().message().c_str());
        return false;
    }
};

Setup setup(benchmark::State& state) {
    const char* pattern = kPatterns[state.range(0)];
    state.SetLabel(pattern);
    Setup s;
    s.n = uint32_t(state.range(1));
    s.arrays = state.range(2) != 0;
    stipple::Status status = stipple::Sampler::create(s.sampler, pattern, s.n, 7);
    (void)status; // reported through sampler.status() by ok()
    return s;
}

void finish(benchmark::State& state, const Setup& s, double sum) {
    benchmark::DoNotOptimize(sum);
    const int64_t perSample = 2 + 2 * (kStreams / 2) + 1 * (kStreams / 2) + (s.arrays ? 2 * kArrayK : 0);
    state.SetItemsProcessed(int64_t(state.iterations()) * s.n * perSample); // items = floats served
}

void BM_Cursor(benchmark::State& state) {
    Setup s = setup(state);
    if (!s.ok(state)) return;
    stipple::PixelSampleCursor cursor(s.sampler);
    uint32_t pixel = 0;
    double sum = 0;
    for (auto _ : state) {
        const stipple::Pixel p = {int32_t(pixel % kTileWidth), int32_t(pixel / kTileWidth)};
        for (uint32_t i = 0; i < s.n; ++i) {
            cursor.start(p, i);
            const std::array<float, 2> film = cursor.getPixel2D();
            sum += film[0] + film[1];
            for (uint32_t d = 0; d < kStreams; d += 2) {
                const std::array<float, 2> uv = cursor.get2D();
                sum += uv[0] + uv[1] + cursor.get1D();
            }
            if (s.arrays) {
                const float* a = cursor.get2DArray(kArrayK);
                for (uint32_t j = 0; j < 2 * kArrayK; ++j) sum += a[j];
            }
        }
        ++pixel;
    }
    finish(state, s, sum);
}

// The adopter's cache, as a host writes it for its own sampler class: per pixel, a stream is filled for all N
// samples on its first use (stream_fill / array_fill), then Get1D / Get2D / Get2DArray read it by call counter.
// Minimal on purpose: no error path, one arity per index, pixel-major hosts only, sample indices below N.
class HandCache {
public:
    HandCache(const stipple::Sampler& sampler, uint32_t n) : sampler_(sampler), n_(n) {}
    void start(stipple::Pixel pixel, uint32_t sample) {
        if (pixel != pixel_) {
            std::fill(filled_.begin(), filled_.end(), 0);
            pixel_ = pixel;
        }
        sample_ = sample;
        dimension_ = array_ = 0;
    }
    float get1D() { return *get(dimension_++, 1, 1, false); }
    std::array<float, 2> get2D() {
        const float* v = get(dimension_++, 2, 1, false);
        return {{v[0], v[1]}};
    }
    std::array<float, 2> getPixel2D() {
        const float* v = get(kFilmSlot, 2, 1, false);
        return {{v[0], v[1]}};
    }
    const float* get2DArray(uint32_t k) { return get(kArraySlot + array_++, 2, k, true); }

private:
    static constexpr uint32_t kFilmSlot = 64, kArraySlot = 65;
    const float* get(uint32_t slot, uint32_t arity, uint32_t k, bool isArray) {
        if (!filled_[slot]) {
            values_[slot].resize(size_t(n_) * k * arity);
            const uint32_t index = slot == kFilmSlot ? stipple::PixelSampleCursor::kPixelStream
                                   : isArray         ? slot - kArraySlot
                                                     : slot;
            (void)(isArray ? sampler_.arrayFill(pixel_, 0, n_, index, arity, k, values_[slot].data())
                           : sampler_.streamFill(pixel_, 0, n_, index, arity, values_[slot].data()));
            filled_[slot] = 1;
        }
        return &values_[slot][size_t(sample_) * k * arity];
    }
    const stipple::Sampler& sampler_;
    uint32_t n_, sample_ = 0, dimension_ = 0, array_ = 0;
    stipple::Pixel pixel_ = {-1, -1};
    std::vector<std::vector<float> > values_ = std::vector<std::vector<float> >(80);
    std::vector<char> filled_ = std::vector<char>(80, 0);
};

// The host loop of BM_Cursor with the hand-written cache in the cursor's place.
void BM_HandBatch(benchmark::State& state) {
    Setup s = setup(state);
    if (!s.ok(state)) return;
    HandCache cache(s.sampler, s.n);
    uint32_t pixel = 0;
    double sum = 0;
    for (auto _ : state) {
        const stipple::Pixel p = {int32_t(pixel % kTileWidth), int32_t(pixel / kTileWidth)};
        for (uint32_t i = 0; i < s.n; ++i) {
            cache.start(p, i);
            const std::array<float, 2> film = cache.getPixel2D();
            sum += film[0] + film[1];
            for (uint32_t d = 0; d < kStreams; d += 2) {
                const std::array<float, 2> uv = cache.get2D();
                sum += uv[0] + uv[1] + cache.get1D();
            }
            if (s.arrays) {
                const float* a = cache.get2DArray(kArrayK);
                for (uint32_t j = 0; j < 2 * kArrayK; ++j) sum += a[j];
            }
        }
        ++pixel;
    }
    finish(state, s, sum);
}

void BM_PerValue(benchmark::State& state) {
    Setup s = setup(state);
    if (!s.ok(state)) return;
    uint32_t pixel = 0;
    double sum = 0;
    float v[2 * kArrayK];
    for (auto _ : state) {
        const stipple::Pixel p = {int32_t(pixel % kTileWidth), int32_t(pixel / kTileWidth)};
        bool ok = true;
        for (uint32_t i = 0; i < s.n; ++i) {
            ok = ok && s.sampler.stream(p, i, stipple::PixelSampleCursor::kPixelStream, 2, v).ok();
            sum += v[0] + v[1];
            for (uint32_t d = 0; d < kStreams; ++d) {
                ok = ok && s.sampler.stream(p, i, d, arityOf(d), v).ok();
                sum += v[0] + (arityOf(d) == 2 ? v[1] : 0.0f);
            }
            if (s.arrays) {
                ok = ok && s.sampler.array(p, i, 0, 2, kArrayK, v).ok();
                for (uint32_t j = 0; j < 2 * kArrayK; ++j) sum += v[j];
            }
        }
        if (!ok) return state.SkipWithError("stream failed");
        ++pixel;
    }
    finish(state, s, sum);
}

void arguments(benchmark::internal::Benchmark* b) {
    for (int64_t pattern = 0; pattern < 4; ++pattern)
        for (int64_t n : {16, 64})
            for (int64_t arrays : {0, 1}) b->Args({pattern, n, arrays});
}

} // namespace

BENCHMARK(BM_Cursor)->ArgNames({"pattern", "N", "arrays"})->Apply(arguments)->MinTime(0.2);
BENCHMARK(BM_HandBatch)->ArgNames({"pattern", "N", "arrays"})->Apply(arguments)->MinTime(0.2);
BENCHMARK(BM_PerValue)->ArgNames({"pattern", "N", "arrays"})->Apply(arguments)->MinTime(0.2);

BENCHMARK_MAIN();
