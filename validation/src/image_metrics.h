// Error of a render against a reference: the study's RMS (its equation 1) and the reference's noise floor.
// Images are the renderer's Image (a plain struct; this file needs no renderer code).
#pragma once

#include <cstdint>

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

// MSE with the reference noise removed: max(mse − floor, 0).
inline double correctedMse(double mse, double floor) { return mse > floor ? mse - floor : 0.0; }
// A cell whose corrected MSE is within 2× the floor cannot be told apart from the reference's noise.
inline bool floorLimited(double correctedMse, double floor) { return correctedMse <= 2.0 * floor; }

// Copies the w×h region at (x, y) (clamped to the image), each pixel repeated `scale` times in x and y.
Image cropImage(const Image& image, int x, int y, int w, int h, int scale = 1);

} // namespace stipple::validation
