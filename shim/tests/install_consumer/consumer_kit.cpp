// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// consumer_kit.cpp — a C++11 host without exceptions: the installed stipple.hpp, linked, one array through the cursor.
#include <stipple/stipple.hpp>

#include <cstdio>

int main() {
    stipple::Sampler sampler("stratified+blue-noise", 16, 7);
    if (!sampler) {
        std::fprintf(stderr, "consumer_kit: %s\n", sampler.status().message().c_str());
        return 1;
    }
    stipple::PixelSampleCursor cursor(sampler);
    cursor.start(stipple::Pixel{-1, 2}, 3);
    const float* uv = cursor.get2DArray(4);
    const float u = cursor.get1D();
    if (!cursor.status().ok()) {
        std::fprintf(stderr, "consumer_kit: %s\n", cursor.status().message().c_str());
        return 1;
    }
    for (int i = 0; i < 8; ++i)
        if (!(uv[i] >= 0.0f && uv[i] < 1.0f)) return 1;
    if (!(u >= 0.0f && u < 1.0f)) return 1;
    std::printf("consumer_kit: an array of 4 and a stream value through the installed stipple.hpp\n");
    return 0;
}
