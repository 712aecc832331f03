// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Loading a matrix takes memory in proportion to its file: the peak a load adds (measured in a child process,
// ru_maxrss) stays within limits::kLoadBytesPerInputByte × the file's size + limits::kLoadBaseBytes for a matrix
// of many scene entries. yaml-cpp's node tree took about 70 bytes per byte on the same file. Skipped under
// sanitizers, whose shadow memory and quarantine are not the program's.
#define BOOST_TEST_MODULE matrix_memory
#include <boost/test/unit_test.hpp>

#include <stipple/render/input_limits.h>
#include <stipple/testing/peak_memory.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "matrix/matrix.h"
#include "test_vocabulary.h"

#include <stipple/testing/scratch_folder.h>

using namespace stipple::validation;
namespace fs = std::filesystem;
namespace limits = stipple::render::limits;

BOOST_AUTO_TEST_CASE(big_matrix_loads_in_proportion) {
    if (stipple::testing::kUnderSanitizer) {
        BOOST_TEST_MESSAGE("skipped under a sanitizer: its shadow memory is not the loader's");
        return;
    }
    const fs::path dir = stipple::testing::freshScratchFolder("matrix-memory");
    fs::create_directories(dir);
    std::ofstream(dir / "box.yaml") << "name: box\n";
    std::string text = "patterns: [independent]\nspp: [4]\nseeds: 4\nscenes:\n";
    char line[128];
    for (int i = 0; text.size() < (8u << 20); ++i) {
        std::snprintf(line, sizeof line, "  - { file: box.yaml, name: scene%07d, width: 64, height: 48 }\n", i);
        text += line;
    }
    const std::string path = (dir / "big.yaml").string();
    std::ofstream(path) << text;
    const auto grown = stipple::testing::peakGrowthInChild([&] { loadMatrix(path, test::kVocabulary); });
    fs::remove_all(dir);
    BOOST_REQUIRE_MESSAGE(grown, "the matrix did not load in the child process");
    const uint64_t bound = limits::kLoadBytesPerInputByte * text.size() + limits::kLoadBaseBytes;
    BOOST_TEST_MESSAGE("matrix: " << text.size() << " bytes, load peak +" << *grown << " bytes = "
                                  << double(*grown) / double(text.size()) << " per input byte (bound " << bound << ")");
    BOOST_TEST(*grown <= bound);
}
