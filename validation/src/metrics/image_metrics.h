// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Error of a render against a reference: the study's RMS (its equation 1) and the reference's noise floor.
// Images are the renderer's Image (a plain struct; this file needs no renderer code).
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <stipple/render/renderer.h>

namespace stipple::validation {

using render::Image;

struct ImageError {
    double mse = 0;               // (1/P) Σ_pixels Σ_rgb (I_ref − I)², P = finite pixel count
    double rms = 0;               // sqrt(mse): the study's equation 1
    uint64_t pixels = 0;          // pixels compared (finite in both images)
    uint64_t nonFinitePixels = 0; // pixels with a non-finite channel in either image: counted, excluded
};

// Throws std::invalid_argument naming both sizes when the images differ in size.
ImageError compareImages(const Image& reference, const Image& image);

// E[contribution of the reference's own noise to the MSE]: the mean over pixels of the per-pixel variance of
// the reference's mean, summed over channels. `varianceOfMean` is the renderer's variance image.
// Non-finite pixels are skipped.
double noiseFloor(const Image& varianceOfMean);

// The largest share of a cell's pixels that may be non-finite (in the render or the reference): they are
// excluded from the error, and beyond this share the error of the rest says nothing of the image, so the cell is
// an error (measurableError). An image with no finite pixel has no error at all.
inline constexpr double kMaxNonFinitePixelShare = 0.01;

// "" when the error can be trusted: some pixel compared, and at most kMaxNonFinitePixelShare of them non-finite.
// Else why not, with the counts.
std::string unmeasurableWhy(const ImageError& error);

// MSE with the reference noise removed: max(mse − floor, 0). Not a number when either is not: a broken
// measurement never becomes an error of 0.
inline double correctedMse(double mse, double floor) {
    if (std::isnan(mse) || std::isnan(floor)) return mse + floor;
    return mse > floor ? mse - floor : 0.0;
}
// A cell whose corrected MSE is within 2× the floor cannot be told apart from the reference's noise.
inline bool floorLimited(double correctedMse, double floor) { return correctedMse <= 2.0 * floor; }

// Error per block, for intervals that need no more seeds: where pixels are sampled independently, blocks of
// pixels are independent replicates within one render, and the K seeds' values of one block give its variance.
inline constexpr int kErrorBlockSize = 8;
// Blocks of a w × h rectangle: row-major from its top left, kErrorBlockSize square, the last column and row cut short.
int blockColumns(int w);
int blockCount(int w, int h);
// Σ_pixels Σ_rgb (I_ref − I)² per block of the rectangle (x, y, w, h), finite pixels only.
std::vector<double> blockSquaredErrors(const Image& reference, const Image& image, int x, int y, int w, int h);
// Relative squared errors that neither a bright light, nor a light's edge, nor a firefly can decide: per pixel
// min(w_p · Σ_rgb (I_ref − I)², 3c²) with
//     w_p = 1 / ((r̄_p + m)² · max(1, S_b / S̃)),
// r̄_p the reference pixel's mean channel, m the reference image's mean (a dark pixel is measured against the
// image's level), S_b the reference's own per-sample noise in the pixel's 8 × 8 block in those relative units
// (the mean over the block of Σ_rgb Var(reference) / (r̄_p + m)²) and S̃ the median of S_b over the image's blocks.
// Relative, each pixel counts by its own brightness; but where one sample can hit or miss a small light (its edge,
// a penumbra it barely reaches) a pixel's relative error is 10–1000× the image's typical one whatever the pattern,
// and a few such blocks would hold nearly all of the error. Dividing by the block's noise above the median gives
// such a block the vote of a typical block: what it adds is its error relative to how noisy it is. The cap (an
// error of c times the pixel's level) bounds a rare bright path's share. Weights and cap depend on the reference
// only: every pattern and seed of a scene is measured by the same rule, so the ratio of two patterns' means
// compares the same fixed quantity.
inline constexpr double kRelativeErrorCap = 4.0; // c
// w_p per pixel of the reference (0 where it is not finite); varianceOfMean: the reference's variance image.
std::vector<float> relativeErrorWeights(const Image& reference, const Image& varianceOfMean);
// The reference's own noise in those units: the mean over the rectangle of weights[p] · Σ_rgb Var(reference).
double relativeNoiseFloor(const Image& varianceOfMean, const std::vector<float>& weights, int x, int y, int w, int h);
// Σ_pixels min(weights[p] · Σ_rgb (I_ref − I)², 3c²) per block of the rectangle (x, y, w, h), finite pixels only.
std::vector<double> blockRelativeSquaredErrors(const Image& reference, const Image& image,
                                               const std::vector<float>& weights, int x, int y, int w, int h);
// Σ_pixels of a per-pixel map (mapWidth wide, e.g. FLIP) per block of the rectangle.
std::vector<double> blockSums(const std::vector<float>& map, int mapWidth, int x, int y, int w, int h);

// A false-colour map (viridis, colour-blind safe) of the per-pixel error sqrt(Σ_rgb (I_ref − I)²) of the w×h region
// at (x, y), 0 to `scale` (clamped), each pixel repeated `magnify` times; its values are linear, so an sRGB PNG of it
// shows viridis' colours.
Image errorMap(const Image& reference, const Image& image, int x, int y, int w, int h, double scale, int magnify = 1);
// The q-quantile (0..1) of that per-pixel error over the region: a shared scale for several maps.
double errorQuantile(const Image& reference, const Image& image, int x, int y, int w, int h, double q);
// The colour bar of errorMap: `width` × `height`, 0 on the left.
Image errorColourBar(int width, int height);

// Copies the w×h region at (x, y) (clamped to the image), each pixel repeated `scale` times in x and y.
Image cropImage(const Image& image, int x, int y, int w, int h, int scale = 1);

} // namespace stipple::validation
