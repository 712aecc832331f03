// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "materials/material.h"

#include "materials/microfacet.h"

namespace stipple::render {

namespace {

// Reflection-only BSDFs are two-sided: evaluate with wo in the upper hemisphere.
inline void toUpper(Vec3& wo, Vec3& wi) {
    if (wo.z < 0) {
        wo.z = -wo.z;
        wi.z = -wi.z;
    }
}

Spectrum conductorFresnel(const Material& m, float cosThetaI) {
    return {fresnelConductor(cosThetaI, m.eta.r, m.k.r), fresnelConductor(cosThetaI, m.eta.g, m.k.g),
            fresnelConductor(cosThetaI, m.eta.b, m.k.b)};
}

// GGX reflection lobe value D G / (4 cos cos) (times Fresnel by the caller) and its sampling density.
float microfacetReflection(const GGX& ggx, const Vec3& wo, const Vec3& wi, Vec3& wm) {
    float co = absCosTheta(wo), ci = absCosTheta(wi);
    if (co == 0 || ci == 0) return 0;
    wm = wo + wi;
    if (lengthSquared(wm) == 0) return 0;
    wm = normalize(wm);
    return ggx.D(wm) * ggx.G(wo, wi) / (4 * co * ci);
}

float microfacetReflectionPdf(const GGX& ggx, const Vec3& wo, const Vec3& wi) {
    Vec3 wm = wo + wi;
    if (lengthSquared(wm) == 0) return 0;
    wm = normalize(wm);
    if (wm.z < 0) wm = -wm;
    float d = std::abs(dot(wo, wm));
    if (d == 0) return 0;
    return ggx.pdf(wo, wm) / (4 * d);
}

} // namespace

float Material::plasticCoatProbability(float cosThetaO) const {
    float F = fresnelDielectric(std::abs(cosThetaO), ior);
    float d = (1 - F) * albedo.average();
    float p = F + d > 0 ? F / (F + d) : 1.0f;
    return clampf(p, 0.05f, 0.95f);
}

Spectrum Material::f(Vec3 wo, Vec3 wi, TransportMode) const {
    switch (type) {
    case MaterialType::Diffuse: return sameHemisphere(wo, wi) ? albedo * kInvPi : Spectrum();
    case MaterialType::Conductor: {
        toUpper(wo, wi);
        if (wi.z <= 0) return {};
        Vec3 wm;
        float v = microfacetReflection(GGX(roughness), wo, wi, wm);
        return v > 0 ? conductorFresnel(*this, std::abs(dot(wo, wm))) * v : Spectrum();
    }
    case MaterialType::Plastic: {
        toUpper(wo, wi);
        if (wi.z <= 0) return {};
        Vec3 wm;
        float spec = microfacetReflection(GGX(roughness), wo, wi, wm);
        if (spec > 0) spec *= fresnelDielectric(std::abs(dot(wo, wm)), ior);
        // Lambert base seen through the coat twice; inter-reflections under the coat are ignored (energy lost).
        float t = (1 - fresnelDielectric(wo.z, ior)) * (1 - fresnelDielectric(wi.z, ior));
        return albedo * (kInvPi * t) + Spectrum(spec);
    }
    case MaterialType::Mirror:
    case MaterialType::Dielectric: return {};
    }
    return {};
}

float Material::pdf(Vec3 wo, Vec3 wi) const {
    switch (type) {
    case MaterialType::Diffuse: return sameHemisphere(wo, wi) ? cosineHemispherePdf(std::abs(wi.z)) : 0;
    case MaterialType::Conductor:
        toUpper(wo, wi);
        if (wi.z <= 0) return 0;
        return microfacetReflectionPdf(GGX(roughness), wo, wi);
    case MaterialType::Plastic: {
        toUpper(wo, wi);
        if (wi.z <= 0) return 0;
        float pc = plasticCoatProbability(wo.z);
        return pc * microfacetReflectionPdf(GGX(roughness), wo, wi) + (1 - pc) * cosineHemispherePdf(wi.z);
    }
    case MaterialType::Mirror:
    case MaterialType::Dielectric: return 0;
    }
    return 0;
}

bool Material::sample(Vec3 wo, float uc, Point2 u, BsdfSample& out, TransportMode mode) const {
    if (wo.z == 0) return false;
    switch (type) {
    case MaterialType::Diffuse: {
        Vec3 wi = sampleCosineHemisphere(u);
        if (wo.z < 0) wi.z = -wi.z;
        out.wi = wi;
        out.pdf = cosineHemispherePdf(std::abs(wi.z));
        out.f = albedo * kInvPi;
        out.flags = kBsdfReflection | kBsdfDiffuse;
        return out.pdf > 0;
    }
    case MaterialType::Conductor: {
        float flip = wo.z < 0 ? -1.0f : 1.0f;
        Vec3 wou(wo.x, wo.y, wo.z * flip);
        GGX ggx(roughness);
        Vec3 wm = ggx.Sample_wm(wou, u);
        Vec3 wi = reflect(wou, wm);
        if (wi.z <= 0) return false;
        out.pdf = microfacetReflectionPdf(ggx, wou, wi);
        out.f = f(wou, wi, mode);
        out.wi = Vec3(wi.x, wi.y, wi.z * flip);
        out.flags = kBsdfReflection | kBsdfGlossy;
        return out.pdf > 0;
    }
    case MaterialType::Plastic: {
        float flip = wo.z < 0 ? -1.0f : 1.0f;
        Vec3 wou(wo.x, wo.y, wo.z * flip);
        float pc = plasticCoatProbability(wou.z);
        Vec3 wi;
        if (uc < pc) {
            Vec3 wm = GGX(roughness).Sample_wm(wou, u);
            wi = reflect(wou, wm);
            if (wi.z <= 0) return false;
            out.flags = kBsdfReflection | kBsdfGlossy;
        } else {
            wi = sampleCosineHemisphere(u);
            out.flags = kBsdfReflection | kBsdfDiffuse;
        }
        out.pdf = pdf(wou, wi);
        out.f = f(wou, wi, mode);
        out.wi = Vec3(wi.x, wi.y, wi.z * flip);
        return out.pdf > 0;
    }
    case MaterialType::Mirror: {
        out.wi = Vec3(-wo.x, -wo.y, wo.z);
        out.pdf = 1;
        out.f = albedo / std::abs(wo.z);
        out.flags = kBsdfReflection | kBsdfSpecular;
        return true;
    }
    case MaterialType::Dielectric: {
        float R = fresnelDielectric(wo.z, ior), T = 1 - R;
        if (uc < R / (R + T)) {
            out.wi = Vec3(-wo.x, -wo.y, wo.z);
            out.pdf = R / (R + T);
            out.f = Spectrum(R / std::abs(wo.z));
            out.flags = kBsdfReflection | kBsdfSpecular;
            return true;
        }
        Vec3 wi;
        float etap = 1;
        if (!refract(wo, Vec3(0, 0, 1), ior, etap, wi)) return false;
        out.wi = wi;
        out.pdf = T / (R + T);
        // Radiance is scaled by 1/eta^2 across the interface (solid-angle compression); importance is not
        // (Veach's thesis 5.2: the BSDF is not symmetric at refractions, its adjoint drops this factor).
        float scale = mode == TransportMode::Radiance ? 1 / (etap * etap) : 1.0f;
        out.f = Spectrum(T * scale / std::abs(wi.z));
        out.flags = kBsdfTransmission | kBsdfSpecular;
        out.eta = etap;
        return true;
    }
    }
    return false;
}

} // namespace stipple::render
