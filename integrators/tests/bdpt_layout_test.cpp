// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// BDPT declares to the shim exactly the dimensions it reads (integrators/src/bdpt_integrator.cpp lists them), and
// its debug variants parse or fail with a message naming the expected forms.
#define BOOST_TEST_MODULE bdpt_layout
#include <boost/test/unit_test.hpp>

#include "integrators/bdpt/bdpt_integrator.h"
#include "test_support.h"

#include <sstream>

using namespace stipple::render;
using namespace stipple::render::test;

namespace {
std::string names(const std::string& file, int maxDepth) {
    auto scene = Scene::load(scenePath(file));
    RenderOptions o;
    o.integrator = "bdpt";
    o.maxDepth = maxDepth;
    std::string text = scene->describeLayout(o), out;
    // "<index> <name> <arity>D x<k>" per line -> "name/arity" joined by spaces.
    std::istringstream in(text);
    std::string index, name, arity, count;
    while (in >> index >> name >> arity >> count) out += (out.empty() ? "" : " ") + name + "/" + arity.substr(0, 1);
    return out;
}
} // namespace

BOOST_AUTO_TEST_CASE(cornell_box_one_light_diffuse_pinhole) {
    BOOST_TEST(names("cornell-box.yaml", 2) ==
               "pixel/2 cam.b0.bsdf.dir/2 cam.b1.bsdf.dir/2 light.pos/2 light.dir/2 light.b0.bsdf.dir/2 "
               "connect.s1.t2.light.pos/2 connect.s1.t3.light.pos/2");
}

BOOST_AUTO_TEST_CASE(max_depth_zero_needs_only_the_light_point) {
    BOOST_TEST(names("cornell-box.yaml", 0) == "pixel/2 light.pos/2");
}

BOOST_AUTO_TEST_CASE(two_lights_and_two_lobes) {
    BOOST_TEST(names("glossy-lights.yaml", 1) ==
               "pixel/2 cam.b0.bsdf.lobe/1 cam.b0.bsdf.dir/2 light.choice/1 light.pos/2 light.dir/2 "
               "connect.s1.t2.light.choice/1 connect.s1.t2.light.pos/2");
}

BOOST_AUTO_TEST_CASE(thin_lens_declares_lens_connections) {
    BOOST_TEST(names("bdpt-furnace-thinlens.yaml", 1) ==
               "pixel/2 lens/2 cam.b0.bsdf.dir/2 light.pos/2 light.dir/2 connect.s1.t2.light.pos/2 "
               "connect.t1.s1.lens/2 connect.t1.s2.lens/2");
}

BOOST_AUTO_TEST_CASE(scene_file_selects_bdpt) {
    auto scene = Scene::load(scenePath("bdpt-glass-box.yaml"));
    BOOST_TEST(scene->defaultIntegrator() == "bdpt");
    std::string layout = scene->describeLayout(RenderOptions{});
    BOOST_TEST(layout.find("cam.b0.bsdf.lobe") != std::string::npos, layout); // the dielectric has two lobes
    BOOST_TEST(layout.find("connect.s1.t2.light.pos") != std::string::npos, layout);
}

BOOST_AUTO_TEST_CASE(variants_parse) {
    bdpt::StrategyFilter f = bdpt::parseVariant("bdpt");
    BOOST_TEST((f.s == -1 && f.depth == -1 && f.weighted));
    f = bdpt::parseVariant("bdpt:s=2,t=3");
    BOOST_TEST((f.s == 2 && f.t == 3 && !f.weighted));
    BOOST_TEST(f.accepts(2, 3));
    BOOST_TEST(!f.accepts(1, 4));
    f = bdpt::parseVariant("bdpt:s=0,t=2,mis");
    BOOST_TEST((f.s == 0 && f.t == 2 && f.weighted));
    f = bdpt::parseVariant("bdpt:depth=3");
    BOOST_TEST((f.depth == 3 && f.accepts(1, 4) && !f.accepts(1, 3)));
}

BOOST_AUTO_TEST_CASE(bad_variants_name_the_expected_forms) {
    for (const char* bad : {"bdpt:", "bdpt:s=1", "bdpt:s=a,t=2", "bdpt:s=1,t=2,wis", "bdpt:depth=", "bdpt:t=1,s=1",
                            "bdpt:s=-1,t=2", "bdptx"}) {
        try {
            bdpt::parseVariant(bad);
            BOOST_ERROR("accepted " << bad);
        } catch (const std::invalid_argument& e) {
            BOOST_TEST(std::string(e.what()).find("bdpt:s=S,t=T") != std::string::npos, e.what());
        }
    }
    try {
        bdpt::parseVariant("bdpt:s=1,t=0");
        BOOST_ERROR("accepted t=0");
    } catch (const std::invalid_argument& e) {
        BOOST_TEST(std::string(e.what()).find("t must be >= 1") != std::string::npos, e.what());
    }
    auto scene = Scene::load(scenePath("cornell-box.yaml"));
    RenderOptions o;
    o.integrator = "bdpt:bogus";
    BOOST_CHECK_THROW(scene->render(o), std::invalid_argument);
}
