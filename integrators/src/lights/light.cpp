// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "lights/light.h"

namespace stipple::render {

Light Light::mesh(std::vector<Vec3> tri, Spectrum L, bool twoSided) {
    Light l;
    l.kind_ = Kind::Mesh;
    l.L_ = L;
    l.twoSided_ = twoSided;
    std::vector<double> areas;
    for (size_t i = 0; i + 2 < tri.size(); i += 3) {
        double a = 0.5 * length(cross(tri[i + 1] - tri[i], tri[i + 2] - tri[i]));
        areas.push_back(a);
        l.area_ += float(a);
    }
    l.tri_ = std::move(tri);
    l.triArea_ = DiscreteDistribution(areas);
    return l;
}

Light Light::parallelogram(Vec3 p0, Vec3 e1, Vec3 e2, Spectrum L, bool twoSided) {
    Light l;
    l.kind_ = Kind::Parallelogram;
    l.L_ = L;
    l.twoSided_ = twoSided;
    l.p0_ = p0;
    l.e1_ = e1;
    l.e2_ = e2;
    Vec3 c = cross(e1, e2);
    l.area_ = length(c);
    l.n_ = c / l.area_;
    return l;
}

Light Light::sphere(Vec3 center, float radius, Spectrum L, bool twoSided) {
    Light l;
    l.kind_ = Kind::Sphere;
    l.L_ = L;
    l.twoSided_ = twoSided;
    l.center_ = center;
    l.radius_ = radius;
    l.area_ = 4 * kPi * radius * radius;
    return l;
}

float Light::power() const { return L_.average() * area_ * kPi * (twoSided_ ? 2.0f : 1.0f); }

void Light::samplePoint(Point2 u, Vec3& p, Vec3& n) const {
    switch (kind_) {
    case Kind::Parallelogram:
        p = p0_ + e1_ * u.x + e2_ * u.y;
        n = n_;
        return;
    case Kind::Mesh: {
        float ux;
        size_t t = triArea_.sample(u.x, nullptr, &ux);
        float b0, b1;
        sampleUniformTriangle({ux, u.y}, b0, b1);
        const Vec3 &a = tri_[3 * t], &b = tri_[3 * t + 1], &c = tri_[3 * t + 2];
        p = a * b0 + b * b1 + c * (1 - b0 - b1);
        n = normalize(cross(b - a, c - a));
        return;
    }
    case Kind::Sphere: {
        n = sampleUniformSphere(u);
        p = center_ + n * radius_;
        return;
    }
    }
}

// The cone of directions is only defined from outside the sphere. A point on (or numerically near) the surface,
// such as a hit on the inside of an emissive sphere far from the origin, uses area sampling, which is valid
// from anywhere; the slack covers float error of points computed on the surface.
bool Light::seesSphereAsCone(const Vec3& ref) const {
    float outer = radius_ * 1.001f + 4 * surfaceEpsilon(center_);
    return lengthSquared(ref - center_) > outer * outer;
}

float Light::sphereConePdf(const Vec3& ref) const {
    float dc2 = lengthSquared(center_ - ref);
    float sin2ThetaMax = radius_ * radius_ / dc2;
    float oneMinusCos = 1 - safeSqrt(1 - sin2ThetaMax);
    if (sin2ThetaMax < 0.00068523f) oneMinusCos = sin2ThetaMax / 2; // sin^2(1.5 deg): Taylor keeps precision
    return 1 / (2 * kPi * oneMinusCos);
}

bool Light::sampleLi(const Vec3& ref, Point2 u, LightLiSample& out) const {
    Vec3 p, n;
    if (kind_ == Kind::Sphere && seesSphereAsCone(ref)) {
        // Sample the cone of directions the sphere subtends (pbrt-v4), robust for tiny radii.
        float dc = length(center_ - ref);
        float sin2ThetaMax = radius_ * radius_ / (dc * dc);
        float sinThetaMax = std::sqrt(sin2ThetaMax);
        float cosThetaMax = safeSqrt(1 - sin2ThetaMax);
        float oneMinusCos = 1 - cosThetaMax;
        float cosTheta = (cosThetaMax - 1) * u.x + 1;
        float sin2Theta = 1 - cosTheta * cosTheta;
        if (sin2ThetaMax < 0.00068523f) {
            sin2Theta = sin2ThetaMax * u.x;
            cosTheta = std::sqrt(1 - sin2Theta);
            oneMinusCos = sin2ThetaMax / 2;
        }
        float cosAlpha = sin2Theta / sinThetaMax + cosTheta * safeSqrt(1 - sin2Theta / (sinThetaMax * sinThetaMax));
        float sinAlpha = safeSqrt(1 - cosAlpha * cosAlpha);
        float phi = 2 * kPi * u.y;
        Vec3 w(sinAlpha * std::cos(phi), sinAlpha * std::sin(phi), cosAlpha);
        Frame frame(normalize(center_ - ref));
        n = frame.toWorld(-w);
        p = center_ + n * radius_;
        out.pdf = 1 / (2 * kPi * oneMinusCos);
    } else {
        samplePoint(u, p, n);
        out.pdf = toSolidAngle(1 / area_, ref, p, n);
    }
    Vec3 d = p - ref;
    out.distance = length(d);
    if (out.distance == 0 || out.pdf == 0 || !std::isfinite(out.pdf)) return false;
    out.wi = d / out.distance;
    out.p = p;
    out.n = n;
    out.L = L(n, -out.wi);
    return !out.L.isBlack();
}

float Light::pdfLi(const Vec3& ref, const Vec3& p, const Vec3& n) const {
    if (kind_ == Kind::Sphere && seesSphereAsCone(ref)) return sphereConePdf(ref);
    return toSolidAngle(1 / area_, ref, p, n);
}

bool Light::sampleLe(Point2 uPos, Point2 uDir, LightLeSample& out) const {
    Vec3 p, n;
    samplePoint(uPos, p, n);
    float side = 1;
    if (twoSided_) {
        // The first half of uDir.x picks the front, the second the back; each half is stretched back to [0,1).
        if (uDir.x < 0.5f) {
            uDir.x = std::min(uDir.x * 2, kOneMinusEpsilon);
        } else {
            uDir.x = std::min((uDir.x - 0.5f) * 2, kOneMinusEpsilon);
            side = -1;
        }
    }
    Vec3 nSide = n * side;
    Vec3 local = sampleCosineHemisphere(uDir);
    Vec3 w = Frame(nSide).toWorld(local);
    out.L = L_;
    out.n = nSide;
    out.ray.o = offsetRayOrigin(p, nSide, w);
    out.ray.d = w;
    out.pdfPos = 1 / area_;
    out.pdfDir = cosineHemispherePdf(local.z) * (twoSided_ ? 0.5f : 1.0f);
    return out.pdfDir > 0;
}

void Light::pdfLe(const Vec3& n, const Vec3& w, float& pdfPos, float& pdfDir) const {
    pdfPos = 1 / area_;
    float c = dot(n, w);
    if (twoSided_)
        pdfDir = cosineHemispherePdf(std::abs(c)) * 0.5f;
    else
        pdfDir = c > 0 ? cosineHemispherePdf(c) : 0.0f;
}

} // namespace stipple::render
