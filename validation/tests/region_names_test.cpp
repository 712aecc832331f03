// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The matrix loader's region-name checks (a name twice, two names with one report file name) on many regions.
//
// The checks compare each region with the earlier ones by report file name. Two measures of their cost, neither a
// clock: the loader's heap allocations, counted here, grow in proportion to the region count (a scan that builds
// the file names of every earlier region for each new one, as the checks once did, makes them grow with its
// square); and the test's CTest TIMEOUT (validation/tests/CMakeLists.txt) is a ceiling far above the loader's cost
// and below the quadratic scan's on 32,000 regions.
#define BOOST_TEST_MODULE region_names
#include <boost/test/unit_test.hpp>

#include <atomic>
#include <cstdlib>
#include <new>
#include <string>

#include "matrix/matrix.h"
#include "test_vocabulary.h"

using namespace stipple::validation;

// Every heap allocation of this program is counted (single-threaded: the loader starts no thread).
namespace {
std::atomic<uint64_t> allocations{0};
}
void* operator new(std::size_t size) {
    allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size ? size : 1)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace {

// Region names longer than a short string's inline buffer, so that building a file name allocates.
std::string regionName(uint32_t i) { return "shadow_region_of_the_scene_" + std::to_string(100000 + i); }

// A matrix of one scene (its file is the test's own source: the loader checks only that it is a regular file)
// with `count` regions; `last`, if given, names the last one instead.
std::string matrixText(uint32_t count, const std::string& last = {}) {
    std::string text = "name: regions\nscenes:\n  - file: " STIPPLE_TEST_SCENE_FILE
                       "\n    width: 32\n    height: 24\n    regions:\n";
    for (uint32_t i = 0; i < count; ++i)
        text += "      - { name: " + (i + 1 == count && !last.empty() ? last : regionName(i)) +
                ", rect: [0, 0, 1, 1] }\n";
    return text + "patterns: [independent, stratified]\nspp: [4]\nseeds: 4\nreference: { spp: 16, seed: 99 }\n";
}

std::string loadError(const std::string& text) {
    try {
        parseMatrix(text, "regions.yaml", test::kVocabulary);
    } catch (const MatrixError& e) {
        return e.what();
    }
    return "(loaded)";
}

uint64_t allocationsToLoad(uint32_t regions) {
    const std::string text = matrixText(regions);
    const uint64_t before = allocations.load();
    const Matrix m = parseMatrix(text, "regions.yaml", test::kVocabulary);
    const uint64_t used = allocations.load() - before;
    BOOST_REQUIRE_EQUAL(m.scenes.at(0).regions.size(), regions);
    return used;
}

} // namespace

// 8 times the regions: about 8 times the allocations (a quadratic scan: about 64 times).
BOOST_AUTO_TEST_CASE(the_checks_allocate_in_proportion_to_the_region_count) {
    const uint64_t small = allocationsToLoad(1000), large = allocationsToLoad(8000);
    BOOST_TEST_MESSAGE("allocations: " << small << " for 1000 regions, " << large << " for 8000");
    BOOST_CHECK_LT(double(large) / double(small), 12.0);
}

// 32,000 regions load, and a repeat or a file-name clash in the last one is found and named.
BOOST_AUTO_TEST_CASE(thirty_two_thousand_regions_are_checked) {
    constexpr uint32_t kRegions = 32000;
    const Matrix m = parseMatrix(matrixText(kRegions), "regions.yaml", test::kVocabulary);
    BOOST_REQUIRE_EQUAL(m.scenes.at(0).regions.size(), kRegions);
    BOOST_CHECK_EQUAL(m.scenes[0].regions.back().name, regionName(kRegions - 1));
    const uint32_t lastLine = 7 + kRegions - 1;
    const std::string twice = loadError(matrixText(kRegions, regionName(0)));
    BOOST_CHECK_MESSAGE(twice.find("regions.yaml:" + std::to_string(lastLine) + ":") != std::string::npos &&
                            twice.find("region '" + regionName(0) + "' appears twice") != std::string::npos,
                        twice);
    std::string clash = regionName(17);
    clash[6] = '.'; // "shadow.region_...": the same report file name as "shadow_region_..."
    const std::string sameFile = loadError(matrixText(kRegions, clash));
    BOOST_CHECK_MESSAGE(sameFile.find("regions.yaml:" + std::to_string(lastLine) + ":") != std::string::npos &&
                            sameFile.find("have the same file name") != std::string::npos,
                        sameFile);
}
