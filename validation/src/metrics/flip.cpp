// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "metrics/flip.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace stipple::validation {

namespace {

constexpr double kPi = 3.14159265358979323846;
using Vec3 = std::array<double, 3>;

// One channel of an image, row-major.
struct Plane {
    int w = 0, h = 0;
    std::vector<double> v;
    double at(int x, int y) const { return v[size_t(y) * w + x]; }
};

struct Kernel {
    int radius = 0;
    std::vector<double> k; // (2r+1)², row-major, k[(dy + r)(2r+1) + dx + r]
};

// 2D correlation with the border replicated (edge pixels extend outwards).
Plane filter(const Plane& in, const Kernel& k, bool transpose = false) {
    Plane out{in.w, in.h, std::vector<double>(in.v.size())};
    const int r = k.radius, n = 2 * r + 1;
    for (int y = 0; y < in.h; ++y)
        for (int x = 0; x < in.w; ++x) {
            double sum = 0;
            for (int dy = -r; dy <= r; ++dy) {
                const int yy = std::clamp(y + dy, 0, in.h - 1);
                for (int dx = -r; dx <= r; ++dx) {
                    const double w =
                        transpose ? k.k[size_t(dx + r) * n + (dy + r)] : k.k[size_t(dy + r) * n + (dx + r)];
                    sum += w * in.at(std::clamp(x + dx, 0, in.w - 1), yy);
                }
            }
            out.v[size_t(y) * in.w + x] = sum;
        }
    return out;
}

// Contrast sensitivity of one opponent channel as a spatial filter: a1 √(π/b1) exp(−π² r² / b1) + (same for
// a2, b2), r in degrees, normalised to sum 1. All three channels share the radius of the widest (b = 0.04).
Kernel csfKernel(double ppd, double a1, double b1, double a2, double b2) {
    Kernel k;
    k.radius = int(std::ceil(3 * std::sqrt(0.04 / (2 * kPi * kPi)) * ppd));
    const int n = 2 * k.radius + 1;
    k.k.resize(size_t(n) * n);
    double sum = 0;
    for (int y = -k.radius; y <= k.radius; ++y)
        for (int x = -k.radius; x <= k.radius; ++x) {
            const double z = (double(x) * x + double(y) * y) / (ppd * ppd);
            const double s = a1 * std::sqrt(kPi / b1) * std::exp(-kPi * kPi * z / b1) +
                             a2 * std::sqrt(kPi / b2) * std::exp(-kPi * kPi * z / b2);
            k.k[size_t(y + k.radius) * n + (x + k.radius)] = s;
            sum += s;
        }
    for (double& v : k.k) v /= sum;
    return k;
}

// Gaussian derivative along x (edge: first, point: second), positive weights scaled to sum 1, negative to −1.
Kernel featureKernel(double ppd, bool point) {
    const double sd = 0.5 * 0.082 * ppd;
    Kernel k;
    k.radius = int(std::ceil(3 * sd));
    const int n = 2 * k.radius + 1;
    k.k.resize(size_t(n) * n);
    double pos = 0, neg = 0;
    for (int y = -k.radius; y <= k.radius; ++y)
        for (int x = -k.radius; x <= k.radius; ++x) {
            const double g = std::exp(-(double(x) * x + double(y) * y) / (2 * sd * sd));
            const double v = point ? (double(x) * x / (sd * sd) - 1) * g : -double(x) * g;
            k.k[size_t(y + k.radius) * n + (x + k.radius)] = v;
            (v > 0 ? pos : neg) += v;
        }
    for (double& v : k.k) v = v > 0 ? v / pos : v < 0 ? v / -neg : 0;
    return k;
}

double srgbToLinear(double c) { return c > 0.04045 ? std::pow((c + 0.055) / 1.055, 2.4) : c / 12.92; }
double linearToSrgb(double c) { return c > 0.0031308 ? 1.055 * std::pow(c, 1 / 2.4) - 0.055 : 12.92 * c; }

// Linear Rec.709 / sRGB primaries, D65 white.
Vec3 rgbToXyz(const Vec3& c) {
    return {0.4124564 * c[0] + 0.3575761 * c[1] + 0.1804375 * c[2],
            0.2126729 * c[0] + 0.7151522 * c[1] + 0.0721750 * c[2],
            0.0193339 * c[0] + 0.1191920 * c[1] + 0.9503041 * c[2]};
}
Vec3 xyzToRgb(const Vec3& c) {
    return {3.2404542 * c[0] - 1.5371385 * c[1] - 0.4985314 * c[2],
            -0.9692660 * c[0] + 1.8760108 * c[1] + 0.0415560 * c[2],
            0.0556434 * c[0] - 0.2040259 * c[1] + 1.0572252 * c[2]};
}
const Vec3 kWhite = rgbToXyz({1, 1, 1});

Vec3 xyzToYcxcz(const Vec3& c) {
    const double x = c[0] / kWhite[0], y = c[1] / kWhite[1], z = c[2] / kWhite[2];
    return {116 * y - 16, 500 * (x - y), 200 * (y - z)};
}
Vec3 ycxczToXyz(const Vec3& c) {
    const double y = (c[0] + 16) / 116;
    return {(y + c[1] / 500) * kWhite[0], y * kWhite[1], (y - c[2] / 200) * kWhite[2]};
}
Vec3 xyzToLab(const Vec3& c) {
    auto f = [](double t) {
        constexpr double d = 6.0 / 29;
        return t > d * d * d ? std::cbrt(t) : t / (3 * d * d) + 4.0 / 29;
    };
    const double fx = f(c[0] / kWhite[0]), fy = f(c[1] / kWhite[1]), fz = f(c[2] / kWhite[2]);
    return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}
Vec3 huntLab(const Vec3& rgb) {
    Vec3 lab = xyzToLab(rgbToXyz(rgb));
    return {lab[0], 0.01 * lab[0] * lab[1], 0.01 * lab[0] * lab[2]};
}
double hyab(const Vec3& a, const Vec3& b) { return std::fabs(a[0] - b[0]) + std::hypot(a[1] - b[1], a[2] - b[2]); }

struct Opponent {
    Plane y, cx, cz;
};
Opponent toOpponent(const Image& srgb) {
    Opponent o;
    for (Plane* p : {&o.y, &o.cx, &o.cz})
        *p = {srgb.width, srgb.height, std::vector<double>(size_t(srgb.width) * srgb.height)};
    for (size_t i = 0; i < o.y.v.size(); ++i) {
        Vec3 c;
        for (int ch = 0; ch < 3; ++ch) c[ch] = srgbToLinear(std::clamp(double(srgb.rgb[3 * i + ch]), 0.0, 1.0));
        const Vec3 v = xyzToYcxcz(rgbToXyz(c));
        o.y.v[i] = v[0], o.cx.v[i] = v[1], o.cz.v[i] = v[2];
    }
    return o;
}

// The colour pipeline's per-pixel Hunt-adjusted Lab after the CSF filters.
std::vector<Vec3> filteredHuntLab(const Opponent& o, const Kernel& a, const Kernel& rg, const Kernel& by) {
    const Plane fy = filter(o.y, a), fcx = filter(o.cx, rg), fcz = filter(o.cz, by);
    std::vector<Vec3> out(fy.v.size());
    for (size_t i = 0; i < out.size(); ++i) {
        Vec3 rgb = xyzToRgb(ycxczToXyz({fy.v[i], fcx.v[i], fcz.v[i]}));
        for (double& c : rgb) c = std::clamp(c, 0.0, 1.0);
        out[i] = huntLab(rgb);
    }
    return out;
}

// ‖(∂x, ∂y)‖ of the achromatic channel for the edge or point kernel.
std::vector<double> featureMagnitude(const Plane& achromatic, const Kernel& k) {
    const Plane fx = filter(achromatic, k), fy = filter(achromatic, k, true);
    std::vector<double> m(fx.v.size());
    for (size_t i = 0; i < m.size(); ++i) m[i] = std::hypot(fx.v[i], fy.v[i]);
    return m;
}

} // namespace

double FlipMaps::mean() const {
    double s = 0;
    for (float v : flip) s += v;
    return flip.empty() ? 0 : s / double(flip.size());
}

FlipMaps ldrFlipSrgb(const Image& ref, const Image& test, double ppd) {
    if (ref.width != test.width || ref.height != test.height)
        throw std::invalid_argument("FLIP: images differ in size: reference " + std::to_string(ref.width) + "x" +
                                    std::to_string(ref.height) + ", test " + std::to_string(test.width) + "x" +
                                    std::to_string(test.height));
    if (!(ppd > 0)) throw std::invalid_argument("FLIP: pixels per degree must be > 0");
    constexpr double qc = 0.7, qf = 0.5, pc = 0.4, pt = 0.95;
    const Opponent r = toOpponent(ref), t = toOpponent(test);

    const Kernel a = csfKernel(ppd, 1, 0.0047, 0, 1e-5), rg = csfKernel(ppd, 1, 0.0053, 0, 1e-5),
                 by = csfKernel(ppd, 34.1, 0.04, 13.5, 0.025);
    const auto labR = filteredHuntLab(r, a, rg, by), labT = filteredHuntLab(t, a, rg, by);
    const double cmax = std::pow(hyab(huntLab({0, 1, 0}), huntLab({0, 0, 1})), qc);

    auto achromatic = [](const Plane& y) {
        Plane p = y;
        for (double& v : p.v) v = (v + 16) / 116;
        return p;
    };
    const Kernel edge = featureKernel(ppd, false), point = featureKernel(ppd, true);
    const Plane yr = achromatic(r.y), yt = achromatic(t.y);
    const auto er = featureMagnitude(yr, edge), et = featureMagnitude(yt, edge);
    const auto pr = featureMagnitude(yr, point), ptm = featureMagnitude(yt, point);

    FlipMaps m;
    m.width = ref.width;
    m.height = ref.height;
    const size_t n = labR.size();
    m.color.resize(n), m.feature.resize(n), m.flip.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const double d = std::pow(hyab(labR[i], labT[i]), qc);
        const double c = d < pc * cmax ? pt / (pc * cmax) * d : pt + (d - pc * cmax) / (cmax - pc * cmax) * (1 - pt);
        const double f = std::pow(std::max(std::fabs(er[i] - et[i]), std::fabs(pr[i] - ptm[i])) / std::sqrt(2.0), qf);
        m.color[i] = float(c);
        m.feature[i] = float(f);
        m.flip[i] = float(std::pow(c, 1 - f));
    }
    return m;
}

FlipMaps ldrFlipLinear(const Image& reference, const Image& test, double ppd) {
    auto encode = [](const Image& im) {
        Image o = im;
        for (float& v : o.rgb) v = std::isfinite(v) ? float(linearToSrgb(std::clamp(double(v), 0.0, 1.0))) : 0.0f;
        return o;
    };
    return ldrFlipSrgb(encode(reference), encode(test), ppd);
}

} // namespace stipple::validation
