// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// analytic_host.cpp — a host renderer of libstipple as a C++11 program built without exceptions: every value
// through stipple.hpp's PixelSampleCursor, sample arrays for direct lighting (pbrt-v3's Get2DArray shape), errors
// through the status forms.
//
// Scene (analytic): a white Lambertian floor z = 0 seen from above, the image covering [0, 1]^2 of it; three
// square lights facing down at heights 0.25-0.4, each of its own colour. A pixel is the radiance leaving the floor
// at the pixel's centre, estimated per sample with k points on every light (one array of k 2D values per light).
// Its exact value is Lambert's polygon formula, so the renderer's bias is measurable.
//
//   analytic_host --pattern P --spp N --seed S --width W --height H --output image.pfm [--lights-per-sample k]
//       renders and writes a PFM (RGB, float) — the form stipple-validate's external-renderer template runs;
//   analytic_host --exact --width W --height H --output exact.pfm  writes the closed form;
//   analytic_host --check  runs the checks below and exits 1 if one fails:
//     1. unbiased: per pixel of a 6 x 5 image, 48 seeds of 16 samples, a two-sided t-test of the mean against the
//        closed form, alpha = 0.01 Sidak-corrected over pixels x channels x patterns;
//     2. stratified across N * k: for stratified, each light's 16 x 4 array values of a pixel hit every cell of the
//        8 x 8 grid once; for sobol and pmj02 they form a (0,6,2)-net (every elementary interval of area 1/64 once);
//     3. the cursor's batched values equal the sampler's per-sample array calls bitwise;
//     4. errors without exceptions: a pmj02 array past the pattern's set size is reported by cursor.status()
//        and predicted by stipple::patternLimits before creation; the render goes on.
#include <stipple/stipple.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

const double kPi = 3.14159265358979323846;

struct Vec3 {
    double x, y, z;
};
Vec3 sub(Vec3 a, Vec3 b) { return Vec3{a.x - b.x, a.y - b.y, a.z - b.z}; }
double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross(Vec3 a, Vec3 b) { return Vec3{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec3 normalize(Vec3 a) {
    const double l = std::sqrt(dot(a, a));
    return Vec3{a.x / l, a.y / l, a.z / l};
}

// A square light facing down (-z): corner, side, height, RGB radiance.
struct Light {
    double x0, y0, side, height;
    double radiance[3];
};
const Light kLights[] = {{0.10, 0.15, 0.30, 0.25, {4.0, 3.2, 2.0}},
                         {0.55, 0.45, 0.35, 0.40, {1.0, 2.5, 4.0}},
                         {0.30, 0.70, 0.15, 0.30, {3.0, 0.8, 0.8}}};
const int kLightCount = 3;

// Lambert: irradiance at p (normal +z) from a uniform polygon of radiance 1 is (1/2) sum_edges beta_e (gamma_e . n).
double exactIrradiance(const Light& l, Vec3 p) {
    const Vec3 v[4] = {Vec3{l.x0, l.y0, l.height}, Vec3{l.x0 + l.side, l.y0, l.height},
                       Vec3{l.x0 + l.side, l.y0 + l.side, l.height}, Vec3{l.x0, l.y0 + l.side, l.height}};
    double sum = 0;
    for (int e = 0; e < 4; ++e) {
        const Vec3 a = normalize(sub(v[e], p)), b = normalize(sub(v[(e + 1) % 4], p));
        const double beta = std::acos(std::max(-1.0, std::min(1.0, dot(a, b))));
        sum += beta * normalize(cross(a, b)).z;
    }
    return 0.5 * std::fabs(sum);
}

Vec3 pixelCentre(int i, int j, int width, int height) {
    return Vec3{(i + 0.5) / width, (j + 0.5) / height, 0.0};
}

void exactPixel(int i, int j, int width, int height, double rgb[3]) {
    const Vec3 p = pixelCentre(i, j, width, height);
    rgb[0] = rgb[1] = rgb[2] = 0;
    for (int l = 0; l < kLightCount; ++l) {
        const double e = exactIrradiance(kLights[l], p) / kPi; // radiance off a white Lambertian floor
        for (int c = 0; c < 3; ++c) rgb[c] += e * kLights[l].radiance[c];
    }
}

// One pixel sample: k area samples on every light, one array each. Returns false (cursor.status() says why) on
// a failed call; the values are then zeros and the sample is dropped by the caller.
bool estimateSample(stipple::PixelSampleCursor& cursor, Vec3 p, uint32_t k, double rgb[3]) {
    rgb[0] = rgb[1] = rgb[2] = 0;
    for (int l = 0; l < kLightCount; ++l) {
        const Light& light = kLights[l];
        const float* uv = cursor.get2DArray(k);
        double sum = 0;
        for (uint32_t j = 0; j < k; ++j) {
            const Vec3 q = {light.x0 + uv[2 * j] * light.side, light.y0 + uv[2 * j + 1] * light.side, light.height};
            const Vec3 d = sub(q, p);
            const double r2 = dot(d, d), cosine = d.z / std::sqrt(r2); // cos at the floor = cos at the light
            sum += cosine * cosine / r2;
        }
        const double e = sum * light.side * light.side / k / kPi;
        for (int c = 0; c < 3; ++c) rgb[c] += e * light.radiance[c];
    }
    return cursor.status().ok();
}

struct Image {
    int width, height;
    std::vector<float> rgb; // row-major from the top
};

// Renders with the cursor, pixel by pixel (all samples of a pixel in a row: the cursor's batches serve them).
bool render(const stipple::Sampler& sampler, uint32_t spp, uint32_t k, Image& image, std::string& error) {
    stipple::PixelSampleCursor cursor(sampler);
    image.rgb.assign(size_t(image.width) * image.height * 3, 0.0f);
    for (int j = 0; j < image.height; ++j)
        for (int i = 0; i < image.width; ++i) {
            const Vec3 p = pixelCentre(i, j, image.width, image.height);
            double sum[3] = {0, 0, 0};
            for (uint32_t s = 0; s < spp; ++s) {
                cursor.start(stipple::Pixel{i, j}, s);
                double rgb[3];
                if (!estimateSample(cursor, p, k, rgb)) {
                    error = cursor.status().message();
                    return false;
                }
                for (int c = 0; c < 3; ++c) sum[c] += rgb[c];
            }
            for (int c = 0; c < 3; ++c) image.rgb[(size_t(j) * image.width + i) * 3 + c] = float(sum[c] / spp);
        }
    return true;
}

// PFM: "PF", width height, -1 (little-endian), rows bottom to top. Written to a temporary name, then renamed.
bool writePfm(const std::string& path, const Image& image) {
    const std::string partial = path + ".partial";
    std::FILE* f = std::fopen(partial.c_str(), "wb");
    if (!f) return false;
    std::fprintf(f, "PF\n%d %d\n-1.0\n", image.width, image.height);
    bool ok = true;
    for (int j = image.height - 1; j >= 0; --j)
        ok = ok && std::fwrite(&image.rgb[size_t(j) * image.width * 3], sizeof(float), size_t(image.width) * 3, f) ==
                       size_t(image.width) * 3;
    ok = std::fclose(f) == 0 && ok;
    return ok && std::rename(partial.c_str(), path.c_str()) == 0;
}

// ---- checks -----------------------------------------------------------------------------------------------------

// Two-sided critical value of Student's t with nu degrees of freedom at level alpha: the normal quantile by
// bisection on erfc, then the Cornish-Fisher expansion (accurate to ~1e-3 for nu >= 30).
double tCritical(double alpha, double nu) {
    double lo = 0, hi = 40;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > alpha ? lo : hi) = mid;
    }
    const double z = 0.5 * (lo + hi), z3 = z * z * z, z5 = z3 * z * z, z7 = z5 * z * z;
    return z + (z3 + z) / (4 * nu) + (5 * z5 + 16 * z3 + 3 * z) / (96 * nu * nu) +
           (3 * z7 + 19 * z5 + 17 * z3 - 15 * z) / (384 * nu * nu * nu);
}

int failures = 0;
void expect(bool ok, const std::string& what) {
    std::printf("%s: %s\n", ok ? "ok  " : "FAIL", what.c_str());
    if (!ok) ++failures;
}

void checkUnbiased() {
    const char* patterns[] = {"independent", "stratified", "sobol", "stratified+blue-noise"};
    const int width = 6, height = 5, seeds = 48;
    const uint32_t spp = 16, k = 4;
    const double alpha = 1 - std::pow(1 - 0.01, 1.0 / (width * height * 3 * 4));
    const double critical = tCritical(alpha, seeds - 1);
    for (int p = 0; p < 4; ++p) {
        std::vector<double> sum(size_t(width) * height * 3, 0.0), sum2(sum.size(), 0.0);
        for (int s = 0; s < seeds; ++s) {
            stipple::Sampler sampler(patterns[p], spp, uint64_t(9001 + s));
            Image image = {width, height, std::vector<float>()};
            std::string error;
            if (!sampler || !render(sampler, spp, k, image, error)) {
                expect(false, std::string(patterns[p]) + ": " + (sampler ? error : sampler.status().message()));
                return;
            }
            for (size_t v = 0; v < sum.size(); ++v) {
                sum[v] += image.rgb[v];
                sum2[v] += double(image.rgb[v]) * image.rgb[v];
            }
        }
        double worst = 0;
        for (int j = 0; j < height; ++j)
            for (int i = 0; i < width; ++i) {
                double exact[3];
                exactPixel(i, j, width, height, exact);
                for (int c = 0; c < 3; ++c) {
                    const size_t v = (size_t(j) * width + i) * 3 + c;
                    const double mean = sum[v] / seeds, var = (sum2[v] - seeds * mean * mean) / (seeds - 1);
                    const double t = (mean - exact[c]) / std::sqrt(std::max(var, 1e-300) / seeds);
                    worst = std::max(worst, std::fabs(t));
                }
            }
        char line[160];
        std::snprintf(line, sizeof line, "%s: unbiased, max |t| %.2f over %d pixels x 3 (critical %.2f, %d seeds)",
                      patterns[p], worst, width * height, critical, seeds);
        expect(worst < critical, line);
    }
}

// Every elementary interval of area 1/M (M = 2^m: 2^a x 2^(m-a) cells) holds exactly one of the M points.
bool isNet(const std::vector<float>& uv, int m) {
    const size_t count = uv.size() / 2;
    for (int a = 0; a <= m; ++a) {
        std::vector<int> hits(count, 0);
        for (size_t p = 0; p < count; ++p) {
            const size_t cx = size_t(uv[2 * p] * (1u << a)), cy = size_t(uv[2 * p + 1] * (1u << (m - a)));
            if (++hits[cy * (size_t(1) << a) + cx] > 1) return false;
        }
    }
    return true;
}

void checkStratifiedArrays() {
    const uint32_t spp = 16, k = 4; // 64 points per light and pixel: an 8 x 8 grid, a (0,6,2)-net
    const char* patterns[] = {"stratified", "sobol", "pmj02"};
    for (int p = 0; p < 3; ++p) {
        stipple::Sampler sampler(patterns[p], spp, 77);
        stipple::PixelSampleCursor cursor(sampler);
        bool ok = bool(sampler), equal = true;
        for (int pixel = 0; pixel < 12 && ok; ++pixel) {
            const stipple::Pixel px = {pixel % 4 - 1, pixel / 4}; // negative pixels too
            std::vector<std::vector<float> > points(kLightCount);
            for (uint32_t s = 0; s < spp; ++s) {
                cursor.start(px, s);
                for (int l = 0; l < kLightCount; ++l) {
                    const float* uv = cursor.get2DArray(k);
                    points[l].insert(points[l].end(), uv, uv + 2 * k);
                    float direct[2 * 4];
                    if (!sampler.array(px, s, uint32_t(l), 2, k, direct).ok() ||
                        std::memcmp(direct, uv, sizeof direct) != 0)
                        equal = false;
                }
            }
            ok = cursor.status().ok();
            for (int l = 0; l < kLightCount && ok; ++l) {
                if (p == 0) {
                    std::vector<int> cells(64, 0);
                    for (size_t q = 0; q < 64; ++q) ++cells[size_t(points[l][2 * q + 1] * 8) * 8 + size_t(points[l][2 * q] * 8)];
                    for (int c = 0; c < 64; ++c) ok = ok && cells[c] == 1;
                } else {
                    ok = isNet(points[l], 6);
                }
            }
        }
        expect(ok, std::string(patterns[p]) + ": every light's 16 x 4 array values of a pixel are " +
                       (p == 0 ? "one per cell of the 8 x 8 grid" : "a (0,6,2)-net"));
        expect(equal, std::string(patterns[p]) + ": the cursor's batched arrays equal Sampler::array bitwise");
    }
}

void checkErrorsWithoutExceptions() {
    stipple_pattern_limits limits;
    const stipple::Status s = stipple::patternLimits("pmj02", limits);
    expect(s.ok() && limits.max_set_size == 65536, "pmj02's limits say sets of at most 65536 points");
    stipple::Sampler sampler("pmj02", 32768, 1);
    stipple::PixelSampleCursor cursor(sampler);
    cursor.start(stipple::Pixel{0, 0}, 0);
    const float* uv = cursor.get2DArray(4); // 4 * 32768 points: past the limit
    const bool reported = !cursor.status().ok() && cursor.status().code() == STIPPLE_ERROR_OUT_OF_RANGE &&
                          cursor.status().message().find("65536") != std::string::npos && uv[0] == 0.0f;
    expect(reported, "a pmj02 array of 131072 points is reported by cursor.status(): " + cursor.status().message());
    stipple::Sampler bad("sobol+blue-noise+extra", 16, 1);
    expect(!bad && bad.status().code() == STIPPLE_ERROR_INVALID_ARGUMENT,
           "a bad pattern name is reported by sampler.status(): " + bad.status().message());
    std::vector<std::string> names;
    expect(stipple::patternNames(names).ok() && names.size() >= 6 && names[4] == "sobol",
           "pattern listing names the library's patterns");
}

int usage(const char* message) {
    std::fprintf(stderr,
                 "analytic_host: %s\nusage: analytic_host --pattern P --spp N --seed S --width W --height H "
                 "--output image.pfm [--lights-per-sample k]\n       analytic_host --exact --width W --height H "
                 "--output exact.pfm\n       analytic_host --check\n",
                 message);
    return 2;
}

bool parseUnsigned(const char* text, unsigned long long max, unsigned long long& out) {
    char* end = nullptr;
    if (!*text || *text == '-') return false;
    out = std::strtoull(text, &end, 10);
    return *end == '\0' && out <= max && out > 0;
}

} // namespace

int main(int argc, char** argv) {
    std::string pattern, output;
    unsigned long long spp = 0, seed = 0, width = 0, height = 0, k = 4;
    bool exact = false;
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        if (arg == "--check") {
            checkUnbiased();
            checkStratifiedArrays();
            checkErrorsWithoutExceptions();
            std::printf("%s\n", failures ? "analytic_host: checks FAILED" : "analytic_host: all checks passed");
            return failures ? 1 : 0;
        }
        if (arg == "--exact") {
            exact = true;
            continue;
        }
        if (a + 1 >= argc) return usage((arg + " needs a value").c_str());
        const char* value = argv[++a];
        bool ok = true;
        if (arg == "--pattern") pattern = value;
        else if (arg == "--output") output = value;
        else if (arg == "--spp") ok = parseUnsigned(value, 1u << 20, spp);
        else if (arg == "--seed") ok = parseUnsigned(value, ~0ull, seed) || std::strcmp(value, "0") == 0;
        else if (arg == "--width") ok = parseUnsigned(value, 1u << 14, width);
        else if (arg == "--height") ok = parseUnsigned(value, 1u << 14, height);
        else if (arg == "--lights-per-sample") ok = parseUnsigned(value, 1024, k);
        else return usage(("unknown option " + arg).c_str());
        if (!ok) return usage((arg + " " + value + ": expected a positive integer in range").c_str());
    }
    if (output.empty() || !width || !height) return usage("--output, --width and --height are required");
    Image image = {int(width), int(height), std::vector<float>()};
    if (exact) {
        image.rgb.resize(size_t(width) * height * 3);
        for (int j = 0; j < image.height; ++j)
            for (int i = 0; i < image.width; ++i) {
                double rgb[3];
                exactPixel(i, j, image.width, image.height, rgb);
                for (int c = 0; c < 3; ++c) image.rgb[(size_t(j) * width + i) * 3 + c] = float(rgb[c]);
            }
    } else {
        if (pattern.empty() || !spp) return usage("--pattern and --spp are required");
        stipple::Sampler sampler(pattern, uint32_t(spp), seed);
        if (!sampler) {
            std::fprintf(stderr, "analytic_host: %s\n", sampler.status().message().c_str());
            return 1;
        }
        std::string error;
        if (!render(sampler, uint32_t(spp), uint32_t(k), image, error)) {
            std::fprintf(stderr, "analytic_host: %s\n", error.c_str());
            return 1;
        }
    }
    if (!writePfm(output, image)) {
        std::fprintf(stderr, "analytic_host: cannot write %s\n", output.c_str());
        return 1;
    }
    return 0;
}
