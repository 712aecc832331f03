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
        Spectrum L;
        LiPacket(&ray, &first, sv.pixel(), sv.sampleIndex(), 1, tile, &L);
        return L;
    }

    // A pixel's samples go through each technique together: their shadow rays (toward the lights) and BSDF rays
    // leave one small patch of surface, so each technique's rays are traced as one packet. Every sample's
    // arithmetic and the order of its terms are Li's for that sample alone.
    void LiPacket(const Ray* rays, const TracedHit* firsts, const PixelSamples& samples, uint32_t firstSample,
                  int count, TileContext& tile, Spectrum* L) const override {
        constexpr int P = RenderScene::kPacketSize;
        Frame frames[P];
        Vec3 wo[P];
        bool shaded[P];
        for (int k = 0; k < count; ++k) {
            L[k] = Spectrum();
            shaded[k] = false;
            if (!firsts[k].found) continue;
            const SurfaceHit& hit = firsts[k].hit;
            if (hit.light >= 0) L[k] += scene_.lights()[size_t(hit.light)].L(hit.ng, -rays[k].d);
            if (maxDepth_ < 1) continue;
            shaded[k] = true;
            frames[k] = Frame(hit.ng);
            wo[k] = frames[k].toLocal(-rays[k].d);
        }
        const float invK = 1.0f / float(k_);
        Ray next[P];
        int lane[P];
        Spectrum term[P];
        // Light sampling; specular surfaces are left to BSDF sampling (a light sample cannot hit a delta lobe).
        for (uint32_t j = 0; j < k_ && lightPos_ >= 0; ++j) {
            int n = 0;
            for (int k = 0; k < count; ++k) {
                if (!shaded[k] || firsts[k].hit.material->isSpecular()) continue;
                const SurfaceHit& hit = firsts[k].hit;
                const Material& m = *hit.material;
                const SampleView sv(samples, firstSample + uint32_t(k));
                float pmf = 1;
                size_t li =
                    scene_.lights().size() == 1 ? 0 : scene_.lightChoice().sample(sv.get1D(lightChoice_, j), &pmf);
                LightLiSample ls;
                if (!scene_.lights()[li].sampleLi(hit.p, sv.get2D(lightPos_, j), ls)) continue;
                Vec3 wi = frames[k].toLocal(ls.wi);
                Spectrum f = m.f(wo[k], wi) * std::abs(wi.z);
                if (f.isBlack()) continue;
                ++tile.rays;
                float pdfLight = pmf * ls.pdf;
                float w = strategy_ == DirectStrategy::Mis ? powerHeuristic(pdfLight, m.pdf(wo[k], wi)) : 1.0f;
                Spectrum value = f * ls.L * (w * invK / pdfLight);
                if (!RenderScene::shadowRay(hit.p, hit.ng, ls.p, next[n])) {
                    L[k] += value; // nothing between coincident points
                    continue;
                }
                lane[n] = k;
                term[n++] = value;
            }
            bool blocked[P];
            scene_.occludedPacket(next, n, blocked);
            for (int i = 0; i < n; ++i)
                if (!blocked[i]) L[lane[i]] += term[i];
        }
        // BSDF sampling.
        BsdfSample bsdf[P];
        for (uint32_t j = 0; j < k_ && dir_ >= 0; ++j) {
            int n = 0;
            for (int k = 0; k < count; ++k) {
                if (!shaded[k]) continue;
                const SurfaceHit& hit = firsts[k].hit;
                const SampleView sv(samples, firstSample + uint32_t(k));
                BsdfSample& bs = bsdf[n];
                if (!hit.material->sample(wo[k], sv.get1D(lobe_, j), sv.get2D(dir_, j), bs)) continue;
                Vec3 wi = frames[k].toWorld(bs.wi);
                next[n] = Ray{offsetRayOrigin(hit.p, hit.ng, wi), wi};
                ++tile.rays;
                lane[n++] = k;
            }
            TracedHit found[P];
            scene_.intersectPacket(next, n, found);
            for (int i = 0; i < n; ++i) {
                const SurfaceHit& lightHit = found[i].hit;
                if (!found[i].found || lightHit.light < 0) continue;
                const SurfaceHit& hit = firsts[lane[i]].hit;
                const BsdfSample& bs = bsdf[i];
                const Light& light = scene_.lights()[size_t(lightHit.light)];
                Spectrum Le = light.L(lightHit.ng, -next[i].d);
                if (Le.isBlack()) continue;
                float w = 1;
                if (strategy_ == DirectStrategy::Mis && !bs.isSpecular() && lightPos_ >= 0) {
                    float pdfLight =
                        scene_.lightChoicePmf(lightHit.light) * light.pdfLi(hit.p, lightHit.p, lightHit.ng);
                    w = powerHeuristic(bs.pdf, pdfLight);
                }
                L[lane[i]] += bs.f * Le * (std::abs(bs.wi.z) * w * invK / bs.pdf);
            }
        }
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
