// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Warps from [0,1)^n to the domains the renderer samples; each documents the measure of its pdf.
#pragma once

#include "core/geometry.h"

namespace stipple::render {

struct Point2 {
    float x = 0, y = 0;
};

// Concentric map of the unit square to the unit disk (Shirley & Chiu), keeps strata compact.
inline Point2 sampleUniformDiskConcentric(Point2 u) {
    float ox = 2 * u.x - 1, oy = 2 * u.y - 1;
    if (ox == 0 && oy == 0) return {0, 0};
    float r, theta;
    if (std::abs(ox) > std::abs(oy)) {
        r = ox;
        theta = (kPi / 4) * (oy / ox);
    } else {
        r = oy;
        theta = kPi / 2 - (kPi / 4) * (ox / oy);
    }
    return {r * std::cos(theta), r * std::sin(theta)};
}

// Cosine-weighted hemisphere about +z. pdf (solid angle) = cos(theta) / pi.
inline Vec3 sampleCosineHemisphere(Point2 u) {
    Point2 d = sampleUniformDiskConcentric(u);
    float z = safeSqrt(1 - d.x * d.x - d.y * d.y);
    return {d.x, d.y, z};
}
inline float cosineHemispherePdf(float cosTheta) { return cosTheta * kInvPi; }

// Uniform sphere. pdf (solid angle) = 1 / (4 pi).
inline Vec3 sampleUniformSphere(Point2 u) {
    float z = 1 - 2 * u.x;
    float r = safeSqrt(1 - z * z);
    float phi = 2 * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// Barycentrics uniform over a triangle (Heitz 2019's low-distortion map: keeps strata compact).
inline void sampleUniformTriangle(Point2 u, float& b0, float& b1) {
    if (u.x < u.y) {
        b0 = u.x / 2;
        b1 = u.y - b0;
    } else {
        b1 = u.y / 2;
        b0 = u.x - b1;
    }
}

// Power heuristic with beta = 2 for one sample of each strategy (counts fold into the pdfs).
inline float powerHeuristic(float fPdf, float gPdf) {
    if (std::isinf(fPdf)) return 1;
    float f = fPdf * fPdf, g = gPdf * gPdf;
    if (f + g == 0) return 0;
    return f / (f + g);
}

} // namespace stipple::render
