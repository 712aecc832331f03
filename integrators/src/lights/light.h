// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Area lights: emissive triangle meshes, parallelograms (quads) and spheres, one- or two-sided, constant
// radiance. All in world space. Densities:
//   sampleLi / pdfLi: SOLID ANGLE at the reference point (area density converted in one place, toSolidAngle).
//   sampleLe / pdfLe: position in AREA measure on the light, direction in solid angle (for BDPT light paths).
#pragma once

#include "sampling/discrete_distribution.h"
#include "core/geometry.h"
#include "sampling/warps.h"

#include <vector>

namespace stipple::render {

struct LightLiSample {
    Spectrum L;    // radiance arriving at the reference point (before visibility)
    Vec3 wi;       // from the reference point to the light point
    float pdf = 0; // solid angle at the reference point
    Vec3 p, n;     // light point and its normal
    float distance = 0;
};

struct LightLeSample {
    Spectrum L;
    Ray ray;          // leaves the light point
    Vec3 n;           // light normal at the origin (oriented to the side the ray leaves)
    float pdfPos = 0; // area measure
    float pdfDir = 0; // solid angle
};

class Light {
public:
    enum class Kind { Mesh, Parallelogram, Sphere };

    static Light mesh(std::vector<Vec3> trianglesWorld, Spectrum L, bool twoSided); // 3 points per triangle
    static Light parallelogram(Vec3 p0, Vec3 e1, Vec3 e2, Spectrum L, bool twoSided);
    static Light sphere(Vec3 center, float radius, Spectrum L, bool twoSided);

    Kind kind() const { return kind_; }
    bool twoSided() const { return twoSided_; }
    const Spectrum& radiance() const { return L_; }
    float area() const { return area_; }
    // Emitted power (radiance x area x pi, doubled when two-sided): the light-choice weight.
    float power() const;

    // Radiance leaving point p (normal n) in direction w.
    Spectrum L(const Vec3& n, const Vec3& w) const { return (twoSided_ || dot(n, w) > 0) ? L_ : Spectrum(); }
    // Samples a point seen from ref; false when the sample carries nothing.
    bool sampleLi(const Vec3& ref, Point2 u, LightLiSample& out) const;
    // Solid-angle density of sampleLi at ref for the light point p with normal n.
    float pdfLi(const Vec3& ref, const Vec3& p, const Vec3& n) const;

    // Emission sampling for light paths: uPos picks the point, uDir the (cosine-weighted) direction.
    bool sampleLe(Point2 uPos, Point2 uDir, LightLeSample& out) const;
    void pdfLe(const Vec3& n, const Vec3& w, float& pdfPos, float& pdfDir) const;

private:
    void samplePoint(Point2 u, Vec3& p, Vec3& n) const; // uniform by area
    float sphereConePdf(const Vec3& ref) const;
    bool seesSphereAsCone(const Vec3& ref) const;

    Kind kind_ = Kind::Mesh;
    Spectrum L_;
    bool twoSided_ = false;
    float area_ = 0;
    std::vector<Vec3> tri_;        // mesh
    DiscreteDistribution triArea_; // mesh
    Vec3 p0_, e1_, e2_, n_;        // parallelogram
    Vec3 center_;                  // sphere
    float radius_ = 0;
};

// Area density (1/area) at light point p with normal n converted to solid angle at ref.
inline float toSolidAngle(float pdfArea, const Vec3& ref, const Vec3& p, const Vec3& n) {
    Vec3 d = p - ref;
    float dist2 = lengthSquared(d);
    float cosL = absDot(n, d) / std::sqrt(dist2);
    return cosL > 0 ? pdfArea * dist2 / cosL : 0.0f;
}

} // namespace stipple::render
