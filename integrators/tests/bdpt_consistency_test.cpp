// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Exact (non-statistical) checks of BDPT's bookkeeping on subpaths drawn by the real walks, for a diffuse
// Cornell box, the glossy two-light scene and the box with glass and mirror spheres:
//  - every density a walk stores (pdfFwd from its own end, pdfRev from the other) equals what PathEvaluator
//    computes afresh from the vertex positions (relative 1e-3; the walk uses sampled directions, the evaluator
//    directions rebuilt from positions, so a few grazing configurations may differ more: at most 0.2% of them);
//  - for full paths made by joining a light prefix and a camera prefix, the MIS weights of every strategy that
//    could have sampled the path sum to 1 (relative 1e-4), with each split's subpaths rebuilt as its walks would
//    have stored them. This is what makes BDPT unbiased; a statistical test sees only large violations.
#define BOOST_TEST_MODULE bdpt_consistency
#include <boost/test/unit_test.hpp>

#include "integrators/bdpt/bdpt_mis.h"
#include "integrators/bdpt/bdpt_subpath.h"
#include "sampling/pixel_sampler.h"
#include "scene/scene_loader.h"
#include "test_support.h"

#include <optional>

using namespace stipple::render;
using namespace stipple::render::bdpt;
using namespace stipple::render::test;

namespace {

constexpr int kDepth = 5;

struct Fixture {
    explicit Fixture(const std::string& file)
        : scene(loadSceneDescription(scenePath(file))), camera(scene.description().camera, 24, 24), eval(scene, camera),
          mis(eval), gen(scene, camera, kDepth) {
        layout.add("pixel", 2);
        if (camera.isThinLens()) layout.add("lens", 2);
        gen.declareDimensions(layout, true);
    }
    // Calls f(cameraSubpath, lightSubpath) for spp samples of a few pixels.
    template <class F>
    void forSubpaths(uint32_t spp, F&& f) {
        PixelSampler sampler(ShimLibrary::get(), "independent", spp, 3, layout);
        PixelSamples ps(sampler);
        TileContext tile;
        std::vector<PathVertex> cam, light;
        for (int y = 2; y < 24; y += 5)
            for (int x = 1; x < 24; x += 5) {
                sampler.startPixel(uint32_t(x), uint32_t(y), ps);
                for (uint32_t i = 0; i < spp; ++i) {
                    SampleView sv(ps, i);
                    Point2 u = sv.get2D(0);
                    Point2 lens = camera.isThinLens() ? sv.get2D(1) : Point2{0.5f, 0.5f};
                    const Ray ray = camera.generateRay({float(x) + u.x, float(y) + u.y}, lens);
                    TracedHit first; // the camera ray's hit, as the render loop passes it
                    first.found = scene.intersect(ray, first.hit);
                    gen.cameraSubpath(ray, first, sv, tile, cam);
                    gen.lightSubpath(sv, tile, light);
                    f(cam, light);
                }
            }
    }

    RenderScene scene;
    Camera camera;
    PathEvaluator eval;
    MisWeights mis;
    SubpathGenerator gen;
    SampleLayout layout;
};

bool close(double a, double b, double rel) { return std::abs(a - b) <= rel * std::max(std::abs(a), std::abs(b)); }

void checkStoredDensities(const std::string& file, uint32_t spp) {
    Fixture fx(file);
    long checked = 0, off = 0;
    auto check = [&](const std::vector<PathVertex>& p, bool lightPath) {
        if (p.empty()) return;
        if (lightPath) {
            ++checked;
            if (!close(p[0].pdfFwd, fx.eval.pdfLightOrigin(p[0]), 1e-5)) ++off;
        }
        for (size_t i = 1; i < p.size(); ++i) {
            ++checked;
            if (!close(p[i].pdfFwd, fx.eval.pdf(i >= 2 ? &p[i - 2] : nullptr, p[i - 1], p[i]), 1e-3)) ++off;
            if (i + 2 < p.size()) {
                ++checked;
                if (!close(p[i].pdfRev, fx.eval.pdf(&p[i + 2], p[i + 1], p[i]), 1e-3)) ++off;
            }
        }
    };
    fx.forSubpaths(spp, [&](const std::vector<PathVertex>& cam, const std::vector<PathVertex>& light) {
        check(cam, false);
        check(light, true);
    });
    BOOST_TEST_MESSAGE(file << ": " << checked << " densities, " << off << " off by more than 1e-3");
    BOOST_TEST(checked > 1000);
    BOOST_TEST(off <= checked / 500, file << ": " << off << " of " << checked << " stored densities disagree");
}

// The subpaths a split at s' of the full path x would have produced, densities rebuilt by the evaluator.
void split(const PathEvaluator& eval, const std::vector<PathVertex>& x, int sp, std::vector<PathVertex>& light,
           std::vector<PathVertex>& cam) {
    const int n = int(x.size());
    light.assign(x.begin(), x.begin() + sp);
    cam.assign(x.rbegin(), x.rbegin() + (n - sp));
    for (std::vector<PathVertex>* p : {&light, &cam}) {
        std::vector<PathVertex>& v = *p;
        for (size_t i = 0; i < v.size(); ++i) {
            if (v[i].kind == VertexKind::Surface) v[i].follow(v[i - 1]); // a Surface vertex is never first
            v[i].pdfFwd = i == 0 ? (p == &light ? eval.pdfLightOrigin(v[0]) : 0.0f)
                                 : eval.pdf(i >= 2 ? &v[i - 2] : nullptr, v[i - 1], v[i]);
            v[i].pdfRev = i + 2 < v.size() ? eval.pdf(&v[i + 2], v[i + 1], v[i]) : 0.0f;
        }
    }
}

void checkWeightsSumToOne(const std::string& file, uint32_t spp) {
    Fixture fx(file);
    long paths = 0, bad = 0;
    double worst = 0;
    std::vector<PathVertex> x, light, cam;
    fx.forSubpaths(spp, [&](const std::vector<PathVertex>& camPath, const std::vector<PathVertex>& lightPath) {
        // Every join of a light prefix (s >= 1) and a camera prefix (t >= 1) of depth <= kDepth is a full path.
        for (int s = 1; s <= int(lightPath.size()); ++s)
            for (int t = 1; t <= int(camPath.size()) && s + t - 2 <= kDepth; ++t) {
                x.assign(lightPath.begin(), lightPath.begin() + s);
                for (int j = t - 1; j >= 0; --j) x.push_back(camPath[size_t(j)]);
                const int n = s + t;
                double sum = 0;
                for (int sp = 0; sp < n; ++sp) {
                    if (sp >= 1 && (x[size_t(sp - 1)].delta || x[size_t(sp)].delta)) continue;
                    split(fx.eval, x, sp, light, cam);
                    ConnectionVertices fresh;
                    if (sp == 1) fresh.freshLight = &light[0];
                    if (n - sp == 1) fresh.freshCamera = &cam[0];
                    std::optional<Link> link;
                    if (sp >= 1) fresh.link = &link.emplace(light.back(), cam.back());
                    sum += fx.mis.weight(light, cam, sp, n - sp, fresh);
                }
                ++paths;
                worst = std::max(worst, std::abs(sum - 1));
                if (!(std::abs(sum - 1) <= 1e-4)) ++bad;
            }
    });
    BOOST_TEST_MESSAGE(file << ": " << paths << " paths, worst |sum of weights - 1| = " << worst);
    BOOST_TEST(paths > 500);
    BOOST_TEST(bad == 0, file << ": " << bad << " of " << paths << " paths have weights not summing to 1 (worst "
                              << worst << ")");
}

} // namespace

BOOST_AUTO_TEST_CASE(stored_densities_cornell_box) { checkStoredDensities("cornell-box.yaml", 8); }
BOOST_AUTO_TEST_CASE(stored_densities_glossy) { checkStoredDensities("glossy-lights.yaml", 32); }
BOOST_AUTO_TEST_CASE(stored_densities_glass) { checkStoredDensities("bdpt-glass-box.yaml", 8); }
BOOST_AUTO_TEST_CASE(weights_sum_to_one_cornell_box) { checkWeightsSumToOne("cornell-box.yaml", 4); }
BOOST_AUTO_TEST_CASE(weights_sum_to_one_glossy) { checkWeightsSumToOne("glossy-lights.yaml", 16); }
BOOST_AUTO_TEST_CASE(weights_sum_to_one_glass) { checkWeightsSumToOne("bdpt-glass-box.yaml", 4); }
BOOST_AUTO_TEST_CASE(weights_sum_to_one_thin_lens) { checkWeightsSumToOne("bdpt-furnace-thinlens.yaml", 4); }

// Veach's adjoint factor |wo.ns| |wi.ng| / (|wo.ng| |wi.ns|): 1 without shading normals, the closed form with.
BOOST_AUTO_TEST_CASE(shading_normal_correction) {
    Vec3 ng(0, 0, 1), wo = normalize(Vec3(1, 0, 1)), wi = normalize(Vec3(-1, 0.5f, 2));
    BOOST_TEST(shadingNormalCorrection(ng, ng, wo, wi) == 1.0f, boost::test_tools::tolerance(1e-6f));
    Vec3 ns = normalize(Vec3(0.2f, 0, 1));
    float expected = absDot(wo, ns) * absDot(wi, ng) / (absDot(wo, ng) * absDot(wi, ns));
    BOOST_TEST(shadingNormalCorrection(ns, ng, wo, wi) == expected, boost::test_tools::tolerance(1e-6f));
    BOOST_TEST(expected != 1.0f);
    BOOST_TEST(shadingNormalCorrection(ns, ng, Vec3(1, 0, 0), wi) == 0.0f); // grazing on the true surface
}
