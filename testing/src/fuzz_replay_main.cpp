// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Replays a libFuzzer harness's seed corpus and every input that once crashed it through the same
// LLVMFuzzerTestOneInput, built by gcc without libFuzzer. A broken expectation in the harness traps, which fails
// this test. STIPPLE_FUZZ_DIR names the part's fuzz folder; STIPPLE_FUZZ_CORPUS and STIPPLE_FUZZ_REGRESSIONS the
// harness's two subfolders in it.
#define BOOST_TEST_MODULE fuzz_replay
#include <boost/test/unit_test.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

BOOST_AUTO_TEST_CASE(replay_corpus_and_regressions) {
    namespace fs = std::filesystem;
    const fs::path fuzzDir = STIPPLE_FUZZ_DIR;
    size_t files = 0;
    for (const char* sub : {STIPPLE_FUZZ_CORPUS, STIPPLE_FUZZ_REGRESSIONS}) {
        BOOST_REQUIRE_MESSAGE(fs::is_directory(fuzzDir / sub), "missing " << (fuzzDir / sub).string());
        for (const auto& entry : fs::directory_iterator(fuzzDir / sub)) {
            if (!entry.is_regular_file() || entry.path().filename().string()[0] == '.') continue;
            std::ifstream in(entry.path(), std::ios::binary);
            const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
            BOOST_TEST_CHECKPOINT(entry.path().filename().string());
            LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
            ++files;
        }
    }
    BOOST_TEST_MESSAGE(files << " inputs replayed");
    BOOST_TEST(files > 0u);
}
