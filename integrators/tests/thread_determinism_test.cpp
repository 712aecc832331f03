// The image is bitwise identical for 1 and 2 threads (every value is a function of (seed, pixel, sample,
// dimension); tiles never share state; splats merge in tile order).
#define BOOST_TEST_MODULE thread_determinism
#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <cstring>

using namespace stipple::render;
using namespace stipple::render::test;

namespace {
void checkIdentical(const std::string& scene, const std::string& pattern, const std::string& integrator) {
    auto s = Scene::load(scenePath(scene));
    RenderOptions o;
    o.pattern = pattern;
    o.integrator = integrator;
    o.spp = 4;
    o.width = 40; // not a multiple of the tile size: partial tiles too
    o.height = 24;
    o.seed = 5;
    o.threads = 1;
    RenderResult a = s->render(o);
    o.threads = 2;
    RenderResult b = s->render(o);
    BOOST_REQUIRE_EQUAL(a.image.rgb.size(), b.image.rgb.size());
    BOOST_TEST(std::memcmp(a.image.rgb.data(), b.image.rgb.data(), a.image.rgb.size() * sizeof(float)) == 0,
               scene << " " << pattern << " " << integrator << ": images differ");
    BOOST_TEST(std::memcmp(a.variance.rgb.data(), b.variance.rgb.data(), a.variance.rgb.size() * sizeof(float)) == 0);
    BOOST_TEST(a.raysTraced == b.raysTraced);
}
} // namespace

BOOST_AUTO_TEST_CASE(path_cornell_box_one_vs_two_threads) { checkIdentical("cornell-box.yaml", "stratified", "path"); }
BOOST_AUTO_TEST_CASE(path_cornell_box_poisson_one_vs_two_threads) {
    checkIdentical("cornell-box.yaml", "poisson", "path");
}
BOOST_AUTO_TEST_CASE(direct_glossy_one_vs_two_threads) { checkIdentical("glossy-lights.yaml", "independent", "direct"); }
