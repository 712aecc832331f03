#include "image_metrics.h"

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
