// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// matrix_fuzzer.cpp — libFuzzer harness for the validation matrix loader (validation/README.md format). The input
// is parsed as the text of "fuzz/matrix.yaml" through parseMatrix (the same code loadMatrix runs on a file).
// Expected: a Matrix that keeps the documented invariants, or a MatrixError whose message starts with the file
// name and a position; any other exception, a crash or a sanitizer report is a finding.
#include "matrix/matrix.h"
#include "../tests/test_vocabulary.h"

#include <algorithm>
#include <cstdint>
#include <string>

namespace {

void require(bool condition) {
    if (!condition) __builtin_trap();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size > 16384) return 0;
    const std::string text(reinterpret_cast<const char*>(data), size);
    const std::string path = "fuzz/matrix.yaml";
    using namespace stipple::validation;
    try {
        const Matrix m = parseMatrix(text, path, stipple::validation::test::kVocabulary);
        // What the runner relies on: sample counts ascending, at least one scene and pattern, K >= 4 seeds, checks
        // that name a scene of the matrix (or all).
        require(std::is_sorted(m.spp.begin(), m.spp.end()));
        require(!m.scenes.empty() && !m.patterns.empty() && !m.spp.empty());
        require(m.seeds.size() >= 4);
        for (const Check& c : m.checks) require(c.scene == "all" || m.findScene(c.scene) != nullptr);
    } catch (const MatrixError& e) {
        require(std::string(e.what()).rfind(path, 0) == 0);
    }
    return 0;
}
