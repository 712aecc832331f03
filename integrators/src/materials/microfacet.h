// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Isotropic GGX (Trowbridge-Reitz) microfacet distribution with visible-normal sampling (Heitz 2018, as in
// pbrt-v4), plus the Fresnel terms the materials use. All directions in the local shading frame (z = normal).
#pragma once

#include "sampling/warps.h"

#include <algorithm>
#include <cmath>


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

// Fresnel reflectance of a conductor with complex IOR eta + i k (one channel), in real arithmetic: with
// a^2 - b^2 = eta^2 - k^2 - sin^2 and a^2 + b^2 = sqrt((eta^2 - k^2 - sin^2)^2 + 4 eta^2 k^2), where a + i b is the
// refracted cosine times the IOR, Rs = (a^2 + b^2 + cos^2 - 2 a cos) / (a^2 + b^2 + cos^2 + 2 a cos) and
// Rp = Rs (cos^2 (a^2 + b^2) - 2 a cos sin^2 + sin^4) / (cos^2 (a^2 + b^2) + 2 a cos sin^2 + sin^4). The same value as
// the complex form, without its library calls (complex division and square root), and as accurate.
inline float fresnelConductor(float cosThetaI, float eta, float k) {
    const float c = clampf(cosThetaI, 0, 1);
    const float cos2 = c * c, sin2 = 1 - cos2;
    const float eta2 = eta * eta, k2 = k * k;
    const float t0 = eta2 - k2 - sin2;
    const float a2plusb2 = std::sqrt(t0 * t0 + 4 * eta2 * k2);
    // a^2 = (a^2 + b^2 + t0) / 2, or, where t0 < 0 would cancel (eta < 1, small k), the same value as
    // 2 eta^2 k^2 / (a^2 + b^2 - t0), since (a^2 + b^2)^2 - t0^2 = 4 eta^2 k^2.
    const float a2 = t0 >= 0 ? 0.5f * (a2plusb2 + t0) : (a2plusb2 - t0 > 0 ? 2 * eta2 * k2 / (a2plusb2 - t0) : 0.0f);
    const float a = std::sqrt(a2);
    const float t1 = a2plusb2 + cos2, t2 = 2 * c * a;
    const float Rs = t1 + t2 > 0 ? (t1 - t2) / (t1 + t2) : 1.0f;
    const float t3 = cos2 * a2plusb2 + sin2 * sin2, t4 = t2 * sin2;
    const float Rp = t3 + t4 > 0 ? Rs * (t3 - t4) / (t3 + t4) : Rs;
    return clampf(0.5f * (Rp + Rs), 0, 1);
}

} // namespace stipple::render
