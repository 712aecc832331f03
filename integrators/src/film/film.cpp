// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "film/film.h"

namespace stipple::render {

void SplatList::add(Point2 p, const Spectrum& L, int width, int height) {
    if (!L.isFinite()) {
        ++nonFinite_;
        return;
    }
    int x = int(std::floor(p.x)), y = int(std::floor(p.y));
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    splats_.push_back({x, y, L});
}

Film::Film(int width, int height)
    : width_(width), height_(height), pixels_(size_t(width) * height), splat_(size_t(width) * height * 3, 0.0) {}

bool Film::addSample(int x, int y, const Spectrum& L) {
    if (!L.isFinite()) return false;
    Pixel& px = pixels_[size_t(y) * width_ + x];
    px.n += 1;
    for (int c = 0; c < 3; ++c) {
        double v = L[c];
        double delta = v - px.mean[c];
        px.mean[c] += delta / px.n;
        px.m2[c] += delta * (v - px.mean[c]);
    }
    return true;
}

void Film::mergeSplats(const std::vector<SplatList>& lists, uint32_t spp) {
    double scale = 1.0 / double(spp);
    for (const SplatList& list : lists)
        for (const Splat& s : list.splats()) {
            double* d = &splat_[3 * (size_t(s.y) * width_ + s.x)];
            for (int c = 0; c < 3; ++c) d[c] += double(s.L[c]) * scale;
        }
}

std::vector<float> Film::mean() const {
    std::vector<float> out(pixels_.size() * 3);
    for (size_t i = 0; i < pixels_.size(); ++i)
        for (int c = 0; c < 3; ++c) out[3 * i + c] = float(pixels_[i].mean[c] + splat_[3 * i + c]);
    return out;
}

std::vector<float> Film::varianceOfMean() const {
    std::vector<float> out(pixels_.size() * 3, 0.0f);
    for (size_t i = 0; i < pixels_.size(); ++i) {
        double n = pixels_[i].n;
        if (n < 2) continue;
        for (int c = 0; c < 3; ++c) out[3 * i + c] = float(pixels_[i].m2[c] / (n - 1) / n);
    }
    return out;
}

} // namespace stipple::render
