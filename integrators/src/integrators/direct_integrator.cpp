// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Direct illumination with multiple importance sampling (Veach's thesis ch. 9, the "MIS" scene): at the first
// surface hit, k light samples and k BSDF samples (k = light_samples), combined with the power heuristic. The
// diagnostic strategies "direct-light" and "direct-bsdf" use one technique alone (weight 1), so the three can
// be compared: all estimate the same image.
//
// Dimensions (b0 = the first hit; only those the scene uses, each with count k):
//   b0.light.choice 1D xk (more than one light), b0.light.pos 2D xk, b0.bsdf.lobe 1D xk, b0.bsdf.dir 2D xk.
// With max_depth 0 only emitters seen directly are counted and nothing is declared.
#include "integrators/integrator_registry.h"

namespace stipple::render {

namespace {

class DirectIntegrator final : public Integrator {
public:
    DirectIntegrator(const RenderScene& scene, const IntegratorSettings& s, DirectStrategy strategy)
        : scene_(scene), maxDepth_(s.maxDepth), k_(std::max(1u, s.lightSamples)), strategy_(strategy) {}
    const char* name() const override {
        return strategy_ == DirectStrategy::Mis
                   ? "direct"
                   : (strategy_ == DirectStrategy::LightOnly ? "direct-light" : "direct-bsdf");
    }

    void declareDimensions(SampleLayout& layout) override {
        if (maxDepth_ < 1) return;
        size_t nLights = scene_.lights().size();
        bool useLight = strategy_ != DirectStrategy::BsdfOnly && nLights > 0 && scene_.anyNonSpecularMaterial();
        bool useBsdf = strategy_ != DirectStrategy::LightOnly || !scene_.anyNonSpecularMaterial();
        if (useLight && nLights > 1) lightChoice_ = layout.add("b0.light.choice", 1, k_);
        if (useLight) lightPos_ = layout.add("b0.light.pos", 2, k_);
        if (useBsdf && scene_.anyMaterialUsesLobeChoice()) lobe_ = layout.add("b0.bsdf.lobe", 1, k_);
        if (useBsdf) dir_ = layout.add("b0.bsdf.dir", 2, k_);
    }

    Spectrum Li(const Ray& ray, const TracedHit& first, const SampleView& sv, TileContext& tile) const override {
        if (!first.found) return {};
        const SurfaceHit& hit = first.hit;
        Spectrum L;
        if (hit.light >= 0) L += scene_.lights()[size_t(hit.light)].L(hit.ng, -ray.d);
        if (maxDepth_ < 1) return L;
        const Material& m = *hit.material;
        Frame frame(hit.ng);
        Vec3 wo = frame.toLocal(-ray.d);
        float invK = 1.0f / float(k_);
        // Specular surfaces: light sampling cannot hit a delta lobe, so BSDF samples carry weight 1.
        bool lightTechnique = lightPos_ >= 0 && !m.isSpecular();
        bool bsdfTechnique = dir_ >= 0;
        for (uint32_t j = 0; j < k_ && lightTechnique; ++j) {
            float pmf = 1;
            size_t li = scene_.lights().size() == 1 ? 0 : scene_.lightChoice().sample(sv.get1D(lightChoice_, j), &pmf);
            LightLiSample ls;
            if (!scene_.lights()[li].sampleLi(hit.p, sv.get2D(lightPos_, j), ls)) continue;
            Vec3 wi = frame.toLocal(ls.wi);
            Spectrum f = m.f(wo, wi) * std::abs(wi.z);
            if (f.isBlack()) continue;
            ++tile.rays;
            if (scene_.occludedBetween(hit.p, hit.ng, ls.p)) continue;
            float pdfLight = pmf * ls.pdf;
            float w = strategy_ == DirectStrategy::Mis ? powerHeuristic(pdfLight, m.pdf(wo, wi)) : 1.0f;
            L += f * ls.L * (w * invK / pdfLight);
        }
        for (uint32_t j = 0; j < k_ && bsdfTechnique; ++j) {
            BsdfSample bs;
            if (!m.sample(wo, sv.get1D(lobe_, j), sv.get2D(dir_, j), bs)) continue;
            Vec3 wi = frame.toWorld(bs.wi);
            Ray r{offsetRayOrigin(hit.p, hit.ng, wi), wi};
            SurfaceHit lightHit;
            ++tile.rays;
            if (!scene_.intersect(r, lightHit) || lightHit.light < 0) continue;
            const Light& light = scene_.lights()[size_t(lightHit.light)];
            Spectrum Le = light.L(lightHit.ng, -wi);
            if (Le.isBlack()) continue;
            float w = 1;
            if (strategy_ == DirectStrategy::Mis && !bs.isSpecular() && lightPos_ >= 0) {
                float pdfLight = scene_.lightChoicePmf(lightHit.light) * light.pdfLi(hit.p, lightHit.p, lightHit.ng);
                w = powerHeuristic(bs.pdf, pdfLight);
            }
            L += bs.f * Le * (std::abs(bs.wi.z) * w * invK / bs.pdf);
        }
        return L;
    }

private:
    const RenderScene& scene_;
    int maxDepth_;
    uint32_t k_;
    DirectStrategy strategy_;
    int lightChoice_ = -1, lightPos_ = -1, lobe_ = -1, dir_ = -1;
};

} // namespace

std::unique_ptr<Integrator> makeDirectIntegrator(const RenderScene& scene, const IntegratorSettings& settings,
                                                 DirectStrategy strategy) {
    return std::make_unique<DirectIntegrator>(scene, settings, strategy);
}

} // namespace stipple::render
