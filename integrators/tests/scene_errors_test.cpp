// Every file in tests/bad-scenes/*.yaml starts with "# expect: <substring>". Loading it must throw SceneError
// whose message contains that substring and names a file:line:column.
#define BOOST_TEST_MODULE scene_errors
#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <algorithm>
#include <regex>

using namespace stipple::render;
using namespace stipple::render::test;
namespace fs = std::filesystem;

BOOST_AUTO_TEST_CASE(every_bad_scene_gives_its_message) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(STIPPLE_TEST_BAD_SCENES))
        if (e.path().extension() == ".yaml") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    BOOST_TEST(files.size() >= 20u);
    const std::regex place(R"([^ :]+\.(yaml|inc|ply):[0-9]+(:[0-9]+)?: )");
    for (const fs::path& f : files) {
        std::ifstream in(f);
        std::string first;
        std::getline(in, first);
        const std::string tag = "# expect: ";
        BOOST_REQUIRE_MESSAGE(first.rfind(tag, 0) == 0, f.filename() << ": first line must be '# expect: ...'");
        std::string expected = first.substr(tag.size());
        try {
            auto scene = Scene::load(f.string());
            BOOST_ERROR(f.filename() << ": loaded, expected an error containing '" << expected << "'");
        } catch (const SceneError& e) {
            std::string msg = e.what();
            BOOST_TEST_MESSAGE(f.filename().string() << ": " << msg);
            BOOST_TEST(msg.find(expected) != std::string::npos,
                       f.filename() << ": message '" << msg << "' lacks '" << expected << "'");
            BOOST_TEST(std::regex_search(msg, place), f.filename() << ": message '" << msg << "' names no file:line");
        } catch (const std::exception& e) {
            BOOST_ERROR(f.filename() << ": threw a non-SceneError: " << e.what());
        }
    }
}

BOOST_AUTO_TEST_CASE(missing_file_is_a_scene_error) {
    BOOST_CHECK_THROW(Scene::load("no-such-dir/no-such-scene.yaml"), SceneError);
}
