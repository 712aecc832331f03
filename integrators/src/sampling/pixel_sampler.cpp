// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "sampling/pixel_sampler.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace stipple::render {

namespace {
double emptyClockInterval() {
    double sum = 0;
    for (int i = 0; i < 4096; ++i) {
        auto a = std::chrono::steady_clock::now();
        auto b = std::chrono::steady_clock::now();
        sum += std::chrono::duration<double>(b - a).count();
    }
    return sum / 4096;
}
} // namespace

PixelSampler::PixelSampler(const ShimLibrary& shim, const std::string& pattern, uint32_t spp, uint64_t seed,
                           const SampleLayout& layout)
    : spp_(spp), layout_(layout) {
    const stipple_api& api = shim.api();
    // "<name>" or "<name>+blue-noise": the shim's own parser (stipple.hpp's parsePattern) reads it.
    uint32_t patternId = 0, flags = 0;
    const stipple::Status parsed = stipple::parsePattern(pattern, patternId, flags, api);
    if (!parsed.ok()) {
        // A bad name is the caller's argument, not a shim failure (stipple-render exits with 2 on it).
        std::string known;
        for (const std::string& n : shim.patternNames()) known += (known.empty() ? "" : ", ") + n;
        throw std::invalid_argument("unknown pattern '" + pattern + "' (" + parsed.message() + "); expected one of " +
                                    known + ", optionally followed by +blue-noise");
    }
    std::vector<stipple::LayoutDimension> dims;
    for (const Dimension& d : layout.dimensions()) dims.push_back({d.arity, d.count, d.name});
    const stipple::Status created = stipple::Sampler::create(sampler_, pattern, spp, seed, dims, 0, api);
    if (!created.ok())
        throw ShimError("cannot create a '" + pattern + "' sampler with " + std::to_string(spp) + " spp and " +
                        std::to_string(dims.size()) + " dimensions: " + created.message());
    clockSeconds_ = emptyClockInterval();
}

void PixelSampler::startPixel(uint32_t x, uint32_t y, PixelSamples& out) const {
    out.x_ = x;
    out.y_ = y;
    out.timed_ = out.pixels_++ % PixelSamples::kTimedEvery == 0;
    out.pixelsTimed_ += out.timed_;
    std::fill(out.held_.begin(), out.held_.end(), uint8_t(0));
}

void PixelSampler::drawPixel(uint32_t x, uint32_t y, uint32_t d, float* out, size_t count) const {
    // The kit's Pixel is signed; the ABI reads the same 32 bits either way.
    const stipple::Status s = sampler_.fillPixel(stipple::Pixel{int32_t(x), int32_t(y)}, d, out, count);
    if (!s.ok())
        throw ShimError("stipple_sampler_fill_pixel(" + std::to_string(x) + ", " + std::to_string(y) + ", dimension " +
                        std::to_string(d) + ") failed: " + s.message());
}

PixelSamples::PixelSamples(const PixelSampler& sampler) : sampler_(&sampler) {
    pixelOffset_.push_back(0);
    for (const Dimension& d : sampler.layout().dimensions()) {
        arity_.push_back(d.arity);
        perSample_.push_back(size_t(d.count) * d.arity);
        pixelOffset_.push_back(pixelOffset_.back() + size_t(sampler.samplesPerPixel()) * perSample_.back());
    }
    pixelValues_.assign(pixelOffset_.back() + 1, 0.0f); // + 1: a valid address for an empty layout
    held_.assign(arity_.size(), 0);
}

void PixelSamples::fetchPixel(uint32_t dim) const {
    float* out = &pixelValues_[pixelOffset_[dim]];
    const size_t count = pixelOffset_[dim + 1] - pixelOffset_[dim];
    if (timed_) {
        const auto start = std::chrono::steady_clock::now();
        sampler_->drawPixel(x_, y_, dim, out, count);
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        timedSeconds_ += std::max(0.0, elapsed - sampler_->clockSeconds_);
    } else {
        sampler_->drawPixel(x_, y_, dim, out, count);
    }
    held_[dim] = 1;
}

} // namespace stipple::render
