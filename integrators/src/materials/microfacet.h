// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Isotropic GGX (Trowbridge-Reitz) microfacet distribution with visible-normal sampling (Heitz 2018, as in
// pbrt-v4), plus the Fresnel terms the materials use. All directions in the local shading frame (z = normal).
#pragma once

#include "sampling/warps.h"

#include <complex>

namespace stipple::render {

class GGX {
public:
    explicit GGX(float alpha) : alpha_(alpha) {}
    float alpha() const { return alpha_; }

    // Normal distribution D(wm), normalised so that integral of D(wm) cos(theta_m) d(wm) = 1.
    float D(const Vec3& wm) const {
        float t2 = tan2Theta(wm);
        if (std::isinf(t2)) return 0;
        float c4 = sqr(cos2Theta(wm));
        if (c4 < 1e-16f) return 0;
        float e = t2 / sqr(alpha_);
        return 1 / (kPi * sqr(alpha_) * c4 * sqr(1 + e));
    }
    float Lambda(const Vec3& w) const {
        float t2 = tan2Theta(w);
        if (std::isinf(t2)) return 0;
        return (std::sqrt(1 + sqr(alpha_) * t2) - 1) / 2;
    }
    float G1(const Vec3& w) const { return 1 / (1 + Lambda(w)); }
    // Height-correlated masking-shadowing.
    float G(const Vec3& wo, const Vec3& wi) const { return 1 / (1 + Lambda(wo) + Lambda(wi)); }
    // Distribution of visible normals from w; pdf of Sample_wm (solid angle of wm).
    float D(const Vec3& w, const Vec3& wm) const { return G1(w) / absCosTheta(w) * D(wm) * std::abs(dot(w, wm)); }
    float pdf(const Vec3& w, const Vec3& wm) const { return D(w, wm); }

    // Samples a visible normal seen from w (any hemisphere; the result is in the upper one).
    Vec3 Sample_wm(const Vec3& w, Point2 u) const {
        Vec3 wh = normalize(Vec3(alpha_ * w.x, alpha_ * w.y, w.z));
        if (wh.z < 0) wh = -wh;
        Vec3 t1 = wh.z < 0.99999f ? normalize(cross(Vec3(0, 0, 1), wh)) : Vec3(1, 0, 0);
        Vec3 t2 = cross(wh, t1);
        float r = std::sqrt(u.x), phi = 2 * kPi * u.y;
        float px = r * std::cos(phi), py = r * std::sin(phi);
        float h = std::sqrt(std::max(0.0f, 1 - px * px));
        float s = (1 + wh.z) / 2;
        py = (1 - s) * h + s * py;
        float pz = safeSqrt(1 - px * px - py * py);
        Vec3 nh = t1 * px + t2 * py + wh * pz;
        return normalize(Vec3(alpha_ * nh.x, alpha_ * nh.y, std::max(1e-6f, nh.z)));
    }

private:
    float alpha_;
};

inline Vec3 reflect(const Vec3& wo, const Vec3& n) { return -wo + n * (2 * dot(wo, n)); }

// Refraction of wi about n with relative IOR eta (= n_transmitted / n_incident when wi is on n's side).
// Returns false on total internal reflection; etap is the relative IOR actually used.
inline bool refract(const Vec3& wi, Vec3 n, float eta, float& etap, Vec3& wt) {
    float cosi = dot(n, wi);
    if (cosi < 0) {
        eta = 1 / eta;
        cosi = -cosi;
        n = -n;
    }
    float sin2i = std::max(0.0f, 1 - cosi * cosi);
    float sin2t = sin2i / (eta * eta);
    if (sin2t >= 1) return false;
    float cost = safeSqrt(1 - sin2t);
    wt = -wi / eta + n * (cosi / eta - cost);
    etap = eta;
    return true;
}

// Unpolarised Fresnel reflectance of a dielectric interface; cosThetaI < 0 means from the inside.
inline float fresnelDielectric(float cosThetaI, float eta) {
    cosThetaI = clampf(cosThetaI, -1, 1);
    if (cosThetaI < 0) {
        eta = 1 / eta;
        cosThetaI = -cosThetaI;
    }
    float sin2t = (1 - cosThetaI * cosThetaI) / (eta * eta);
    if (sin2t >= 1) return 1;
    float cost = safeSqrt(1 - sin2t);
    float rParl = (eta * cosThetaI - cost) / (eta * cosThetaI + cost);
    float rPerp = (cosThetaI - eta * cost) / (cosThetaI + eta * cost);
    return (rParl * rParl + rPerp * rPerp) / 2;
}

// Fresnel reflectance of a conductor with complex IOR eta + i k (one channel).
inline float fresnelConductor(float cosThetaI, float eta, float k) {
    using C = std::complex<float>;
    cosThetaI = clampf(cosThetaI, 0, 1);
    C e(eta, k);
    float sin2i = 1 - cosThetaI * cosThetaI;
    C sin2t = sin2i / (e * e);
    C cost = std::sqrt(C(1) - sin2t);
    C rParl = (e * cosThetaI - cost) / (e * cosThetaI + cost);
    C rPerp = (cosThetaI - e * cost) / (cosThetaI + e * cost);
    return (std::norm(rParl) + std::norm(rPerp)) / 2;
}

} // namespace stipple::render
