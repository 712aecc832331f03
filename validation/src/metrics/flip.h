// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// FLIP (Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström, Fairchild: "FLIP: A Difference Evaluator for
// Alternating Images", HPG 2020), the LDR version: a per-pixel perceptual difference in [0, 1] between two
// sRGB images seen at a given number of pixels per degree of visual angle.
//
// Colour pipeline: sRGB → linear RGB → XYZ → YCxCz (a linearised opponent space); each channel blurred by its
// contrast sensitivity function (sums of Gaussians whose widths scale with the pixels per degree), back to linear
// RGB clamped to the unit cube, → CIELAB with the Hunt adjustment (a, b scaled by 0.01 L); the HyAB distance
// |ΔL| + ‖Δ(a, b)‖ raised to 0.7 and remapped to [0, 1] (differences below 40% of the largest possible — green
// against blue — fill [0, 0.95], the rest (0.95, 1]).
// Feature pipeline: on the achromatic channel ((Y_YCxCz + 16) / 116), first and second derivatives of a
// Gaussian (σ = 0.5 · 0.082° in pixels) detect edges and points; the feature difference is
// sqrt(max(|Δ‖edge‖|, |Δ‖point‖|) / √2). FLIP = colour difference ^ (1 − feature difference): a colour error
// counts more where the images' edges or points differ.
#pragma once

#include <vector>

#include "metrics/image_metrics.h"

namespace stipple::validation {

// 0.7 m wide 4K monitor seen from 0.7 m: 3840 / (2 atan(0.5) in degrees) ≈ 67 pixels per degree.
inline constexpr double kFlipDefaultPixelsPerDegree = 0.7 * 3840 / 0.7 * 3.14159265358979323846 / 180;

struct FlipMaps {
    int width = 0, height = 0;
    std::vector<float> color;   // colour difference per pixel, [0, 1]
    std::vector<float> feature; // feature difference per pixel, [0, 1]
    std::vector<float> flip;    // color ^ (1 − feature)
    double mean() const;
};

// Both images hold sRGB-encoded values in [0, 1] (clamped). Throws std::invalid_argument on a size mismatch.
FlipMaps ldrFlipSrgb(const Image& referenceSrgb, const Image& testSrgb,
                     double pixelsPerDegree = kFlipDefaultPixelsPerDegree);

// Scene-linear renders as the report shows them: exposure 0, clamped to [0, 1], sRGB-encoded; then LDR-FLIP.
FlipMaps ldrFlipLinear(const Image& reference, const Image& test, double pixelsPerDegree = kFlipDefaultPixelsPerDegree);

} // namespace stipple::validation
