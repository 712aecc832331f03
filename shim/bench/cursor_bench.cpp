// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// cursor_bench.cpp — what a call-order host pays per value: stipple.hpp's documented PixelSampleCursor against the
// per-pixel stream_fill cache a host would write by hand, and against one C call per value.
//
// The host loop of all three: pixel after pixel, its N samples in a row; per sample the film position (2D) and
// eight values by call order (2D, 1D, 2D, 1D, ...: a path's bounce directions and lobe choices) and, with
// arrays, one array of 4 2D values (direct lighting); the values are summed. items = floats served. One loop
// (hostPixel) serves all three; before timing, the program checks that the three serve the same floats bit for bit
// (memcmp over 67 pixels of every configuration) and exits 1 if not.
//   BM_Cursor/<pattern>/<N>/<arrays>       the documented cursor (batches each (pixel, stream, arity) on first use)
//   BM_HandBatch/<pattern>/<N>/<arrays>    the per-pixel cache a host writes itself (the adopter's dozen lines):
//                                          each stream's N samples by one stream_fill / array_fill on first use
//                                          in the pixel, then reads by call counter
//   BM_PerValue/<pattern>/<N>/<arrays>     Sampler::stream / Sampler::array per value (the 1.1 cursor's cost)
// Ratios from one run, interleaved (shim/bench/cursor_ratios.py):
//   shim_cursor_bench --benchmark_enable_random_interleaving=true --benchmark_repetitions=9 \
//       --benchmark_min_time=0.1 --benchmark_format=json > cursor.json && python3 shim/bench/cursor_ratios.py
//       cursor.json
// stipple-link: shared
#include <stipple/stipple.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

const char* const kPatterns[] = {"independent", "stratified", "sobol", "pmj02"};
constexpr uint32_t kStreams = 8; // values by call order per sample
constexpr uint32_t kArrayK = 4;  // the array's k (2D)
constexpr uint32_t kTileWidth = 64;

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

// The host loop of all three, one pixel: its N samples in a row, every value handed to sink (a sum in the
// benchmarks, a record in the equality check).
template <typename Source, typename Sink>
void hostPixel(Source& source, stipple::Pixel p, uint32_t n, bool arrays, Sink& sink) {
    for (uint32_t i = 0; i < n; ++i) {
        source.start(p, i);
        const std::array<float, 2> film = source.getPixel2D();
        sink.add(film[0], film[1]);
        for (uint32_t d = 0; d < kStreams; d += 2) {
            const std::array<float, 2> uv = source.get2D();
            sink.add(uv[0], uv[1], source.get1D());
        }
        if (arrays) {
            const float* a = source.get2DArray(kArrayK);
            for (uint32_t j = 0; j < 2 * kArrayK; ++j) sink.add(a[j]);
        }
    }
}

stipple::Pixel pixelOf(uint32_t pixel) { return {int32_t(pixel % kTileWidth), int32_t(pixel / kTileWidth)}; }

// The benchmarks' host work per value: a sum, float terms grouped per call as a host would use them.
struct Sum {
    double sum = 0;
    void add(float a) { sum += a; }
    void add(float a, float b) { sum += a + b; }
    void add(float a, float b, float c) { sum += a + b + c; }
};

// Pixel after pixel through one source; items = floats served.
template <typename Source>
void run(benchmark::State& state, const Setup& s, Source& source) {
    Sum sink;
    uint32_t pixel = 0;
    for (auto _ : state) hostPixel(source, pixelOf(pixel++), s.n, s.arrays, sink);
    finish(state, s, sink.sum);
}

void BM_Cursor(benchmark::State& state) {
    Setup s = setup(state);
    if (!s.ok(state)) return;
    stipple::PixelSampleCursor cursor(s.sampler);
    run(state, s, cursor);
    if (!cursor.status().ok()) state.SkipWithError(cursor.status().message().c_str());
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
    std::vector<std::vector<float>> values_ = std::vector<std::vector<float>>(80);
    std::vector<char> filled_ = std::vector<char>(80, 0);
};

// The host loop of BM_Cursor with the hand-written cache in the cursor's place.
void BM_HandBatch(benchmark::State& state) {
    Setup s = setup(state);
    if (!s.ok(state)) return;
    HandCache cache(s.sampler, s.n);
    run(state, s, cache);
}

// One C call per value (Sampler::stream / Sampler::array), behind the cursor's interface.
class PerValue {
public:
    explicit PerValue(const stipple::Sampler& sampler) : sampler_(sampler) {}
    void start(stipple::Pixel pixel, uint32_t sample) {
        pixel_ = pixel;
        sample_ = sample;
        dimension_ = array_ = 0;
    }
    float get1D() {
        float v = 0;
        ok_ = sampler_.stream(pixel_, sample_, dimension_++, 1, &v).ok() && ok_;
        return v;
    }
    std::array<float, 2> get2D() { return stream2(dimension_++); }
    std::array<float, 2> getPixel2D() { return stream2(stipple::PixelSampleCursor::kPixelStream); }
    const float* get2DArray(uint32_t k) {
        ok_ = k <= kArrayK && sampler_.array(pixel_, sample_, array_++, 2, k, array_values_).ok() && ok_;
        return array_values_;
    }
    bool ok() const { return ok_; }

private:
    std::array<float, 2> stream2(uint32_t index) {
        std::array<float, 2> v = {{0, 0}};
        ok_ = sampler_.stream(pixel_, sample_, index, 2, v.data()).ok() && ok_;
        return v;
    }
    const stipple::Sampler& sampler_;
    stipple::Pixel pixel_ = {0, 0};
    uint32_t sample_ = 0, dimension_ = 0, array_ = 0;
    float array_values_[2 * kArrayK] = {};
    bool ok_ = true;
};

void BM_PerValue(benchmark::State& state) {
    Setup s = setup(state);
    if (!s.ok(state)) return;
    PerValue calls(s.sampler);
    run(state, s, calls);
    if (!calls.ok()) state.SkipWithError("a per-value call failed");
}

// Before any timing: the three sources serve the same floats, bit for bit, in the benchmarks' own loop (every
// configuration, pixels across two tile rows). A benchmark of a cursor that served other values would be void.
struct Record {
    std::vector<float> values;
    void add(float a) { values.push_back(a); }
    void add(float a, float b) {
        add(a);
        add(b);
    }
    void add(float a, float b, float c) {
        add(a, b);
        add(c);
    }
};

bool sameValues() {
    bool same = true;
    for (int64_t pattern = 0; pattern < 4; ++pattern)
        for (uint32_t n : {16u, 64u})
            for (bool arrays : {false, true}) {
                stipple::Sampler sampler;
                if (!stipple::Sampler::create(sampler, kPatterns[pattern], n, 7).ok()) {
                    std::fprintf(stderr, "cursor_bench: %s\n", sampler.status().message().c_str());
                    return false;
                }
                stipple::PixelSampleCursor cursor(sampler);
                HandCache cache(sampler, n);
                PerValue calls(sampler);
                Record c, h, v;
                for (uint32_t pixel = 0; pixel < kTileWidth + 3; ++pixel) {
                    hostPixel(cursor, pixelOf(pixel), n, arrays, c);
                    hostPixel(cache, pixelOf(pixel), n, arrays, h);
                    hostPixel(calls, pixelOf(pixel), n, arrays, v);
                }
                const bool equal =
                    cursor.status().ok() && calls.ok() && c.values.size() == h.values.size() &&
                    c.values.size() == v.values.size() &&
                    std::memcmp(c.values.data(), h.values.data(), c.values.size() * sizeof(float)) == 0 &&
                    std::memcmp(c.values.data(), v.values.data(), c.values.size() * sizeof(float)) == 0;
                std::fprintf(
                    stderr,
                    "cursor_bench: %-11s N %2u arrays %d: %zu floats, cursor %s hand cache %s per-value calls\n",
                    kPatterns[pattern], n, int(arrays), c.values.size(), equal ? "==" : "!=", equal ? "==" : "!=");
                same = same && equal;
            }
    return same;
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

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    if (!sameValues()) {
        std::fprintf(stderr, "cursor_bench: the cursor, the hand-written cache and the per-value calls differ\n");
        return 1;
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
