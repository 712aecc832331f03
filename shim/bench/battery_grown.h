// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// battery_grown.h — the 2D integrands that vary at the sample spacing, where a sampler's order shows: the classes
// that found the blue-noise flag's checkerboard losses and the crystal peaks of poisson's former sets.
//
// For N samples per pixel (strata of side 1 / sqrt(N)):
// - checkerboards of 7 x 7 to 24 x 24 squares;
// - gratings cos(2 pi k.x) at every integer k with |k| <= 2 sqrt(N) (one of k and -k);
// - thin stripes: |n.x - c| < w / 2 with w a quarter of a stratum, axis-aligned, near-axis and slanted;
// - axis and near-axis steps: x < a + t (y - 1/2), t = tan of 0, 1, 3 and 6 degrees, off every stratum face;
// - edges: half-planes (x - 1/2, y - 1/2).n < 0.07 at 16 orientations;
// - opposite bumps: two Gaussians of width a quarter stratum and opposite sign either side of a stratum face.
// Exact integrals are closed forms (half-plane areas of the unit square, erf); variances are exact for indicator
// functions and gratings, by quadrature for the bumps.
#pragma once

#include "battery_integrands.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace stipple::battery {

struct GrownIntegrand {
    std::string family; // "checkerboard", "grating", "thin stripe", "step", "edge", "opposite bumps"
    Integrand integrand;
    int k[2] = {0, 0}; // gratings: the wave vector (a bench may evaluate all gratings at once)
};

namespace detail {

// Area of {p in [0,1]^2 : p.n < c}: the unit square clipped by the half-plane (Sutherland-Hodgman), shoelace.
inline double halfPlaneArea(double nx, double ny, double c) {
    const double square[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    double clipped[8][2];
    int count = 0;
    for (int i = 0; i < 4; ++i) {
        const double* a = square[i];
        const double* b = square[(i + 1) % 4];
        const double da = a[0] * nx + a[1] * ny - c, db = b[0] * nx + b[1] * ny - c;
        if (da < 0) {
            clipped[count][0] = a[0];
            clipped[count++][1] = a[1];
        }
        if ((da < 0) != (db < 0)) {
            const double t = da / (da - db);
            clipped[count][0] = a[0] + t * (b[0] - a[0]);
            clipped[count++][1] = a[1] + t * (b[1] - a[1]);
        }
    }
    double area = 0;
    for (int i = 0; i < count; ++i) {
        const int j = (i + 1) % count;
        area += clipped[i][0] * clipped[j][1] - clipped[j][0] * clipped[i][1];
    }
    return 0.5 * std::abs(area);
}

// An indicator with exact integral m: variance m (1 - m).
inline Integrand indicator(std::string name, std::function<double(const float*)> f, double m) {
    Integrand in = simple(std::move(name), 2, IntegrandClass::Edge, std::move(f), m);
    in.variance = {m * (1 - m)};
    return in;
}

// Integral over [0, 1] of exp(-(x - c)^2 / (2 s^2)).
inline double gaussianIntegral(double c, double s) {
    return s * std::sqrt(kPi / 2) * (std::erf((1 - c) / (s * std::sqrt(2.0))) + std::erf(c / (s * std::sqrt(2.0))));
}

} // namespace detail

inline std::vector<GrownIntegrand> makeGrownBattery(uint32_t n) {
    using namespace detail;
    std::vector<GrownIntegrand> out;
    const double side = 1 / std::sqrt(double(n)); // a stratum's side
    const int strataPerAxis = std::max(1, int(std::lround(std::sqrt(double(n)))));
    char name[96];
    for (int s = 7; s <= 24; ++s) {
        std::snprintf(name, sizeof name, "checkerboard %d x %d", s, s);
        const double m = double((s * s) / 2) / (s * s);
        out.push_back({"checkerboard", indicator(name, [s](const float* p) {
                           return (int(std::floor(double(p[0]) * s)) + int(std::floor(double(p[1]) * s))) % 2 == 1 ? 1.0 : 0.0;
                       }, m)});
    }
    const int radius = int(std::floor(2 * std::sqrt(double(n))));
    for (int kx = 0; kx <= radius; ++kx)
        for (int ky = -radius; ky <= radius; ++ky) {
            if ((kx == 0 && ky <= 0) || kx * kx + ky * ky > 4 * int(n)) continue;
            std::snprintf(name, sizeof name, "grating (%d, %d)", kx, ky);
            GrownIntegrand g{"grating", simple(name, 2, IntegrandClass::Smooth, [kx, ky](const float* p) {
                                 return std::cos(2 * kPi * (kx * double(p[0]) + ky * double(p[1])));
                             }, 0.0), {kx, ky}};
            g.integrand.variance = {0.5};
            out.push_back(std::move(g));
        }
    // Thin stripes a quarter of a stratum wide, centred off the stratum faces.
    const double width = 0.25 * side;
    for (double degrees : {0.0, 2.0, 30.0, 45.0, 88.0}) {
        const double t = degrees * kPi / 180, nx = std::cos(t), ny = std::sin(t);
        const double c = 0.5 * (nx + ny) + 0.37 * side;
        std::snprintf(name, sizeof name, "thin stripe at %g degrees", degrees);
        const double m = halfPlaneArea(nx, ny, c + width / 2) - halfPlaneArea(nx, ny, c - width / 2);
        out.push_back({"thin stripe", indicator(name, [nx, ny, c, width](const float* p) {
                           return std::abs(nx * p[0] + ny * p[1] - c) < width / 2 ? 1.0 : 0.0;
                       }, m)});
    }
    // Axis and near-axis steps x < a + tan(t) (y - 1/2) (and the same in y), a off the stratum faces.
    for (int axis = 0; axis < 2; ++axis)
        for (double degrees : {0.0, 1.0, 3.0, 6.0}) {
            const double slope = std::tan(degrees * kPi / 180);
            const double a = (std::floor(0.5 * strataPerAxis) + 0.37) * side;
            std::snprintf(name, sizeof name, "step %s, %g degrees off axis", axis == 0 ? "x" : "y", degrees);
            // x - slope y < a - slope / 2.
            const double m = axis == 0 ? halfPlaneArea(1, -slope, a - slope / 2) : halfPlaneArea(-slope, 1, a - slope / 2);
            out.push_back({"step", indicator(name, [axis, slope, a](const float* p) {
                               const double u = p[axis], v = p[1 - axis];
                               return u < a + slope * (v - 0.5) ? 1.0 : 0.0;
                           }, m)});
        }
    for (int j = 0; j < 16; ++j) {
        const double t = j * kPi / 16 + 0.05, nx = std::cos(t), ny = std::sin(t);
        const double c = 0.07 + 0.5 * (nx + ny);
        std::snprintf(name, sizeof name, "edge at %.1f degrees", t * 180 / kPi);
        out.push_back({"edge", indicator(name, [nx, ny, c](const float* p) { return nx * p[0] + ny * p[1] < c ? 1.0 : 0.0; },
                                         halfPlaneArea(nx, ny, c))});
    }
    // Opposite bumps either side of the stratum face nearest x = 1/2, in the middle of a stratum's row.
    {
        const double face = std::floor(0.5 * strataPerAxis) * side, d = 0.25 * side, sigma = 0.25 * side;
        const double y0 = (std::floor(0.5 * strataPerAxis) + 0.5) * side;
        const double exact = (gaussianIntegral(face - d, sigma) - gaussianIntegral(face + d, sigma)) *
                             gaussianIntegral(y0, sigma);
        Integrand in = simple("opposite bumps across a stratum face", 2, IntegrandClass::Smooth,
                              [face, d, sigma, y0](const float* p) {
                                  const double dy = p[1] - y0, a = p[0] - (face - d), b = p[0] - (face + d);
                                  const double s2 = 2 * sigma * sigma;
                                  return std::exp(-(dy * dy) / s2) * (std::exp(-a * a / s2) - std::exp(-b * b / s2));
                              },
                              exact);
        const double second =
            cubature([&](const float* p) { const double v = in.f(0, p); return v * v; }, 2, 96);
        in.variance = {std::max(second - exact * exact, 1e-300)};
        out.push_back({"opposite bumps", std::move(in)});
    }
    return out;
}

} // namespace stipple::battery
