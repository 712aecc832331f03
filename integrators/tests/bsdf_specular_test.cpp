// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Delta lobes (mirror, smooth dielectric) cannot be chi-square tested: check their directions and weights.
// Also energy bounds of the rough materials (white furnace: albedo <= 1) from a stratified grid of inputs, and the
// conductor's Fresnel term against the complex form in double precision, stiff IORs and grazing angles included.
#define BOOST_TEST_MODULE bsdf_specular
#include <boost/test/unit_test.hpp>

#include "materials/material.h"
#include "materials/microfacet.h"

#include <complex>

using namespace stipple::render;

BOOST_AUTO_TEST_CASE(mirror_reflects_with_its_reflectance) {
    Material m;
    m.type = MaterialType::Mirror;
    m.albedo = Spectrum(0.9f, 0.8f, 0.7f);
    Vec3 wo = normalize(Vec3(0.3f, -0.2f, 0.8f));
    BsdfSample bs;
    BOOST_REQUIRE(m.sample(wo, 0.3f, {0.1f, 0.9f}, bs));
    BOOST_TEST(bs.isSpecular());
    BOOST_TEST(std::abs(bs.wi.x + wo.x) < 1e-6f);
    BOOST_TEST(std::abs(bs.wi.z - wo.z) < 1e-6f);
    Spectrum w = bs.f * (std::abs(bs.wi.z) / bs.pdf);
    BOOST_TEST(std::abs(w.g - 0.8f) < 1e-5f);
    BOOST_TEST(m.pdf(wo, bs.wi) == 0.0f);
    BOOST_TEST(m.f(wo, bs.wi).isBlack());
}

BOOST_AUTO_TEST_CASE(dielectric_splits_by_fresnel_and_scales_radiance) {
    Material m;
    m.type = MaterialType::Dielectric;
    m.ior = 1.5f;
    Vec3 wo = normalize(Vec3(0.5f, 0, 0.7f));
    float R = fresnelDielectric(wo.z, 1.5f);
    BsdfSample r, t, ti;
    BOOST_REQUIRE(m.sample(wo, R * 0.5f, {0.5f, 0.5f}, r));
    BOOST_REQUIRE(m.sample(wo, R + (1 - R) * 0.5f, {0.5f, 0.5f}, t));
    BOOST_TEST(!r.isTransmission());
    BOOST_TEST(t.isTransmission());
    BOOST_TEST(std::abs(r.pdf - R) < 1e-6f);
    BOOST_TEST(std::abs(t.pdf - (1 - R)) < 1e-6f);
    // Snell: sin_t = sin_i / 1.5.
    float sinI = std::sqrt(1 - wo.z * wo.z), sinT = std::sqrt(1 - t.wi.z * t.wi.z);
    BOOST_TEST(std::abs(sinT - sinI / 1.5f) < 1e-5f);
    BOOST_TEST(t.wi.z < 0);
    BOOST_TEST(std::abs(t.eta - 1.5f) < 1e-6f);
    // Weights: reflection 1, transmission 1/eta^2 for radiance, 1 for importance.
    BOOST_TEST(std::abs(r.f.r * std::abs(r.wi.z) / r.pdf - 1) < 1e-5f);
    BOOST_TEST(std::abs(t.f.r * std::abs(t.wi.z) / t.pdf - 1 / 2.25f) < 1e-5f);
    BOOST_REQUIRE(m.sample(wo, R + (1 - R) * 0.5f, {0.5f, 0.5f}, ti, TransportMode::Importance));
    BOOST_TEST(std::abs(ti.f.r * std::abs(ti.wi.z) / ti.pdf - 1) < 1e-5f);
    // From inside beyond the critical angle: total internal reflection only.
    Vec3 inside = normalize(Vec3(0.9f, 0, -0.3f));
    BsdfSample tir;
    BOOST_REQUIRE(m.sample(inside, 0.99f, {0.5f, 0.5f}, tir));
    BOOST_TEST(!tir.isTransmission());
    BOOST_TEST(tir.wi.z < 0);
}

BOOST_AUTO_TEST_CASE(rough_materials_do_not_create_energy) {
    // Albedo estimate by sampling on a 64x64 stratified grid (midpoints) with 4 lobe choices.
    for (float alpha : {0.001f, 0.05f, 0.3f, 1.0f}) {
        for (MaterialType type : {MaterialType::Conductor, MaterialType::Plastic}) {
            Material m;
            m.type = type;
            m.roughness = alpha;
            m.albedo = Spectrum(1.0f);
            m.eta = Spectrum(0.0f + 1e-3f); // eta ~ 0, k large: a near-perfect conductor
            m.k = Spectrum(1e4f);
            for (float ct : {0.95f, 0.5f, 0.1f}) {
                Vec3 wo(std::sqrt(1 - ct * ct), 0, ct);
                double sum = 0;
                const int n = 64;
                for (int l = 0; l < 4; ++l)
                    for (int i = 0; i < n; ++i)
                        for (int j = 0; j < n; ++j) {
                            BsdfSample bs;
                            if (!m.sample(wo, (l + 0.5f) / 4, {(i + 0.5f) / n, (j + 0.5f) / n}, bs)) continue;
                            sum += bs.f.average() * std::abs(bs.wi.z) / bs.pdf;
                        }
                double albedo = sum / (4.0 * n * n);
                BOOST_TEST(albedo <= 1.01,
                           "type " << int(type) << " alpha " << alpha << " cos " << ct << ": " << albedo);
                BOOST_TEST(albedo > 0.3);
            }
        }
    }
}


namespace {
// The textbook form: the refracted cosine through the complex IOR, both polarisations.
template <typename Real>
Real conductorFresnelComplex(Real cosThetaI, Real eta, Real k) {
    using C = std::complex<Real>;
    const C e(eta, k);
    const Real sin2i = 1 - cosThetaI * cosThetaI;
    const C cost = std::sqrt(C(1) - sin2i / (e * e));
    const C rParl = (e * cosThetaI - cost) / (e * cosThetaI + cost);
    const C rPerp = (cosThetaI - e * cost) / (cosThetaI + e * cost);
    return (std::norm(rParl) + std::norm(rPerp)) / 2;
}
} // namespace

// The renderer's real-valued form is as accurate as the complex form in float, measured against it in double:
// stiff IORs (eta from 0.05 to 10, k from 0 to 100) and grazing to normal incidence.
BOOST_AUTO_TEST_CASE(conductor_fresnel_is_as_accurate_as_the_complex_form) {
    const float cosines[] = {0.0f, 1e-6f, 1e-3f, 0.05f, 0.2f, 0.5f, 0.7071f, 0.9f, 0.999f, 1.0f};
    const float etas[] = {0.05f, 0.2f, 0.5f, 0.92f, 1.0f, 1.1f, 1.5f, 3.0f, 10.0f};
    const float ks[] = {0.0f, 1e-3f, 0.5f, 2.14f, 3.9f, 10.0f, 100.0f};
    for (float c : cosines)
        for (float eta : etas)
            for (float k : ks) {
                const float got = fresnelConductor(c, eta, k);
                const double exact = conductorFresnelComplex<double>(c, eta, k);
                const double complexFloatError = std::abs(double(conductorFresnelComplex<float>(c, eta, k)) - exact);
                BOOST_TEST_CONTEXT("cos " << c << " eta " << eta << " k " << k) {
                    BOOST_TEST(std::isfinite(got));
                    BOOST_TEST((got >= 0.0f && got <= 1.0f));
                    if (std::isfinite(exact)) // 0/0 at grazing incidence on a matched interface (eta 1, k 0)
                        BOOST_TEST(std::abs(double(got) - exact) <= complexFloatError + 1e-6);
                }
            }
}
