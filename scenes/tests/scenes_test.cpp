// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The four study scenes through the renderer API: each loads, declares only the sample dimensions it uses,
// and renders a tiny image with no non-finite samples and a plausible (positive, finite) mean.
#define BOOST_TEST_MODULE scenes
#include <boost/test/unit_test.hpp>

#include <stipple/render/renderer.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using stipple::render::RenderOptions;
using stipple::render::RenderResult;
using stipple::render::Scene;

namespace {

std::string scenePath(const std::string& name) { return std::string(STIPPLE_SCENES_DIR) + "/" + name + ".yaml"; }

std::vector<std::string> layoutNames(const Scene& scene, const RenderOptions& options) {
    // one line per dimension: "<index> <name> <arity>D x<count>"
    std::istringstream in(scene.describeLayout(options));
    std::vector<std::string> names;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        std::string index, name;
        if (fields >> index >> name) names.push_back(name);
    }
    return names;
}

bool has(const std::vector<std::string>& names, const std::string& needle) {
    for (const auto& n : names)
        if (n.find(needle) != std::string::npos) return true;
    return false;
}

double meanOf(const RenderResult& r) {
    double sum = 0;
    for (float v : r.image.rgb) sum += v;
    return r.image.rgb.empty() ? 0 : sum / double(r.image.rgb.size());
}

// Renders `name` at a tiny size with its own integrator and checks the result.
void tinyRender(const std::string& name, int width, int height, double minMean, double maxMean) {
    auto scene = Scene::load(scenePath(name));
    BOOST_TEST(scene->name() == name);
    BOOST_TEST_MESSAGE(name << ": load " << scene->loadSeconds() << " s, BVH build " << scene->buildSeconds() << " s, "
                            << scene->triangleCount() << " triangles");
    RenderOptions o;
    o.width = width;
    o.height = height;
    o.spp = 4;
    o.seed = 11;
    RenderResult r = scene->render(o);
    BOOST_TEST(r.image.width == width);
    BOOST_TEST(r.image.height == height);
    BOOST_TEST(r.nonFiniteSamples == 0u);
    double mean = meanOf(r);
    BOOST_TEST_MESSAGE(name << ": " << width << "x" << height << " at 4 spp in " << r.renderSeconds
                            << " s, mean radiance " << mean);
    BOOST_TEST(std::isfinite(mean));
    BOOST_TEST(mean > minMean);
    BOOST_TEST(mean < maxMean);
}

} // namespace

// Each scene asks only for what it uses: the lens only in italian-city; the direct integrator nothing past
// the first hit; a single light needs no light choice; BDPT subpaths end at the scene's max depth.
// (Each scene is loaded once: the city takes seconds.)
BOOST_AUTO_TEST_CASE(layout) {
    RenderOptions o;
    struct Expect {
        const char* scene;
        const char* integrator;
        bool lens;
    };
    for (const Expect& e : {Expect{"cornell-box", "path", false}, Expect{"veach-mis", "direct", false},
                            Expect{"veach-bidir", "bdpt", false}, Expect{"italian-city", "bdpt", true}}) {
        BOOST_TEST_CONTEXT(e.scene) {
            const std::string name = e.scene;
            auto scene = Scene::load(scenePath(name));
            BOOST_TEST(scene->defaultIntegrator() == e.integrator);
            auto names = layoutNames(*scene, o);
            BOOST_TEST_MESSAGE(name << " layout:\n" << scene->describeLayout(o));
            BOOST_TEST(!names.empty());
            BOOST_TEST(has(names, "pixel"));
            BOOST_TEST(has(names, "lens") == e.lens);
            if (name == "cornell-box") {
                BOOST_TEST(!has(names, "light.choice")); // one light
                BOOST_TEST(!has(names, "bsdf.lobe"));    // Lambertian only
                BOOST_TEST(has(names, "b7."));           // max depth 8: bounces 0..7
                BOOST_TEST(!has(names, "b8."));
            } else if (name == "veach-mis") {
                BOOST_TEST(has(names, "b0.light.pos"));
                BOOST_TEST(has(names, "b0.bsdf.dir"));
                BOOST_TEST(has(names, "b0.light.choice")); // five lights
                BOOST_TEST(!has(names, "b1."));            // no path continuation
                BOOST_TEST(!has(names, ".rr"));
            } else {
                const int depth = name == "veach-bidir" ? 7 : 5;
                BOOST_TEST(has(names, "cam.b" + std::to_string(depth - 1) + "."));
                BOOST_TEST(!has(names, "cam.b" + std::to_string(depth) + "."));
                BOOST_TEST(has(names, "light.pos"));
            }
        }
    }
}

BOOST_AUTO_TEST_CASE(cornell_box) { tinyRender("cornell-box", 32, 32, 0.05, 5.0); }
BOOST_AUTO_TEST_CASE(veach_mis) { tinyRender("veach-mis", 48, 32, 0.005, 5.0); }
BOOST_AUTO_TEST_CASE(veach_bidir) { tinyRender("veach-bidir", 32, 32, 0.01, 50.0); }

BOOST_AUTO_TEST_CASE(italian_city) {
    auto scene = Scene::load(scenePath("italian-city"));
    std::cout << "italian-city: " << scene->triangleCount() << " triangles after instancing, BVH build "
              << scene->buildSeconds() << " s, load " << scene->loadSeconds() << " s" << std::endl;
    BOOST_TEST(scene->triangleCount() >= 1000000u);
    RenderOptions o;
    o.width = 48;
    o.height = 32;
    o.spp = 4;
    o.seed = 11;
    RenderResult r = scene->render(o);
    BOOST_TEST(r.nonFiniteSamples == 0u);
    double mean = meanOf(r);
    std::cout << "italian-city: 48x32 at 4 spp in " << r.renderSeconds << " s, mean radiance " << mean << std::endl;
    BOOST_TEST(std::isfinite(mean));
    BOOST_TEST(mean > 0.01);
    BOOST_TEST(mean < 50.0);
}
