// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "scene/shape_builders.h"

namespace stipple::render {

namespace {

// Appends triangle (a, b, c), flipped if needed so its normal agrees with `outward`; drops degenerate ones.
void addOriented(TriangleMesh& m, uint32_t a, uint32_t b, uint32_t c, const Vec3& outward) {
    const Vec3 &pa = m.positions[a], &pb = m.positions[b], &pc = m.positions[c];
    Vec3 n = cross(pb - pa, pc - pa);
    if (lengthSquared(n) == 0) return;
    if (dot(n, outward) < 0) std::swap(b, c);
    m.indices.insert(m.indices.end(), {a, b, c});
}

uint32_t addVertex(TriangleMesh& m, const Vec3& p) {
    m.positions.push_back(p);
    return uint32_t(m.positions.size() - 1);
}

} // namespace

TriangleMesh makeQuad(const Vec3 v[4]) {
    TriangleMesh m;
    m.positions.assign(v, v + 4);
    m.indices = {0, 1, 2, 0, 2, 3};
    return m;
}

TriangleMesh makeBox(const Vec3& lo, const Vec3& hi) {
    TriangleMesh m;
    Vec3 c = (lo + hi) * 0.5f;
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            int u = (axis + 1) % 3, v = (axis + 2) % 3;
            Vec3 corners[4];
            for (int k = 0; k < 4; ++k) {
                Vec3 p;
                p[axis] = side ? hi[axis] : lo[axis];
                p[u] = (k == 1 || k == 2) ? hi[u] : lo[u];
                p[v] = (k >= 2) ? hi[v] : lo[v];
                corners[k] = p;
            }
            uint32_t base = uint32_t(m.positions.size());
            for (const Vec3& p : corners) addVertex(m, p);
            Vec3 out;
            out[axis] = side ? 1.0f : -1.0f;
            addOriented(m, base, base + 1, base + 2, out);
            addOriented(m, base, base + 2, base + 3, out);
        }
    }
    (void)c;
    return m;
}

TriangleMesh makeCylinder(const Vec3& base, const Vec3& axisIn, float height, float radius, int segments, bool caps) {
    TriangleMesh m;
    Vec3 axis = normalize(axisIn);
    Frame f(axis);
    Vec3 top = base + axis * height;
    std::vector<uint32_t> bottomRing, topRing;
    for (int i = 0; i < segments; ++i) {
        float phi = 2 * kPi * float(i) / float(segments);
        Vec3 r = (f.s * std::cos(phi) + f.t * std::sin(phi)) * radius;
        bottomRing.push_back(addVertex(m, base + r));
        topRing.push_back(addVertex(m, top + r));
    }
    for (int i = 0; i < segments; ++i) {
        int j = (i + 1) % segments;
        float phi = 2 * kPi * (float(i) + 0.5f) / float(segments);
        Vec3 out = f.s * std::cos(phi) + f.t * std::sin(phi);
        addOriented(m, bottomRing[i], bottomRing[j], topRing[j], out);
        addOriented(m, bottomRing[i], topRing[j], topRing[i], out);
    }
    if (caps) {
        uint32_t cb = addVertex(m, base), ct = addVertex(m, top);
        for (int i = 0; i < segments; ++i) {
            int j = (i + 1) % segments;
            addOriented(m, cb, bottomRing[i], bottomRing[j], -axis);
            addOriented(m, ct, topRing[i], topRing[j], axis);
        }
    }
    return m;
}

TriangleMesh makeLathe(const std::vector<std::pair<float, float>>& profile, int segments) {
    TriangleMesh m;
    size_t n = profile.size();
    std::vector<std::vector<uint32_t>> rings(n);
    for (size_t i = 0; i < n; ++i) {
        auto [r, h] = profile[i];
        if (r == 0) {
            rings[i].assign(size_t(segments), addVertex(m, Vec3(0, h, 0))); // a pole: one shared vertex
            continue;
        }
        for (int k = 0; k < segments; ++k) {
            float phi = 2 * kPi * float(k) / float(segments);
            rings[i].push_back(addVertex(m, Vec3(r * std::cos(phi), h, r * std::sin(phi))));
        }
    }
    for (size_t i = 0; i + 1 < n; ++i) {
        float dr = profile[i + 1].first - profile[i].first, dh = profile[i + 1].second - profile[i].second;
        for (int k = 0; k < segments; ++k) {
            int k1 = (k + 1) % segments;
            float phi = 2 * kPi * (float(k) + 0.5f) / float(segments);
            // Outward in the profile plane is (dh, -dr): rotate it about +y to this segment's angle.
            Vec3 out(dh * std::cos(phi), -dr, dh * std::sin(phi));
            addOriented(m, rings[i][k], rings[i][k1], rings[i + 1][k1], out);
            addOriented(m, rings[i][k], rings[i + 1][k1], rings[i + 1][k], out);
        }
    }
    return m;
}

TriangleMesh makeSphereMesh(int rings, int segments) {
    std::vector<std::pair<float, float>> profile;
    for (int i = 0; i <= rings; ++i) {
        float theta = kPi * float(i) / float(rings); // from the south pole up
        profile.push_back({i == 0 || i == rings ? 0.0f : std::sin(theta), -std::cos(theta)});
    }
    return makeLathe(profile, segments);
}

} // namespace stipple::render
