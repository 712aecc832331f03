// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The film: a box filter of one pixel (every sample lands in the pixel that drew it), double accumulation and a
// per-pixel running mean and variance (Welford). Non-finite samples are counted and never accumulated.
// Each pixel is written by the one thread that renders its tile, so no locking is needed.
//
// Splats (light tracing, BDPT's t = 1 strategy) land on arbitrary pixels. For determinism they are never added
// in thread order: each tile owns a SplatList, filled by the thread that renders that tile, and after the render
// loop Film::mergeSplats adds the lists in tile index order. The image is therefore bitwise identical for any
// thread count. Splat values are divided by spp when merged (each camera sample splats its own contribution).
#pragma once

#include "core/geometry.h"
#include "sampling/warps.h"

#include <cstdint>
#include <vector>

namespace stipple::render {

struct Splat {
    int x, y;
    Spectrum L;
};

class SplatList {
public:
    // Adds L at raster position p (ignored outside the image or when not finite; the latter is counted).
    void add(Point2 p, const Spectrum& L, int width, int height);
    const std::vector<Splat>& splats() const { return splats_; }
    uint64_t nonFinite() const { return nonFinite_; }

private:
    std::vector<Splat> splats_;
    uint64_t nonFinite_ = 0;
};

class Film {
public:
    Film(int width, int height);
    int width() const { return width_; }
    int height() const { return height_; }

    // One sample of pixel (x, y); returns false (and accumulates nothing) when L is not finite.
    bool addSample(int x, int y, const Spectrum& L);
    // Adds every tile's splats, in the order of `lists` (tile index order), scaled by 1/spp.
    void mergeSplats(const std::vector<SplatList>& lists, uint32_t spp);

    // Mean radiance per pixel, plus the merged splats.
    std::vector<float> mean() const;
    // Variance of the per-pixel mean: sample variance / n (0 for n < 2). Splats are not included.
    std::vector<float> varianceOfMean() const;

private:
    struct Pixel {
        double n = 0;
        double mean[3] = {0, 0, 0};
        double m2[3] = {0, 0, 0};
    };
    int width_, height_;
    std::vector<Pixel> pixels_;
    std::vector<double> splat_;
};

} // namespace stipple::render
