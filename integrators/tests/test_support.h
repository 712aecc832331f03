// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Helpers shared by the renderer's tests: scene files in a temporary directory and image statistics.
#pragma once

#include <stipple/render/renderer.h>

#include <stipple/testing/scratch_folder.h>
#include <stipple/testing/statistics.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace stipple::render::test {

inline std::string scenePath(const std::string& name) { return std::string(STIPPLE_TEST_SCENES) + "/" + name; }

// Writes `text` to a fresh file in a per-process temporary directory and returns its path.
inline std::string writeTempFile(const std::string& name, const std::string& text) {
    namespace fs = std::filesystem;
    fs::path dir = stipple::testing::scratchRoot() / "render";
    fs::create_directories(dir);
    fs::path p = dir / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
}

// Mean over pixels and channels, and a bound on the variance of that mean from the per-pixel variances.
struct ImageEstimate {
    double mean = 0;
    double variance = 0;
};

inline ImageEstimate estimate(const RenderResult& r, int x0 = 0, int y0 = 0, int w = -1, int h = -1) {
    if (w < 0) w = r.image.width;
    if (h < 0) h = r.image.height;
    ImageEstimate e;
    double n = double(w) * h;
    for (int y = y0; y < y0 + h; ++y)
        for (int x = x0; x < x0 + w; ++x) {
            // Channels share paths, so they are correlated: bound the variance of their average by the square
            // of the mean standard deviation (exact for fully correlated channels).
            double sd = 0;
            for (int c = 0; c < 3; ++c) {
                e.mean += r.image.pixel(x, y)[c] / (3 * n);
                sd += std::sqrt(double(r.variance.pixel(x, y)[c])) / 3;
            }
            e.variance += sd * sd / (n * n);
        }
    return e;
}

// The same render with 1 and with 2 threads, at 40 x 24 (not a multiple of the tile size: partial tiles too).
struct OneAndTwoThreads {
    RenderResult one, two;
};
inline OneAndTwoThreads renderWithOneAndTwoThreads(const std::string& sceneFile, RenderOptions o) {
    auto s = Scene::load(scenePath(sceneFile));
    o.spp = 4;
    o.width = 40;
    o.height = 24;
    o.threads = 1;
    OneAndTwoThreads r;
    r.one = s->render(o);
    o.threads = 2;
    r.two = s->render(o);
    return r;
}

inline bool bitwiseEqual(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.rgb.size() == b.rgb.size() &&
           std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

using stipple::testing::sidakZ;

} // namespace stipple::render::test
