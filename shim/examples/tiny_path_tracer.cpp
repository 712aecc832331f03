// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// tiny_path_tracer.cpp — a C++ host of libstipple written like a pbrt-v4 integrator: no declared layout, values
// asked by call order through stipple.hpp's PixelSampleCursor, calls skipped on data-dependent branches.
//
// Scene (analytic): the camera sits at the centre of a unit sphere and looks at its inside. The image is an
// equal-area map of directions: pixel (i, j) spans phi in [phi0 + i dphi, ...) and z = cos(theta) in
// [-1 + j dz, ...). The sphere's inside emits E = 1 where z > 0.5 and is diffuse with albedo 0.6 where y > 0 and
// a two-lobe diffuse mix (albedo 0.8 or 0.2, each picked with probability 1/2) where y < 0.
// Inside a sphere a cosine-distributed bounce lands uniformly on the sphere's area, so the radiance leaving x is
// L(x) = E(x) + rho(x) Lbar with Lbar = mean(E) / (1 - mean(rho)) = 0.25 / 0.45, and a pixel's exact value is
// mean_pixel(E) + mean_pixel(rho) Lbar: a closed form with edges (the cap and the albedo halves cut pixels).
//
// Calls per path vertex: get1D for the lobe only where y < 0; get2D for the bounce; get1D for Russian roulette
// only when the throughput is below 1/2. getPixel2D for the film position.
//
// Checks (exit status 1 if one fails), alpha = 0.01 Sidak-corrected over the checks of each family:
//  1. Unbiased: for every pixel, 16 renders (seeds) of 64 samples from a sampler with N = 16 -- so indices 16..63
//     read later blocks -- give 16 estimates; a two-sided t-test of their mean against the closed form.
//  2. Progressive: 32 samples, then 32 more (indices 32..63), every path equal bitwise to 64 at once.
//  3. Stratified per call index: in every pixel, the values that the samples asked at one dimension index with
//     one arity never share a stratum of that index's N-point grid (a stratified set's subset), for every index.
//  4. Stratification helps: stratified's mean squared error over the image beats independent's (F-test).
#include <stipple/stipple.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace {

constexpr int kWidth = 8, kHeight = 7;
constexpr double kPi = 3.14159265358979323846;
constexpr double kPhi0 = 0.3, kDphi = 2 * kPi / kWidth, kDz = 2.0 / kHeight;
constexpr double kLbar = 0.25 / 0.45;

struct Vec {
    double x, y, z;
};
Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec operator*(double s, Vec a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

double emission(Vec p) { return p.z > 0.5 ? 1.0 : 0.0; }

// Cosine-distributed direction about the unit normal n from (u1, u2).
Vec cosineDirection(Vec n, float u1, float u2) {
    const double r = std::sqrt(double(u1)), phi = 2 * kPi * double(u2);
    const double a = r * std::cos(phi), b = r * std::sin(phi), c = std::sqrt(std::max(0.0, 1.0 - u1));
    const Vec t = std::abs(n.x) > 0.9 ? Vec{0, 1, 0} : Vec{1, 0, 0};
    Vec s = t + (-dot(t, n)) * n;
    s = (1.0 / std::sqrt(dot(s, s))) * s;
    const Vec w{n.y * s.z - n.z * s.y, n.z * s.x - n.x * s.z, n.x * s.y - n.y * s.x};
    return (a * s + b * w) + c * n;
}

// What a traced call asked: (sample index, dimension index, arity) -> values.
struct Call {
    uint32_t sample, dimension, arity;
    std::array<float, 3> value;
};

// One path of pixel sample `cursor`. Records the calls it makes when `trace` is given.
double tracePath(stipple::PixelSampleCursor& cursor, int i, int j, std::vector<Call>* trace) {
    auto record = [&](uint32_t arity, std::array<float, 3> v) {
        if (trace) trace->push_back({cursor.sampleIndex(), cursor.dimension() - 1, arity, v});
    };
    const auto film = cursor.getPixel2D();
    const double phi = kPhi0 + (i + film[0]) * kDphi, z = -1 + (j + film[1]) * kDz;
    const double s = std::sqrt(std::max(0.0, 1 - z * z));
    Vec x{s * std::cos(phi), s * std::sin(phi), z}; // first hit: the sphere along the camera ray
    double beta = 1, radiance = 0;
    for (int depth = 0; depth < 64; ++depth) {
        radiance += beta * emission(x);
        if (x.y > 0) {
            beta *= 0.6;
        } else { // two lobes: the lobe choice is a call only here
            const float u = cursor.get1D();
            record(1, {u, 0, 0});
            beta *= u < 0.5f ? 0.8 : 0.2;
        }
        const auto u = cursor.get2D();
        record(2, {u[0], u[1], 0});
        const Vec d = cosineDirection((-1.0) * x, u[0], u[1]);
        x = x + (-2 * dot(x, d)) * d;
        const double len = std::sqrt(dot(x, x));
        x = (1 / len) * x;
        if (beta < 0.5) { // Russian roulette: a call only below the threshold
            const float r = cursor.get1D();
            record(1, {r, 0, 0});
            if (r >= beta) break;
            beta = 1; // beta / q with q = beta
        }
    }
    return radiance;
}

double exactPixel(int i, int j) {
    const double z0 = -1 + j * kDz, z1 = z0 + kDz;
    const double cap = std::max(0.0, z1 - std::max(z0, 0.5)) / kDz;
    // Fraction of [phi0, phi1) with sin(phi) > 0, i.e. phi mod 2 pi in (0, pi).
    const double p0 = kPhi0 + i * kDphi, p1 = p0 + kDphi;
    double upper = 0;
    for (int k = -1; k <= 2; ++k) upper += std::max(0.0, std::min(p1, 2 * kPi * k + kPi) - std::max(p0, 2 * kPi * k));
    const double fraction = upper / kDphi;
    return cap + (fraction * 0.6 + (1 - fraction) * 0.5) * kLbar;
}

// The path radiances of samples [first, first + count) of pixel (i, j).
std::vector<double> renderPixel(const stipple::Sampler& sampler, int i, int j, uint32_t first, uint32_t count,
                                std::vector<Call>* trace = nullptr) {
    stipple::PixelSampleCursor cursor(sampler);
    std::vector<double> radiance;
    for (uint32_t k = first; k < first + count; ++k) {
        cursor.start({i, j}, k);
        radiance.push_back(tracePath(cursor, i, j, trace));
    }
    return radiance;
}

double total(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s;
}

// Two-sided Student t critical value, by bisection on the regularized incomplete beta (via a series): small and
// exact enough for 15 degrees of freedom. P(|T| > t) = I_{nu/(nu+t^2)}(nu/2, 1/2).
double incompleteBeta(double a, double b, double x) {
    // Continued fraction (Numerical Recipes betacf), converges for x < (a+1)/(a+b+2); use symmetry otherwise.
    if (x <= 0) return 0;
    if (x >= 1) return 1;
    const double front =
        std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log(1 - x));
    if (x > (a + 1) / (a + b + 2)) return 1 - incompleteBeta(b, a, 1 - x);
    double c = 1, d = 1 - (a + b) * x / (a + 1);
    d = 1 / d;
    double f = d;
    for (int m = 1; m < 300; ++m) {
        const double m2 = 2 * m;
        double num = m * (b - m) * x / ((a + m2 - 1) * (a + m2));
        d = 1 / (1 + num * d), c = 1 + num / c, f *= d * c;
        num = -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1));
        d = 1 / (1 + num * d), c = 1 + num / c;
        f *= d * c;
    }
    return front * f / a;
}
double twoSidedP(double t, double nu) { return incompleteBeta(nu / 2, 0.5, nu / (nu + t * t)); }

} // namespace

int main() {
    int failures = 0;
    const int pixels = kWidth * kHeight;

    // 1. Unbiased with indices past N.
    const int renders = 16;
    const uint32_t spp = 64;
    const double alpha = 1 - std::pow(1 - 0.01, 1.0 / pixels);
    double worstP = 1;
    std::map<std::string, double> mse;
    for (const char* pattern : {"independent", "stratified", "poisson"}) {
        double squared = 0;
        for (int j = 0; j < kHeight; ++j)
            for (int i = 0; i < kWidth; ++i) {
                double sum = 0, sum2 = 0;
                for (int r = 0; r < renders; ++r) {
                    const stipple::Sampler sampler(pattern, 16, 1000 + r);
                    const double estimate = total(renderPixel(sampler, i, j, 0, spp)) / spp;
                    sum += estimate, sum2 += estimate * estimate;
                    squared += (estimate - exactPixel(i, j)) * (estimate - exactPixel(i, j));
                }
                const double mean = sum / renders, sd = std::sqrt(std::max(0.0, (sum2 - sum * mean) / (renders - 1)));
                const double t = (mean - exactPixel(i, j)) / (sd / std::sqrt(double(renders)));
                const double p = twoSidedP(std::abs(t), renders - 1);
                worstP = std::min(worstP, p);
                if (p < alpha) {
                    std::printf("FAIL unbiased: %s pixel (%d, %d): mean %.5f exact %.5f t = %.2f p = %.2g\n", pattern,
                                i, j, mean, exactPixel(i, j), t, p);
                    ++failures;
                }
            }
        mse[pattern] = squared / (pixels * renders);
        std::printf("%-12s 64 spp (N = 16, four blocks): image MSE %.3e\n", pattern, mse[pattern]);
    }
    std::printf("unbiased: smallest per-pixel p = %.3g (alpha %.2g per pixel)\n", worstP, alpha);

    // 2. Progressive: 32 + 32 equals 64.
    {
        const stipple::Sampler sampler("stratified", 64, 7);
        for (int j = 0; j < kHeight; ++j)
            for (int i = 0; i < kWidth; ++i) {
                const std::vector<double> once = renderPixel(sampler, i, j, 0, 64);
                std::vector<double> twice = renderPixel(sampler, i, j, 0, 32);
                const std::vector<double> more = renderPixel(sampler, i, j, 32, 32);
                twice.insert(twice.end(), more.begin(), more.end());
                if (once != twice) {
                    std::printf("FAIL progressive: pixel (%d, %d): 32 + 32 samples differ from 64\n", i, j);
                    ++failures;
                }
            }
    }

    // 3. Stratified per call index: 64 samples, N = 64 (1D: 64 strata; 2D: 8 x 8).
    {
        const stipple::Sampler sampler("stratified", 64, 11);
        size_t checkedIndices = 0;
        for (int j = 0; j < kHeight; ++j)
            for (int i = 0; i < kWidth; ++i) {
                std::vector<Call> trace;
                renderPixel(sampler, i, j, 0, 64, &trace);
                std::map<std::pair<uint32_t, uint32_t>, std::set<uint32_t>> strata; // (index, arity) -> cells
                for (const Call& c : trace) {
                    const uint32_t cell = c.arity == 1 ? uint32_t(c.value[0] * 64)
                                                       : uint32_t(c.value[0] * 8) * 8 + uint32_t(c.value[1] * 8);
                    if (!strata[{c.dimension, c.arity}].insert(cell).second) {
                        std::printf("FAIL stratified: pixel (%d, %d) index %u arity %u: stratum %u twice\n", i, j,
                                    c.dimension, c.arity, cell);
                        ++failures;
                    }
                }
                checkedIndices += strata.size();
                if (strata[{0, 2}].size() + strata[{0, 1}].size() != 64) {
                    std::printf("FAIL: index 0 was not asked by every sample\n");
                    ++failures;
                }
            }
        std::printf("stratified per call index: %zu (pixel, index, arity) groups, no stratum hit twice\n",
                    checkedIndices);
    }

    // 4. Stratified beats independent: F = MSE_independent / MSE_stratified over 896 estimates each; ln F is about
    // Normal(0, 4 / 896) under equal MSE; one-sided alpha 0.01 (z = 2.326).
    const double lnF = std::log(mse["independent"] / mse["stratified"]);
    std::printf("MSE ratio independent / stratified = %.2f (critical %.2f)\n", std::exp(lnF),
                std::exp(2.326 * std::sqrt(4.0 / (pixels * renders))));
    if (lnF < 2.326 * std::sqrt(4.0 / (pixels * renders))) {
        std::printf("FAIL: stratified does not beat independent\n");
        ++failures;
    }
    std::printf(failures ? "tiny_path_tracer: %d failures\n" : "tiny_path_tracer: all checks passed\n", failures);
    return failures ? 1 : 0;
}
