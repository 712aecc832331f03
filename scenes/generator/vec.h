// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Small 3-vector and right-handed frame used by the city generator.
#pragma once

#include <cmath>

namespace stipple::citygen {

struct Vec3 {
    double x = 0, y = 0, z = 0;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(Vec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline Vec3 normalize(Vec3 a) { return a * (1.0 / std::sqrt(dot(a, a))); }

// An orthonormal right-handed frame (ex x ey = ez): maps local (s, t, d) to o + s ex + t ey + d ez.
// Orientation-preserving, so geometry built with outward faces in local space stays outward.
struct Frame {
    Vec3 o{0, 0, 0}, ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};
    Vec3 operator()(double s, double t, double d) const { return o + ex * s + ey * t + ez * d; }
    Vec3 dir(Vec3 v) const { return ex * v.x + ey * v.y + ez * v.z; }

    // A vertical facade: origin at its bottom-left seen from outside, outward normal n (horizontal).
    static Frame facade(Vec3 origin, Vec3 n) {
        Frame f;
        f.o = origin;
        f.ez = normalize(n);
        f.ey = {0, 1, 0};
        f.ex = cross(f.ey, f.ez);
        return f;
    }
    // A frame whose ey is `axis` (any perpendicular ex), for cylinders along arbitrary lines.
    static Frame alongAxis(Vec3 origin, Vec3 axis) {
        Frame f;
        f.o = origin;
        f.ey = normalize(axis);
        Vec3 helper = std::abs(f.ey.y) < 0.9 ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
        f.ex = normalize(cross(f.ey, helper));
        f.ez = cross(f.ex, f.ey);
        return f;
    }
    // This frame expressed inside `parent` (parent(child(p)) in one frame).
    Frame inside(const Frame& parent) const {
        return {parent(o.x, o.y, o.z), parent.dir(ex), parent.dir(ey), parent.dir(ez)};
    }
};

} // namespace stipple::citygen
