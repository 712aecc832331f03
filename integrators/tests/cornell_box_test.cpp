// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The Cornell box renders with the path tracer: finite, lit, the expected wall colours, the layout it declares,
// and an EXR/PNG round trip with metadata.
#define BOOST_TEST_MODULE cornell_box
#include <algorithm>
#include <thread>
#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>

using namespace stipple::render;
using namespace stipple::render::test;

BOOST_AUTO_TEST_CASE(renders_and_writes) {
    auto scene = Scene::load(scenePath("cornell-box.yaml"));
    BOOST_TEST(scene->name() == "cornell-box");
    BOOST_TEST(scene->defaultIntegrator() == "path");
    BOOST_TEST(scene->triangleCount() == 36u);
    BOOST_TEST(scene->contentHash().size() == 16u);
    RenderOptions o;
    o.spp = 8;
    o.width = 48;
    o.height = 48;
    RenderResult r = scene->render(o);
    BOOST_TEST(r.nonFiniteSamples == 0u);
    BOOST_TEST(r.raysTraced > uint64_t(48 * 48 * 8));
    BOOST_TEST(r.renderSeconds > 0.0);
    BOOST_TEST(r.samplerSeconds > 0.0);
    BOOST_TEST(r.samplerSeconds < r.renderSeconds);
    // The workers' CPU time: positive, and no more than every thread busy for the whole render (+1 ms of clock
    // granularity per tile).
    const int threads = int(std::thread::hardware_concurrency());
    BOOST_TEST(r.cpuSeconds > 0.0);
    BOOST_TEST(r.cpuSeconds <= r.renderSeconds * std::max(threads, 1) + 0.001 * 9);
    // One light: no light choice is declared; the pinhole declares no lens.
    BOOST_TEST(r.layout.find("0 pixel 2D x1\n1 b0.light.pos 2D x1\n2 b0.bsdf.dir 2D x1\n") == 0u);
    BOOST_TEST(r.layout.find("light.choice") == std::string::npos);
    BOOST_TEST(r.layout.find("lens") == std::string::npos);
    BOOST_TEST(r.layout.find("b7.bsdf.dir") != std::string::npos);
    BOOST_TEST(r.layout.find("b8.") == std::string::npos);
    BOOST_TEST(r.layout == scene->describeLayout(o));

    // Left wall red, right wall green (columns 2 and 45, middle rows).
    double redL = 0, greenL = 0, redR = 0, greenR = 0;
    for (int y = 16; y < 32; ++y) {
        redL += r.image.pixel(1, y)[0];
        greenL += r.image.pixel(1, y)[1];
        redR += r.image.pixel(46, y)[0];
        greenR += r.image.pixel(46, y)[1];
    }
    BOOST_TEST(redL > 2 * greenL);
    BOOST_TEST(greenR > 1.5 * redR);
    ImageEstimate e = estimate(r);
    // A 256^2, 64 spp stratified render of this file averages 0.120 over channels; wide margins at 8 spp.
    BOOST_TEST(e.mean > 0.08);
    BOOST_TEST(e.mean < 0.16);

    std::string exr = writeTempFile("cornell.exr", "");
    writeExr(exr, r.image, {{"scene", "cornell-box"}, {"spp", "8"}});
    Image back = readImage(exr);
    BOOST_TEST(back.width == 48);
    BOOST_TEST(back.rgb == r.image.rgb);
    auto in = OIIO::ImageInput::open(exr);
    BOOST_REQUIRE(in);
    BOOST_TEST(in->spec().get_string_attribute("stipple:scene") == "cornell-box");
    std::string png = writeTempFile("cornell.png", "");
    writePng(png, r.image, 1.0f);
    Image pngBack = readImage(png);
    BOOST_TEST(pngBack.width == 48);
}

BOOST_AUTO_TEST_CASE(settings_are_resolved_once) {
    // Every "scene default" is filled in by Scene::resolve, and a render returns what it used.
    auto scene = Scene::load(scenePath("cornell-box.yaml"));
    RenderOptions o;
    const RenderOptions r = scene->resolve(o);
    BOOST_TEST(r.integrator == "path");
    BOOST_TEST(r.maxDepth == 8);
    BOOST_TEST(r.width == 256);
    BOOST_TEST(r.height == 256);
    BOOST_TEST(r.spp == 64u);
    o.width = 8;
    o.height = 4;
    o.spp = 2;
    o.maxDepth = 3;
    const RenderResult result = scene->render(o);
    BOOST_TEST(result.settings.maxDepth == 3);
    BOOST_TEST(result.settings.width == 8);
    BOOST_TEST(result.settings.spp == 2u);
    BOOST_TEST(result.settings.integrator == "path");
}

BOOST_AUTO_TEST_CASE(exr_metadata_vocabulary) {
    // Keys are written once under "stipple:" (never twice), with the standard Software and chromaticities.
    Image im;
    im.width = 2;
    im.height = 1;
    im.rgb = {0.5f, 0.25f, 1, 0, 0, 0};
    std::string exr = writeTempFile("meta.exr", "");
    writeExr(exr, im, {{"scene", "cornell-box"}, {"content_hash", "0123456789abcdef"}, {"spp", "8"}});
    const ImageMetadata back = readExrMetadata(exr);
    const ImageMetadata expected = {{"scene", "cornell-box"}, {"content_hash", "0123456789abcdef"}, {"spp", "8"}};
    for (const auto& kv : expected) BOOST_TEST((std::find(back.begin(), back.end(), kv) != back.end()), kv.first);
    for (const auto& [key, value] : back) BOOST_TEST(key.find(':') == std::string::npos, key);
    auto in = OIIO::ImageInput::open(exr);
    BOOST_REQUIRE(in);
    BOOST_TEST(in->spec().get_string_attribute("Software") == std::string(rendererVersion()));
    const OIIO::ParamValue* chroma = in->spec().find_attribute("chromaticities");
    BOOST_REQUIRE(chroma);
    BOOST_TEST(chroma->type().numelements() * chroma->type().aggregate == 8u);
    BOOST_TEST(in->spec().find_attribute("stipple:stipple:scene") == nullptr);
    // A key that already carries a prefix is a caller's mistake, named in the error.
    BOOST_CHECK_THROW(writeExr(exr, im, {{"stipple:scene", "x"}}), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(srgb_preview_curve) {
    // 0.18 scene-linear -> sRGB 1.055 * 0.18^(1/2.4) - 0.055 = 0.4614, 1 -> 1, 0 -> 0.
    Image im;
    im.width = 3;
    im.height = 1;
    im.rgb = {0.18f, 0.18f, 0.18f, 1, 1, 1, 0, 0, 0};
    std::string png = writeTempFile("curve.png", "");
    writePng(png, im);
    Image back = readImage(png);
    BOOST_TEST(std::abs(back.rgb[0] - 0.4614f) < 1.0f / 255);
    BOOST_TEST(back.rgb[3] == 1.0f);
    BOOST_TEST(back.rgb[6] == 0.0f);
}
