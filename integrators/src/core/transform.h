// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Affine transforms (3x4, row-major) with their inverse, for shape placement and instances.
#pragma once

#include "core/geometry.h"

#include <array>

namespace stipple::render {

struct Transform {
    // m[r][c]; the implicit fourth row is (0, 0, 0, 1).
    std::array<std::array<float, 4>, 3> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};

    static Transform translate(const Vec3& t);
    static Transform scale(const Vec3& s);
    static Transform rotate(float degrees, const Vec3& axis);
    // From 12 or 16 row-major numbers (the last row must be 0 0 0 1 when 16 are given).
    static Transform fromRows(const float* v);

    Vec3 point(const Vec3& p) const {
        return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
                m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
                m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
    }
    Vec3 vector(const Vec3& v) const {
        return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
    }
    // Applies the inverse transpose of this transform's linear part: call it on the INVERSE transform to map a
    // normal forward (n' = M^-T n).
    Vec3 normalByInverse(const Vec3& n) const {
        return {m[0][0] * n.x + m[1][0] * n.y + m[2][0] * n.z, m[0][1] * n.x + m[1][1] * n.y + m[2][1] * n.z,
                m[0][2] * n.x + m[1][2] * n.y + m[2][2] * n.z};
    }
    float determinant() const;
    Transform inverse() const; // precondition: determinant != 0
    bool isIdentity() const;
    // True when the linear part is a rotation times a uniform scale (spheres stay spheres); returns the scale.
    bool isSimilarity(float& uniformScale) const;
};

// a * b: apply b first, then a.
Transform operator*(const Transform& a, const Transform& b);

} // namespace stipple::render
