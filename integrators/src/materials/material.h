// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Materials and their BSDFs. Everything works in the local shading frame (z = the surface normal as built,
// outward for closed shapes); directions point away from the surface. Conventions:
//   f(wo, wi)       BSDF value without the cosine; 0 for delta lobes.
//   sample(...)     draws wi given wo from one lobe-choice number uc and a 2D point u; returns f, wi, pdf
//                   (solid-angle measure, density of the whole BSDF's sampling at wi, not of the chosen lobe).
//                   For delta lobes, pdf is the discrete probability of that lobe and f includes 1/|cos wi|, so
//                   f |cos| / pdf is the usual weight.
//   pdf(wo, wi)     solid-angle density of sample(); 0 for delta lobes.
// Reflection-only materials (diffuse, conductor, plastic, mirror) are two-sided: they mirror wo into the upper
// hemisphere. The dielectric is one interface: outside is where the normal points.
#pragma once

#include "core/geometry.h"
#include "sampling/warps.h"

#include <string>

namespace stipple::render {

// How light flows along the path being built (BDPT's adjoint needs this at refractions).
enum class TransportMode { Radiance, Importance };

enum BsdfFlags : uint32_t {
    kBsdfReflection = 1,
    kBsdfTransmission = 2,
    kBsdfDiffuse = 4,
    kBsdfGlossy = 8,
    kBsdfSpecular = 16, // a delta lobe
};

struct BsdfSample {
    Spectrum f;
    Vec3 wi;
    float pdf = 0;
    uint32_t flags = 0;
    float eta = 1; // relative IOR crossed (transmission only)
    bool isSpecular() const { return flags & kBsdfSpecular; }
    bool isTransmission() const { return flags & kBsdfTransmission; }
};

enum class MaterialType { Diffuse, Conductor, Plastic, Mirror, Dielectric };

struct Material {
    MaterialType type = MaterialType::Diffuse;
    Spectrum albedo{0.5f};           // diffuse: albedo; plastic: the diffuse base; mirror: reflectance
    float roughness = 0.1f;          // GGX alpha, conductor and plastic, in [0.001, 1]
    float ior = 1.5f;                // plastic coat and dielectric
    Spectrum eta{0.2f, 0.92f, 1.1f}; // conductor
    Spectrum k{3.9f, 2.45f, 2.14f};  // conductor

    Spectrum f(Vec3 wo, Vec3 wi, TransportMode mode = TransportMode::Radiance) const;
    bool sample(Vec3 wo, float uc, Point2 u, BsdfSample& out, TransportMode mode = TransportMode::Radiance) const;
    float pdf(Vec3 wo, Vec3 wi) const;

    // Whether sample() reads its lobe-choice number uc (the integrator then declares a "bsdf.lobe" dimension).
    bool usesLobeChoice() const { return type == MaterialType::Plastic || type == MaterialType::Dielectric; }
    // Only delta lobes: light sampling cannot help (NEE is skipped).
    bool isSpecular() const { return type == MaterialType::Mirror || type == MaterialType::Dielectric; }
    // Probability that the plastic samples its coat, given wo (documented choice: Fresnel weight against the
    // diffuse albedo, clamped to [0.05, 0.95] so neither lobe starves).
    float plasticCoatProbability(float cosThetaO) const;
};

} // namespace stipple::render
