// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Unidirectional path tracing with next-event estimation and MIS (power heuristic, one light sample and one
// BSDF sample per vertex), as pbrt-v4's PathIntegrator.
//
// Dimensions, per bounce b < maxDepth (b = 0 is the first surface hit), only those this scene uses:
//   bB.light.choice 1D  — when the scene has more than one light (choice by power)
//   bB.light.pos    2D  — when it has lights and a non-specular material
//   bB.bsdf.lobe    1D  — when some material has two lobes (plastic, dielectric)
//   bB.bsdf.dir     2D
//   bB.rr           1D  — Russian roulette, from bounce kRouletteStart on: continue with probability
//                         min(1, max throughput component), at least 5%; survivors are divided by it (unbiased).
// Nothing is asked past maxDepth.
#include "integrators/integrator_registry.h"

namespace stipple::render {

namespace {

constexpr int kRouletteStart = 3;

class PathIntegrator final : public Integrator {
public:
    PathIntegrator(const RenderScene& scene, const IntegratorSettings& s) : scene_(scene), maxDepth_(s.maxDepth) {}
    const char* name() const override { return "path"; }

    void declareDimensions(SampleLayout& layout) override {
        size_t nLights = scene_.lights().size();
        bool lobe = scene_.anyMaterialUsesLobeChoice();
        bool nee = nLights > 0 && scene_.anyNonSpecularMaterial();
        dims_.assign(size_t(std::max(0, maxDepth_)), BounceDims{});
        for (int b = 0; b < maxDepth_; ++b) {
            std::string p = "b" + std::to_string(b) + ".";
            BounceDims& d = dims_[size_t(b)];
            if (nee && nLights > 1) d.lightChoice = layout.add(p + "light.choice", 1);
            if (nee) d.lightPos = layout.add(p + "light.pos", 2);
            if (lobe) d.lobe = layout.add(p + "bsdf.lobe", 1);
            d.dir = layout.add(p + "bsdf.dir", 2);
            if (b >= kRouletteStart) d.rr = layout.add(p + "rr", 1);
        }
    }

    Spectrum Li(const Ray& cameraRay, const TracedHit& first, const SampleView& sv, TileContext& tile) const override {
        Spectrum L, beta(1.0f);
        Ray ray = cameraRay;
        bool specularBounce = false;
        float prevPdf = 0;
        Vec3 prevP;
        if (!first.found) return L;
        SurfaceHit hit = first.hit;
        for (int depth = 0;; ++depth) {
            if (depth > 0) {
                ++tile.rays;
                if (!scene_.intersect(ray, hit)) break;
            }
            if (hit.light >= 0) {
                const Light& light = scene_.lights()[size_t(hit.light)];
                Spectrum Le = light.L(hit.ng, -ray.d);
                if (!Le.isBlack()) {
                    if (depth == 0 || specularBounce) {
                        L += beta * Le;
                    } else {
                        float pdfLight = scene_.lightChoicePmf(hit.light) * light.pdfLi(prevP, hit.p, hit.ng);
                        L += beta * Le * powerHeuristic(prevPdf, pdfLight);
                    }
                }
            }
            if (depth >= maxDepth_) break;
            const BounceDims& d = dims_[size_t(depth)];
            const Material& m = *hit.material;
            Frame frame(hit.ng);
            Vec3 wo = frame.toLocal(-ray.d);

            if (!m.isSpecular() && !scene_.lights().empty()) L += beta * sampleLight(hit, frame, wo, sv, d, tile);

            BsdfSample bs;
            if (!m.sample(wo, sv.get1D(d.lobe), sv.get2D(d.dir), bs)) break;
            beta *= bs.f * (std::abs(bs.wi.z) / bs.pdf);
            if (beta.isBlack()) break;
            specularBounce = bs.isSpecular();
            prevPdf = bs.pdf;
            prevP = hit.p;
            Vec3 wi = frame.toWorld(bs.wi);
            ray = Ray{offsetRayOrigin(hit.p, hit.ng, wi), wi};

            if (d.rr >= 0) {
                float q = std::max(0.05f, std::min(1.0f, beta.maxComponent()));
                if (sv.get1D(d.rr) >= q) break;
                beta *= 1 / q;
            }
        }
        return L;
    }

private:
    struct BounceDims {
        int lightChoice = -1, lightPos = -1, lobe = -1, dir = -1, rr = -1;
    };

    Spectrum sampleLight(const SurfaceHit& hit, const Frame& frame, const Vec3& wo, const SampleView& sv,
                         const BounceDims& d, TileContext& tile) const {
        float pmf = 1;
        size_t li = scene_.lights().size() == 1 ? 0 : scene_.lightChoice().sample(sv.get1D(d.lightChoice), &pmf);
        if (scene_.lights().size() == 1) pmf = 1;
        LightLiSample ls;
        if (!scene_.lights()[li].sampleLi(hit.p, sv.get2D(d.lightPos), ls)) return {};
        Vec3 wi = frame.toLocal(ls.wi);
        Spectrum f = hit.material->f(wo, wi) * std::abs(wi.z);
        if (f.isBlack()) return {};
        ++tile.rays;
        if (scene_.occludedBetween(hit.p, hit.ng, ls.p)) return {};
        float pdfLight = pmf * ls.pdf;
        float w = powerHeuristic(pdfLight, hit.material->pdf(wo, wi));
        return f * ls.L * (w / pdfLight);
    }

    const RenderScene& scene_;
    int maxDepth_;
    std::vector<BounceDims> dims_;
};

} // namespace

std::unique_ptr<Integrator> makePathIntegrator(const RenderScene& scene, const IntegratorSettings& settings) {
    return std::make_unique<PathIntegrator>(scene, settings);
}

} // namespace stipple::render
