// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// A triangle soup with the few primitive builders the town needs, and a binary little-endian PLY writer.
#pragma once

#include "vec.h"

#include <cstdint>
#include <string>
#include <vector>

namespace stipple::citygen {

class Mesh {
public:
    uint32_t addVertex(Vec3 p);
    void addTriangle(uint32_t a, uint32_t b, uint32_t c);

    // Triangle / quad whose winding is made counter-clockwise seen from the side `facing` points to.
    void addTriangle(Vec3 a, Vec3 b, Vec3 c, Vec3 facing);
    void addQuad(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 facing);
    // A rectangle in a frame's (s, t) plane at depth d, facing +ez (or -ez when `back`).
    void addRect(const Frame& f, double s0, double t0, double s1, double t1, double d, bool back = false);
    // A box [lo, hi] in frame coordinates, all six faces outward.
    void addBox(const Frame& f, Vec3 lo, Vec3 hi);
    // A capped or open cylinder about the frame's ey axis, radius r, from t0 to t1.
    void addCylinder(const Frame& f, double r, double t0, double t1, int segments, bool caps);
    // A surface of revolution about the frame's ey axis: profile of (radius, height) pairs.
    // Faces point away from the axis where the profile rises (walk the profile bottom to top for outward).
    void addLathe(const Frame& f, const std::vector<std::pair<double, double>>& profile, int segments);

    void append(const Mesh& other);
    size_t triangleCount() const { return indices_.size() / 3; }
    bool empty() const { return indices_.empty(); }

    // Binary little-endian PLY: float x y z, faces as "list uchar int". Written byte by byte, so the file
    // is identical on any host.
    void writePly(const std::string& path) const;

private:
    std::vector<float> positions_;
    std::vector<uint32_t> indices_;
};

} // namespace stipple::citygen
