// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pfm_fuzzer.cpp — libFuzzer harness of the external renderers' PFM reader (pfm_image.h): the input is written to
// a file and read as the image of a 4x3 cell. Expected: an image of exactly 4x3 RGB floats, or a
// std::runtime_error naming the file; memory stays bounded by the expected size whatever the header claims. Any
// other exception, a crash or a sanitizer report is a finding. (EXR goes through OIIO, fuzzed by its authors;
// the run compares its size with the matrix's after reading.)
#include "metrics/pfm_image.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace {

void require(bool condition) {
    if (!condition) __builtin_trap();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size > 16384) return 0;
    // The system's temporary folder ($TMPDIR), one file per fuzzing process.
    static const std::string path =
        (std::filesystem::temp_directory_path() / ("stipple-pfm-fuzz-" + std::to_string(::getpid()) + ".pfm")).string();
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return 0;
    const bool written = std::fwrite(data, 1, size, f) == size;
    std::fclose(f);
    if (!written) return 0;
    try {
        const stipple::render::Image image = stipple::validation::readPfm(path, 4, 3);
        require(image.width == 4 && image.height == 3 && image.rgb.size() == 4 * 3 * 3);
    } catch (const std::runtime_error& e) {
        require(std::string(e.what()).find(path) == 0);
    }
    std::remove(path.c_str());
    return 0;
}
