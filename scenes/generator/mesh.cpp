// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "mesh.h"

#include <stipple/render/temp_files.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <numbers>
#include <stdexcept>

namespace stipple::citygen {

uint32_t Mesh::addVertex(Vec3 p) {
    positions_.push_back(float(p.x));
    positions_.push_back(float(p.y));
    positions_.push_back(float(p.z));
    return uint32_t(positions_.size() / 3 - 1);
}

void Mesh::addTriangle(uint32_t a, uint32_t b, uint32_t c) { indices_.insert(indices_.end(), {a, b, c}); }

void Mesh::addTriangle(Vec3 a, Vec3 b, Vec3 c, Vec3 facing) {
    if (dot(cross(b - a, c - a), facing) < 0) std::swap(b, c);
    uint32_t i = addVertex(a), j = addVertex(b), k = addVertex(c);
    addTriangle(i, j, k);
}

void Mesh::addQuad(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 facing) {
    // Orientation from the quad's diagonal cross product, robust to one degenerate edge.
    if (dot(cross(c - a, d - b), facing) < 0) std::swap(b, d);
    uint32_t i = addVertex(a), j = addVertex(b), k = addVertex(c), l = addVertex(d);
    addTriangle(i, j, k);
    addTriangle(i, k, l);
}

void Mesh::addRect(const Frame& f, double s0, double t0, double s1, double t1, double d, bool back) {
    if (s1 <= s0 || t1 <= t0) return;
    addQuad(f(s0, t0, d), f(s1, t0, d), f(s1, t1, d), f(s0, t1, d), back ? f.ez * -1.0 : f.ez);
}

void Mesh::addBox(const Frame& f, Vec3 lo, Vec3 hi) {
    Vec3 p[8];
    for (int i = 0; i < 8; ++i) p[i] = f(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    addQuad(p[0], p[2], p[6], p[4], f.ex * -1.0);
    addQuad(p[1], p[3], p[7], p[5], f.ex);
    addQuad(p[0], p[1], p[5], p[4], f.ey * -1.0);
    addQuad(p[2], p[3], p[7], p[6], f.ey);
    addQuad(p[0], p[1], p[3], p[2], f.ez * -1.0);
    addQuad(p[4], p[5], p[7], p[6], f.ez);
}

void Mesh::addCylinder(const Frame& f, double r, double t0, double t1, int segments, bool caps) {
    std::vector<std::pair<double, double>> profile;
    if (caps) profile.push_back({0, t0});
    profile.push_back({r, t0});
    profile.push_back({r, t1});
    if (caps) profile.push_back({0, t1});
    addLathe(f, profile, segments);
}

void Mesh::addLathe(const Frame& f, const std::vector<std::pair<double, double>>& profile, int segments) {
    auto at = [&](double r, double h, int k) {
        double phi = 2.0 * std::numbers::pi * k / segments;
        return f(r * std::cos(phi), h, -r * std::sin(phi));
    };
    for (size_t i = 0; i + 1 < profile.size(); ++i) {
        auto [r0, h0] = profile[i];
        auto [r1, h1] = profile[i + 1];
        for (int k = 0; k < segments; ++k) {
            Vec3 a = at(r0, h0, k), b = at(r0, h0, k + 1), c = at(r1, h1, k + 1), d = at(r1, h1, k);
            // Outward for a profile walked bottom to top: the normal of the profile segment turned right.
            double phi = 2.0 * std::numbers::pi * (k + 0.5) / segments;
            Vec3 radial = f.dir({std::cos(phi), 0, -std::sin(phi)});
            Vec3 facing = radial * (h1 - h0) + f.ey * (r0 - r1);
            if (r0 == 0 && r1 == 0) continue;
            if (r0 == 0)
                addTriangle(a, c, d, facing);
            else if (r1 == 0)
                addTriangle(a, b, c, facing);
            else
                addQuad(a, b, c, d, facing);
        }
    }
}

void Mesh::append(const Mesh& other) {
    uint32_t base = uint32_t(positions_.size() / 3);
    positions_.insert(positions_.end(), other.positions_.begin(), other.positions_.end());
    for (uint32_t i : other.indices_) indices_.push_back(base + i);
}

namespace {
void putU32(std::string& out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(char((v >> (8 * i)) & 0xffu));
}
} // namespace

void Mesh::writePly(const std::string& path) const {
    std::string out = "ply\nformat binary_little_endian 1.0\ncomment stipple city generator\n";
    out += "element vertex " + std::to_string(positions_.size() / 3) + "\n";
    out += "property float x\nproperty float y\nproperty float z\n";
    out += "element face " + std::to_string(indices_.size() / 3) + "\n";
    out += "property list uchar int vertex_indices\nend_header\n";
    out.reserve(out.size() + positions_.size() * 4 + indices_.size() / 3 * 13);
    for (float x : positions_) {
        uint32_t bits;
        std::memcpy(&bits, &x, 4);
        putU32(out, bits);
    }
    for (size_t i = 0; i < indices_.size(); i += 3) {
        out.push_back(char(3));
        for (int k = 0; k < 3; ++k) putU32(out, indices_[i + k]);
    }
    stipple::render::TempPath temp(path); // two build trees may regenerate at once
    const std::string& tmp = temp.path();
    {
        std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
        if (!f) throw std::runtime_error("cannot write '" + tmp + "'");
        f.write(out.data(), std::streamsize(out.size()));
        if (!f) throw std::runtime_error("write failed: '" + tmp + "'");
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0)
        throw std::runtime_error("cannot rename '" + tmp + "' to '" + path + "'");
    temp.release();
}

} // namespace stipple::citygen
