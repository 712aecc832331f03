// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "metrics/image_metrics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace stipple::validation {

namespace {
bool finitePixel(const float* p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }

void checkShape(const Image& image, const char* what) {
    if (image.width <= 0 || image.height <= 0 || image.rgb.size() != size_t(image.width) * image.height * 3)
        throw std::invalid_argument(std::string(what) + " image is malformed: " + std::to_string(image.width) + "x" +
                                    std::to_string(image.height) + " with " + std::to_string(image.rgb.size()) +
                                    " floats (expected width*height*3)");
}
} // namespace

ImageError compareImages(const Image& reference, const Image& image) {
    checkShape(reference, "reference");
    checkShape(image, "compared");
    if (reference.width != image.width || reference.height != image.height)
        throw std::invalid_argument("image size mismatch: reference is " + std::to_string(reference.width) + "x" +
                                    std::to_string(reference.height) + ", image is " + std::to_string(image.width) +
                                    "x" + std::to_string(image.height));
    ImageError e;
    double sum = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float* r = reference.pixel(x, y);
            const float* p = image.pixel(x, y);
            if (!finitePixel(r) || !finitePixel(p)) {
                ++e.nonFinitePixels;
                continue;
            }
            for (int c = 0; c < 3; ++c) {
                double d = double(r[c]) - double(p[c]);
                sum += d * d;
            }
            ++e.pixels;
        }
    e.mse = e.pixels ? sum / double(e.pixels) : std::nan("");
    e.rms = std::sqrt(e.mse);
    return e;
}

std::string unmeasurableWhy(const ImageError& error) {
    const uint64_t all = error.pixels + error.nonFinitePixels;
    if (error.pixels == 0) return "no pixel is finite in both the image and the reference (" + std::to_string(all) + " pixels)";
    if (double(error.nonFinitePixels) > kMaxNonFinitePixelShare * double(all))
        return std::to_string(error.nonFinitePixels) + " of " + std::to_string(all) +
               " pixels are not finite (NaN or infinite) in the image or the reference; at most " +
               std::to_string(kMaxNonFinitePixelShare * 100).substr(0, 4) + "% may be";
    return "";
}

double noiseFloor(const Image& varianceOfMean) {
    checkShape(varianceOfMean, "variance");
    double sum = 0;
    uint64_t n = 0;
    for (int y = 0; y < varianceOfMean.height; ++y)
        for (int x = 0; x < varianceOfMean.width; ++x) {
            const float* v = varianceOfMean.pixel(x, y);
            if (!finitePixel(v)) continue;
            sum += double(v[0]) + double(v[1]) + double(v[2]);
            ++n;
        }
    return n ? sum / double(n) : 0.0;
}

namespace {
// Viridis at nine stops (sRGB, 0-255), linearly interpolated.
void viridis(double t, float* rgb) {
    static const unsigned char stops[9][3] = {{68, 1, 84},    {71, 44, 122},  {59, 81, 139},
                                              {44, 113, 142}, {33, 144, 141}, {39, 173, 129},
                                              {92, 200, 99},  {170, 220, 50}, {253, 231, 37}};
    t = std::clamp(std::isfinite(t) ? t : 1.0, 0.0, 1.0) * 8;
    const int i = std::min(int(t), 7);
    const double f = t - i;
    for (int c = 0; c < 3; ++c) {
        const double srgb = ((1 - f) * stops[i][c] + f * stops[i + 1][c]) / 255.0;
        // The PNG writer encodes linear values as sRGB: undo that here.
        rgb[c] = float(srgb <= 0.04045 ? srgb / 12.92 : std::pow((srgb + 0.055) / 1.055, 2.4));
    }
}

double pixelError(const Image& reference, const Image& image, int x, int y) {
    const float* r = reference.pixel(x, y);
    const float* p = image.pixel(x, y);
    if (!finitePixel(r) || !finitePixel(p)) return INFINITY;
    double sum = 0;
    for (int c = 0; c < 3; ++c) sum += (double(r[c]) - double(p[c])) * (double(r[c]) - double(p[c]));
    return std::sqrt(sum);
}
} // namespace

Image errorMap(const Image& reference, const Image& image, int x, int y, int w, int h, double scale, int magnify) {
    Image map;
    map.width = w;
    map.height = h;
    map.rgb.resize(size_t(w) * h * 3);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            viridis(scale > 0 ? pixelError(reference, image, x + i, y + j) / scale : 0, map.pixel(i, j));
    return cropImage(map, 0, 0, w, h, magnify);
}

double errorQuantile(const Image& reference, const Image& image, int x, int y, int w, int h, double q) {
    std::vector<double> e;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            if (const double v = pixelError(reference, image, x + i, y + j); std::isfinite(v)) e.push_back(v);
    if (e.empty()) return 0;
    const size_t k = std::min(e.size() - 1, size_t(q * double(e.size())));
    std::nth_element(e.begin(), e.begin() + long(k), e.end());
    return e[k];
}

Image errorColourBar(int width, int height) {
    Image bar;
    bar.width = width;
    bar.height = height;
    bar.rgb.resize(size_t(width) * height * 3);
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) viridis(double(i) / std::max(width - 1, 1), bar.pixel(i, j));
    return bar;
}

int blockColumns(int w) { return (w + kErrorBlockSize - 1) / kErrorBlockSize; }
int blockCount(int w, int h) { return blockColumns(w) * blockColumns(h); }

namespace {

// Per 8x8 block of the window (x, y, w, h): the sum over its finite pixels of score(squared RGB error, pixel index).
template <typename Score>
std::vector<double> sumPerBlock(const Image& reference, const Image& image, int x, int y, int w, int h, Score score) {
    checkShape(reference, "reference");
    checkShape(image, "compared");
    std::vector<double> blocks(size_t(blockCount(w, h)), 0.0);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const float* r = reference.pixel(x + i, y + j);
            const float* p = image.pixel(x + i, y + j);
            if (!finitePixel(r) || !finitePixel(p)) continue;
            double sum = 0;
            for (int c = 0; c < 3; ++c) sum += (double(r[c]) - double(p[c])) * (double(r[c]) - double(p[c]));
            const size_t pixel = size_t(y + j) * size_t(reference.width) + size_t(x + i);
            blocks[size_t(j / kErrorBlockSize) * blockColumns(w) + i / kErrorBlockSize] += score(sum, pixel);
        }
    return blocks;
}

} // namespace

std::vector<double> blockSquaredErrors(const Image& reference, const Image& image, int x, int y, int w, int h) {
    return sumPerBlock(reference, image, x, y, w, h, [](double squared, size_t) { return squared; });
}

std::vector<float> relativeErrorWeights(const Image& reference, const Image& varianceOfMean) {
    checkShape(reference, "reference");
    checkShape(varianceOfMean, "variance");
    if (varianceOfMean.width != reference.width || varianceOfMean.height != reference.height)
        throw std::invalid_argument("relative error weights: the variance image is " +
                                    std::to_string(varianceOfMean.width) + "x" + std::to_string(varianceOfMean.height) +
                                    ", the reference " + std::to_string(reference.width) + "x" +
                                    std::to_string(reference.height));
    const size_t pixels = size_t(reference.width) * size_t(reference.height);
    std::vector<float> level(pixels, -1.0f);
    double sum = 0;
    size_t finite = 0;
    for (int j = 0; j < reference.height; ++j)
        for (int i = 0; i < reference.width; ++i) {
            const float* r = reference.pixel(i, j);
            if (!finitePixel(r)) continue;
            const double v = std::abs((double(r[0]) + double(r[1]) + double(r[2])) / 3.0);
            level[size_t(j) * size_t(reference.width) + size_t(i)] = float(v);
            sum += v;
            ++finite;
        }
    const double m = finite ? sum / double(finite) : 0.0;
    std::vector<double> weights(pixels, 0.0);
    for (size_t p = 0; p < pixels; ++p)
        if (level[p] >= 0 && double(level[p]) + m > 0)
            weights[p] = 1.0 / ((double(level[p]) + m) * (double(level[p]) + m));

    // The reference's noise per block in relative units (its variance of the mean: the per-sample variance over
    // its spp, the same factor in every pixel, so the ratio to the median does not depend on it).
    const int columns = blockColumns(reference.width);
    std::vector<double> noise(size_t(blockCount(reference.width, reference.height)), 0.0);
    std::vector<int> counted(noise.size(), 0);
    for (int j = 0; j < reference.height; ++j)
        for (int i = 0; i < reference.width; ++i) {
            const size_t p = size_t(j) * size_t(reference.width) + size_t(i);
            const float* v = varianceOfMean.pixel(i, j);
            if (weights[p] <= 0 || !finitePixel(v)) continue;
            const size_t b = size_t(j / kErrorBlockSize) * size_t(columns) + size_t(i / kErrorBlockSize);
            noise[b] += weights[p] * (std::abs(double(v[0])) + std::abs(double(v[1])) + std::abs(double(v[2])));
            ++counted[b];
        }
    std::vector<double> positive;
    for (size_t b = 0; b < noise.size(); ++b)
        if (counted[b] && (noise[b] /= counted[b]) > 0) positive.push_back(noise[b]);
    double median = 0;
    if (!positive.empty()) {
        std::nth_element(positive.begin(), positive.begin() + long(positive.size() / 2), positive.end());
        median = positive[positive.size() / 2];
    }
    std::vector<float> out(pixels, 0.0f);
    for (int j = 0; j < reference.height; ++j)
        for (int i = 0; i < reference.width; ++i) {
            const size_t p = size_t(j) * size_t(reference.width) + size_t(i);
            const double s = noise[size_t(j / kErrorBlockSize) * size_t(columns) + size_t(i / kErrorBlockSize)];
            out[p] = float(median > 0 && s > median ? weights[p] * median / s : weights[p]);
        }
    return out;
}

double relativeNoiseFloor(const Image& varianceOfMean, const std::vector<float>& weights, int x, int y, int w, int h) {
    checkShape(varianceOfMean, "variance");
    if (weights.size() != size_t(varianceOfMean.width) * size_t(varianceOfMean.height))
        throw std::invalid_argument("relative noise floor: the weights do not match the variance image's size");
    double sum = 0;
    uint64_t n = 0;
    for (int j = y; j < y + h; ++j)
        for (int i = x; i < x + w; ++i) {
            const float* v = varianceOfMean.pixel(i, j);
            if (!finitePixel(v)) continue;
            sum += double(weights[size_t(j) * size_t(varianceOfMean.width) + size_t(i)]) *
                   (double(v[0]) + double(v[1]) + double(v[2]));
            ++n;
        }
    return n ? sum / double(n) : 0.0;
}

std::vector<double> blockRelativeSquaredErrors(const Image& reference, const Image& image,
                                               const std::vector<float>& weights, int x, int y, int w, int h) {
    if (weights.size() != size_t(reference.width) * size_t(reference.height))
        throw std::invalid_argument("relative squared errors: the weights do not match the reference's size");
    const double cap = 3.0 * kRelativeErrorCap * kRelativeErrorCap;
    return sumPerBlock(reference, image, x, y, w, h,
                       [&](double squared, size_t pixel) { return std::min(double(weights[pixel]) * squared, cap); });
}

std::vector<double> blockSums(const std::vector<float>& map, int mapWidth, int x, int y, int w, int h) {
    std::vector<double> blocks(size_t(blockCount(w, h)), 0.0);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const float v = map[size_t(y + j) * size_t(mapWidth) + size_t(x + i)];
            if (std::isfinite(v)) blocks[size_t(j / kErrorBlockSize) * blockColumns(w) + i / kErrorBlockSize] += v;
        }
    return blocks;
}

Image cropImage(const Image& image, int x, int y, int w, int h, int scale) {
    checkShape(image, "cropped");
    scale = std::max(scale, 1);
    w = std::clamp(w, 1, image.width);
    h = std::clamp(h, 1, image.height);
    x = std::clamp(x, 0, image.width - w);
    y = std::clamp(y, 0, image.height - h);
    Image out;
    out.width = w * scale;
    out.height = h * scale;
    out.rgb.resize(size_t(out.width) * out.height * 3);
    for (int j = 0; j < out.height; ++j)
        for (int i = 0; i < out.width; ++i) {
            const float* s = image.pixel(x + i / scale, y + j / scale);
            std::copy(s, s + 3, out.pixel(i, j));
        }
    return out;
}

} // namespace stipple::validation
