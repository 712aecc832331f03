// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// battery_integrands.h — the standard integrand battery on [0,1)^d, d = 1, 2, 3, with exact integrals.
//
// Genz (1984) families with randomised parameters: oscillatory, product peak, corner peak, Gaussian, continuous
// (a kink), discontinuous. Their coefficients a are uniform, rescaled so that sum(a) is Genz's difficulty
// (9.0, 7.25, 1.85, 7.03, 20.4, 4.3), and the centres u uniform; each family has kGenzInstances instances drawn
// from a fixed seed and replicate r of a measurement uses instance r mod kGenzInstances, so an MSE is an average
// over instances. The integrands of the PMJ paper (Christensen et al. 2018) in 2D: a quarter disk, a triangle,
// an axis-aligned step, exp(-x^2 - y^2), the bilinear x y. Smooth, non-periodic ones: ramps, exponentials, an
// off-centre Gaussian. A slanted step, a ball. The irradiance from a quad light seen from a point (smooth and
// non-periodic), the same light half hidden by a straight occluder (an edge), and a zone plate.
//
// Every integrand has a class (the rate theory predicts depends on it): smooth, kink (continuous, not
// differentiable) or edge (discontinuous); the zone plate is a class of its own (smooth but resolved only at
// large N). Exact integrals are closed forms, or Gauss-Legendre quadrature of a smooth function on the exact
// domain of continuity (light, occluded light, zone plate) — accurate to ~1e-13, far below the errors measured.
// The variance of each integrand (for normalising: an independent set of N points has normalised MSE 1/N) is
// estimated once by quadrature.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace stipple::battery {

enum class IntegrandClass { Smooth, Kink, Edge, ZonePlate };

inline const char* className(IntegrandClass c) {
    switch (c) {
    case IntegrandClass::Smooth: return "smooth";
    case IntegrandClass::Kink: return "kink";
    case IntegrandClass::Edge: return "edge";
    default: return "zone plate";
    }
}

constexpr int kGenzInstances = 8;

struct Integrand {
    std::string name;
    int dim = 2;
    IntegrandClass cls = IntegrandClass::Smooth;
    int instances = 1; // replicate r uses instance r % instances
    std::function<double(int instance, const float* p)> f;
    std::vector<double> exact;    // per instance
    std::vector<double> variance; // per instance: Var f(U), U uniform
    double operator()(int instance, const float* p) const { return f(instance, p); }
};

namespace detail {

constexpr double kPi = 3.14159265358979323846;

// SplitMix64: a fixed stream of parameters.
struct ParameterRng {
    uint64_t state;
    double next() {
        uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return double((z ^ (z >> 31)) >> 11) * 0x1p-53;
    }
};

// 16-point Gauss-Legendre nodes and weights on [0, 1].
inline const std::array<std::pair<double, double>, 16>& gaussLegendre16() {
    static const std::array<std::pair<double, double>, 16> rule = [] {
        std::array<std::pair<double, double>, 16> r{};
        const int n = 16;
        for (int i = 0; i < n; ++i) { // Newton on P_n from the Chebyshev guess
            double x = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 0;
            for (int it = 0; it < 100; ++it) {
                double p0 = 1, p1 = x;
                for (int k = 2; k <= n; ++k) {
                    const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
                    p0 = p1, p1 = p2;
                }
                dp = n * (x * p1 - p0) / (x * x - 1);
                const double dx = p1 / dp;
                x -= dx;
                if (std::abs(dx) < 1e-16) break;
            }
            r[i] = {0.5 * (1 - x), 1.0 / ((1 - x * x) * dp * dp)};
        }
        return r;
    }();
    return rule;
}

// Composite Gauss-Legendre on [a, b] with `panels` panels.
template <class F> double integrate1(F&& f, double a, double b, int panels) {
    const auto& rule = gaussLegendre16();
    const double h = (b - a) / panels;
    double sum = 0;
    for (int k = 0; k < panels; ++k)
        for (const auto& [x, w] : rule) sum += w * f(a + (k + x) * h);
    return sum * h;
}

// Mean of g(f(p)) over [0,1]^dim by a product rule (float points, as the sampler gives them).
inline double cubature(const std::function<double(const float*)>& g, int dim, int panels) {
    const auto& rule = gaussLegendre16();
    const int n = 16 * panels;
    std::vector<double> x(n), w(n);
    for (int k = 0; k < panels; ++k)
        for (int j = 0; j < 16; ++j) x[k * 16 + j] = (k + rule[j].first) / panels, w[k * 16 + j] = rule[j].second / panels;
    double sum = 0;
    float p[3];
    if (dim == 1)
        for (int i = 0; i < n; ++i) p[0] = float(x[i]), sum += w[i] * g(p);
    else if (dim == 2)
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) p[0] = float(x[i]), p[1] = float(x[j]), sum += w[i] * w[j] * g(p);
    else
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                for (int k = 0; k < n; ++k)
                    p[0] = float(x[i]), p[1] = float(x[j]), p[2] = float(x[k]), sum += w[i] * w[j] * w[k] * g(p);
    return sum;
}

struct GenzParameters {
    double a[3], u[3];
};

inline std::vector<GenzParameters> genzParameters(int family, int dim) {
    static constexpr double kDifficulty[6] = {9.0, 7.25, 1.85, 7.03, 20.4, 4.3};
    ParameterRng rng{0x6e6e7a5eedull + 1000 * uint64_t(family) + uint64_t(dim)};
    std::vector<GenzParameters> out(kGenzInstances);
    for (auto& g : out) {
        double sum = 0;
        for (int c = 0; c < dim; ++c) g.a[c] = 0.1 + rng.next(), sum += g.a[c];
        for (int c = 0; c < dim; ++c) g.a[c] *= kDifficulty[family] / sum, g.u[c] = rng.next();
    }
    return out;
}

inline Integrand genz(int family, int dim) {
    static const char* kNames[6] = {"genz-oscillatory", "genz-product-peak", "genz-corner-peak",
                                    "genz-gaussian",    "genz-continuous",   "genz-discontinuous"};
    static constexpr IntegrandClass kClass[6] = {IntegrandClass::Smooth, IntegrandClass::Smooth,
                                                 IntegrandClass::Smooth, IntegrandClass::Smooth,
                                                 IntegrandClass::Kink,   IntegrandClass::Edge};
    const std::vector<GenzParameters> params = genzParameters(family, dim);
    Integrand in;
    in.name = kNames[family];
    in.dim = dim;
    in.cls = kClass[family];
    in.instances = kGenzInstances;
    in.f = [params, family, dim](int instance, const float* p) {
        const GenzParameters& g = params[instance];
        double s = 0;
        switch (family) {
        case 0:
            for (int c = 0; c < dim; ++c) s += g.a[c] * p[c];
            return std::cos(2 * kPi * g.u[0] + s);
        case 1: {
            double prod = 1;
            for (int c = 0; c < dim; ++c) prod *= 1.0 / (1.0 / (g.a[c] * g.a[c]) + (p[c] - g.u[c]) * (p[c] - g.u[c]));
            return prod;
        }
        case 2:
            for (int c = 0; c < dim; ++c) s += g.a[c] * p[c];
            return std::pow(1 + s, -(dim + 1));
        case 3:
            for (int c = 0; c < dim; ++c) s += g.a[c] * g.a[c] * (p[c] - g.u[c]) * (p[c] - g.u[c]);
            return std::exp(-s);
        case 4:
            for (int c = 0; c < dim; ++c) s += g.a[c] * std::abs(p[c] - g.u[c]);
            return std::exp(-s);
        default:
            if (p[0] > g.u[0] || (dim > 1 && p[1] > g.u[1])) return 0.0;
            for (int c = 0; c < dim; ++c) s += g.a[c] * p[c];
            return std::exp(s);
        }
    };
    for (const GenzParameters& g : params) {
        double value = 1;
        switch (family) {
        case 0: { // Re(e^{i 2 pi u} prod (e^{i a} - 1) / (i a))
            double re = std::cos(2 * kPi * g.u[0]), im = std::sin(2 * kPi * g.u[0]);
            for (int c = 0; c < dim; ++c) {
                const double fr = std::sin(g.a[c]) / g.a[c], fi = (1 - std::cos(g.a[c])) / g.a[c];
                const double r2 = re * fr - im * fi, i2 = re * fi + im * fr;
                re = r2, im = i2;
            }
            value = re;
            break;
        }
        case 1:
            for (int c = 0; c < dim; ++c)
                value *= g.a[c] * (std::atan(g.a[c] * (1 - g.u[c])) + std::atan(g.a[c] * g.u[c]));
            break;
        case 2: { // (1 / (d! prod a)) sum over subsets S of (-1)^|S| / (1 + sum_S a)
            double sum = 0, prodA = 1, factorial = 1;
            for (int c = 0; c < dim; ++c) prodA *= g.a[c], factorial *= c + 1;
            for (int mask = 0; mask < (1 << dim); ++mask) {
                double s = 1;
                int bits = 0;
                for (int c = 0; c < dim; ++c)
                    if (mask >> c & 1) s += g.a[c], ++bits;
                sum += (bits % 2 ? -1.0 : 1.0) / s;
            }
            value = sum / (factorial * prodA);
            break;
        }
        case 3:
            for (int c = 0; c < dim; ++c)
                value *= std::sqrt(kPi) / (2 * g.a[c]) * (std::erf(g.a[c] * (1 - g.u[c])) + std::erf(g.a[c] * g.u[c]));
            break;
        case 4:
            for (int c = 0; c < dim; ++c)
                value *= (2 - std::exp(-g.a[c] * g.u[c]) - std::exp(-g.a[c] * (1 - g.u[c]))) / g.a[c];
            break;
        default:
            for (int c = 0; c < dim; ++c) {
                const double b = c < 2 ? g.u[c] : 1.0;
                value *= std::expm1(g.a[c] * b) / g.a[c];
            }
        }
        in.exact.push_back(value);
    }
    return in;
}

inline Integrand simple(std::string name, int dim, IntegrandClass cls, std::function<double(const float*)> f,
                        double exact) {
    Integrand in;
    in.name = std::move(name);
    in.dim = dim;
    in.cls = cls;
    in.f = [f = std::move(f)](int, const float* p) { return f(p); };
    in.exact = {exact};
    return in;
}

// Irradiance-like integrand of a unit quad light [0,1]^2 at height h above the plane z = 0, sampled by area from
// a shading point s with normal n: f(u, v) = cos(theta_s) cos(theta_l) / r^2 (times the light's area 1).
struct QuadLight {
    double s[3] = {-0.35, 0.2, 0.0}; // shading point
    double n[3] = {0.6, 0.0, 0.8};   // its normal (unit)
    double h = 0.6;                  // the light's plane z = h, facing down
    double operator()(double u, double v) const {
        const double d[3] = {u - s[0], v - s[1], h - s[2]};
        const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        const double r = std::sqrt(r2);
        const double cosS = (d[0] * n[0] + d[1] * n[1] + d[2] * n[2]) / r;
        const double cosL = d[2] / r;
        return cosS > 0 ? cosS * cosL / r2 : 0.0;
    }
};

} // namespace detail

// The whole battery for one dimension (1, 2 or 3), with exact integrals and variances.
inline std::vector<Integrand> makeBattery(int dim) {
    using namespace detail;
    using C = IntegrandClass;
    std::vector<Integrand> out;
    for (int family = 0; family < 6; ++family) out.push_back(genz(family, dim));
    const double sigma = 0.2;
    const double centre[3] = {0.3, 0.6, 0.4};
    auto offGaussian = [sigma, centre, dim](const float* p) {
        double r2 = 0;
        for (int c = 0; c < dim; ++c) r2 += (p[c] - centre[c]) * (p[c] - centre[c]);
        return std::exp(-r2 / (2 * sigma * sigma));
    };
    double offExact = 1;
    for (int c = 0; c < dim; ++c)
        offExact *= sigma * std::sqrt(kPi / 2) *
                    (std::erf((1 - centre[c]) / (sigma * std::sqrt(2.0))) + std::erf(centre[c] / (sigma * std::sqrt(2.0))));
    const double erf1 = std::sqrt(kPi) / 2 * std::erf(1.0); // integral of exp(-x^2) over [0, 1]
    if (dim == 1) {
        out.push_back(simple("ramp x", 1, C::Smooth, [](const float* p) { return double(p[0]); }, 0.5));
        out.push_back(simple("exp(-x)", 1, C::Smooth, [](const float* p) { return std::exp(-double(p[0])); },
                             1 - std::exp(-1.0)));
        out.push_back(simple("off-centre gaussian", 1, C::Smooth, offGaussian, offExact));
        out.push_back(simple("step x<0.3", 1, C::Edge, [](const float* p) { return p[0] < 0.3f ? 1.0 : 0.0; },
                             double(0.3f)));
    } else if (dim == 2) {
        // The PMJ paper's five.
        out.push_back(simple("pmj disk", 2, C::Edge,
                             [](const float* p) { return double(p[0]) * p[0] + double(p[1]) * p[1] < 2 / kPi ? 1.0 : 0.0; },
                             0.5));
        out.push_back(simple("pmj triangle", 2, C::Edge, [](const float* p) { return p[1] < p[0] ? 1.0 : 0.0; }, 0.5));
        out.push_back(simple("pmj step", 2, C::Edge, [](const float* p) { return p[0] < 1.0 / 3 ? 1.0 : 0.0; },
                             1.0 / 3));
        out.push_back(simple("pmj gaussian exp(-x2-y2)", 2, C::Smooth,
                             [](const float* p) { return std::exp(-double(p[0]) * p[0] - double(p[1]) * p[1]); },
                             erf1 * erf1));
        out.push_back(simple("pmj bilinear xy", 2, C::Smooth, [](const float* p) { return double(p[0]) * p[1]; }, 0.25));
        out.push_back(simple("ramp x+y", 2, C::Smooth, [](const float* p) { return double(p[0]) + p[1]; }, 1.0));
        out.push_back(simple("off-centre gaussian", 2, C::Smooth, offGaussian, offExact));
        out.push_back(simple("slanted step", 2, C::Edge, [](const float* p) { return p[0] < 0.3 + 0.4 * p[1] ? 1.0 : 0.0; },
                             0.5));
        const QuadLight light;
        const double lightExact =
            integrate1([&](double v) { return integrate1([&](double u) { return light(u, v); }, 0, 1, 8); }, 0, 1, 8);
        out.push_back(simple("quad light", 2, C::Smooth, [light](const float* p) { return light(p[0], p[1]); },
                             lightExact));
        // A straight occluder edge projects onto the light as the line u < 0.25 + 0.5 v (visible part).
        const double occludedExact = integrate1(
            [&](double v) { return integrate1([&](double u) { return light(u, v); }, 0, 0.25 + 0.5 * v, 8); }, 0, 1, 8);
        out.push_back(simple("quad light occluded", 2, C::Edge,
                             [light](const float* p) { return p[0] < 0.25 + 0.5 * p[1] ? light(p[0], p[1]) : 0.0; },
                             occludedExact));
        // Zone plate 0.5 + 0.5 cos(k r^2) about the corner: rings up to ~10 cycles over the square.
        const double k = 60.0;
        const double ring = integrate1([&](double x) { return std::cos(k * x * x); }, 0, 1, 32),
                     ringS = integrate1([&](double x) { return std::sin(k * x * x); }, 0, 1, 32);
        out.push_back(simple("zone plate", 2, C::ZonePlate,
                             [k](const float* p) {
                                 return 0.5 + 0.5 * std::cos(k * (double(p[0]) * p[0] + double(p[1]) * p[1]));
                             },
                             0.5 + 0.5 * (ring * ring - ringS * ringS)));
    } else {
        out.push_back(simple("ramp x+y+z", 3, C::Smooth, [](const float* p) { return double(p[0]) + p[1] + p[2]; }, 1.5));
        out.push_back(simple("exp(-|p|2)", 3, C::Smooth,
                             [](const float* p) {
                                 return std::exp(-double(p[0]) * p[0] - double(p[1]) * p[1] - double(p[2]) * p[2]);
                             },
                             erf1 * erf1 * erf1));
        out.push_back(simple("off-centre gaussian", 3, C::Smooth, offGaussian, offExact));
        out.push_back(simple("ball", 3, C::Edge,
                             [](const float* p) {
                                 double r2 = 0;
                                 for (int c = 0; c < 3; ++c) r2 += (p[c] - 0.5) * (p[c] - 0.5);
                                 return r2 < 0.16 ? 1.0 : 0.0;
                             },
                             4.0 / 3.0 * kPi * 0.064));
        // Slanted plane x + y + z < 1.2: the volume of the corner simplex minus what sticks out past a face.
        out.push_back(simple("slanted plane", 3, C::Edge,
                             [](const float* p) { return double(p[0]) + p[1] + p[2] < 1.2 ? 1.0 : 0.0; },
                             (1.2 * 1.2 * 1.2 - 3 * 0.2 * 0.2 * 0.2) / 6));
    }
    // Variances by quadrature (normalisation only; a percent is plenty).
    const int panels = dim == 1 ? 256 : dim == 2 ? 24 : 4;
    for (Integrand& in : out) {
        for (int i = 0; i < in.instances; ++i) {
            const double second = cubature([&](const float* p) { double v = in.f(i, p); return v * v; }, dim, panels);
            in.variance.push_back(std::max(second - in.exact[i] * in.exact[i], 1e-300));
        }
    }
    return out;
}

} // namespace stipple::battery
