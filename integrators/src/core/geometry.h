// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Small vector math: Vec3, RGB spectrum, orthonormal frames, rays. Float throughout; accumulation in double
// happens in the film only.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace stipple::render {

constexpr float kPi = 3.14159265358979323846f;
constexpr float kInvPi = 0.31830988618379067154f;
constexpr float kInf = std::numeric_limits<float>::infinity();
// Largest float below 1: what a [0,1) sample may be at most.
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

struct Vec3 {
    float x = 0, y = 0, z = 0;
    constexpr Vec3() = default;
    constexpr Vec3(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
    float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    float& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
    Vec3 operator+(const Vec3& b) const { return {x + b.x, y + b.y, z + b.z}; }
    Vec3 operator-(const Vec3& b) const { return {x - b.x, y - b.y, z - b.z}; }
    Vec3 operator-() const { return {-x, -y, -z}; }
    Vec3 operator*(float s) const { return {x * s, y * s, z * s}; }
    Vec3 operator/(float s) const {
        float r = 1.0f / s;
        return {x * r, y * r, z * r};
    }
    Vec3& operator+=(const Vec3& b) {
        x += b.x;
        y += b.y;
        z += b.z;
        return *this;
    }
    Vec3& operator-=(const Vec3& b) {
        x -= b.x;
        y -= b.y;
        z -= b.z;
        return *this;
    }
    Vec3& operator*=(float s) {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
};
inline Vec3 operator*(float s, const Vec3& v) { return v * s; }
inline float dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline float absDot(const Vec3& a, const Vec3& b) { return std::abs(dot(a, b)); }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline float lengthSquared(const Vec3& v) { return dot(v, v); }
inline float length(const Vec3& v) { return std::sqrt(dot(v, v)); }
inline Vec3 normalize(const Vec3& v) { return v / length(v); }
inline Vec3 vmin(const Vec3& a, const Vec3& b) { return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)}; }
inline Vec3 vmax(const Vec3& a, const Vec3& b) { return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}; }
inline float maxAbsComponent(const Vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }
inline Vec3 faceForward(const Vec3& n, const Vec3& v) { return dot(n, v) < 0 ? -n : n; }

// Linear Rec.709 RGB radiance / reflectance.
struct Spectrum {
    float r = 0, g = 0, b = 0;
    constexpr Spectrum() = default;
    constexpr explicit Spectrum(float v) : r(v), g(v), b(v) {}
    constexpr Spectrum(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}
    float operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
    float& operator[](int i) { return i == 0 ? r : (i == 1 ? g : b); }
    Spectrum operator+(const Spectrum& s) const { return {r + s.r, g + s.g, b + s.b}; }
    Spectrum operator-(const Spectrum& s) const { return {r - s.r, g - s.g, b - s.b}; }
    Spectrum operator*(const Spectrum& s) const { return {r * s.r, g * s.g, b * s.b}; }
    Spectrum operator/(const Spectrum& s) const {
        return {s.r != 0 ? r / s.r : 0, s.g != 0 ? g / s.g : 0, s.b != 0 ? b / s.b : 0};
    }
    Spectrum operator*(float s) const { return {r * s, g * s, b * s}; }
    Spectrum operator/(float s) const {
        float i = 1.0f / s;
        return {r * i, g * i, b * i};
    }
    Spectrum& operator+=(const Spectrum& s) {
        r += s.r;
        g += s.g;
        b += s.b;
        return *this;
    }
    Spectrum& operator*=(const Spectrum& s) {
        r *= s.r;
        g *= s.g;
        b *= s.b;
        return *this;
    }
    Spectrum& operator*=(float s) {
        r *= s;
        g *= s;
        b *= s;
        return *this;
    }
    bool isBlack() const { return r == 0 && g == 0 && b == 0; }
    float maxComponent() const { return std::max({r, g, b}); }
    float average() const { return (r + g + b) * (1.0f / 3.0f); }
    float luminance() const { return 0.2126f * r + 0.7152f * g + 0.0722f * b; }
    bool isFinite() const { return std::isfinite(r) && std::isfinite(g) && std::isfinite(b); }
};
inline Spectrum operator*(float s, const Spectrum& c) { return c * s; }

// Orthonormal basis with z along n (Duff et al. 2017, "Building an orthonormal basis, revisited").
struct Frame {
    Vec3 s, t, n;
    Frame() : s(1, 0, 0), t(0, 1, 0), n(0, 0, 1) {}
    explicit Frame(const Vec3& nn) : n(nn) {
        float sign = std::copysign(1.0f, n.z);
        float a = -1.0f / (sign + n.z);
        float b = n.x * n.y * a;
        s = Vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
        t = Vec3(b, sign + n.y * n.y * a, -n.y);
    }
    Vec3 toLocal(const Vec3& v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
    Vec3 toWorld(const Vec3& v) const { return s * v.x + t * v.y + n * v.z; }
};

struct Ray {
    Vec3 o;
    Vec3 d;
    float tMax = kInf;
};

// Scale-aware offset of a ray origin off a surface: geometry may sit far from the origin (1e5 units), where a
// fixed epsilon would be below one float ulp of the coordinates.
inline float surfaceEpsilon(const Vec3& p) { return 1e-6f * std::max(1.0f, maxAbsComponent(p)); }
inline Vec3 offsetRayOrigin(const Vec3& p, const Vec3& ng, const Vec3& w) {
    float eps = surfaceEpsilon(p);
    return dot(w, ng) >= 0 ? p + ng * eps : p - ng * eps;
}

inline float clampf(float v, float lo, float hi) { return std::min(std::max(v, lo), hi); }
inline float safeSqrt(float v) { return std::sqrt(std::max(0.0f, v)); }
inline float sqr(float v) { return v * v; }

// Local shading-space trigonometry (z is the normal).
inline float cosTheta(const Vec3& w) { return w.z; }
inline float absCosTheta(const Vec3& w) { return std::abs(w.z); }
inline float cos2Theta(const Vec3& w) { return w.z * w.z; }
// From x and y, not 1 - cos^2: exact near the pole, where GGX with alpha 0.001 lives (unit vectors only).
inline float sin2Theta(const Vec3& w) { return w.x * w.x + w.y * w.y; }
inline float tan2Theta(const Vec3& w) { return sin2Theta(w) / cos2Theta(w); }
inline bool sameHemisphere(const Vec3& a, const Vec3& b) { return a.z * b.z > 0; }

} // namespace stipple::render
