// BDPT images are bitwise identical for 1 and 2 threads: camera and light subpaths read only the pixel sample's
// shim values, and light-tracing splats go to the tile's own list, merged in tile order after the render.
#define BOOST_TEST_MODULE bdpt_determinism
#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <cstring>

using namespace stipple::render;
using namespace stipple::render::test;

namespace {
void checkIdentical(const std::string& file, const std::string& pattern) {
    auto s = Scene::load(scenePath(file));
    RenderOptions o;
    o.integrator = "bdpt";
    o.pattern = pattern;
    o.spp = 4;
    o.width = 40; // not a multiple of the tile size: partial tiles too
    o.height = 24;
    o.seed = 9;
    o.threads = 1;
    RenderResult a = s->render(o);
    o.threads = 2;
    RenderResult b = s->render(o);
    BOOST_REQUIRE_EQUAL(a.image.rgb.size(), b.image.rgb.size());
    BOOST_TEST(std::memcmp(a.image.rgb.data(), b.image.rgb.data(), a.image.rgb.size() * sizeof(float)) == 0,
               file << " " << pattern << ": images differ");
    BOOST_TEST(std::memcmp(a.variance.rgb.data(), b.variance.rgb.data(), a.variance.rgb.size() * sizeof(float)) == 0);
    BOOST_TEST(a.raysTraced == b.raysTraced);
    BOOST_TEST(a.raysTraced > 0u);
}
} // namespace

BOOST_AUTO_TEST_CASE(cornell_box_stratified) { checkIdentical("cornell-box.yaml", "stratified"); }
BOOST_AUTO_TEST_CASE(glass_box_independent) { checkIdentical("bdpt-glass-box.yaml", "independent"); }
BOOST_AUTO_TEST_CASE(thin_lens_furnace_poisson) { checkIdentical("bdpt-furnace-thinlens.yaml", "poisson"); }
