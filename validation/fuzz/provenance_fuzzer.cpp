// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// provenance_fuzzer.cpp — libFuzzer harness of the reference cache's reader: the provenance JSON of an entry is
// parsed and verified against the key, size and pixel checksums of a fixed 3x2 reference. Expected: a
// Provenance or a std::runtime_error; an entry verifies only when its key material, size and both checksums are
// exactly the reference's. Any other exception, a crash or a sanitizer report is a finding.
#include "run/reference_integrity.h"

#include <cstdint>
#include <stdexcept>
#include <string>

namespace {

void require(bool condition) {
    if (!condition) __builtin_trap();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size > 16384) return 0;
    using namespace stipple::validation;
    static const stipple::render::Image image{
        3, 2, {0.1f, 0.2f, 0.3f, 1, 2, 3, 0, 0, 0, 4, 5, 6, 7, 8, 9, 0.5f, 0.25f, 1}};
    static const stipple::render::Image variance{3, 2, std::vector<float>(18, 0.01f)};
    static const std::string key = "0123456789abcdef", material = "scene|1.0|shim|3x2|spp 16|seed 7";
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const Provenance p = parseProvenance(text);
        const bool headerOk = verifyProvenance(p, key, material, 3, 2).empty();
        require(headerOk == (p.key == key && p.keyMaterial == material && p.width == 3 && p.height == 2));
        const bool pixelsOk = verifyPixels(p, image, variance).empty();
        require(pixelsOk == (p.width == 3 && p.height == 2 && p.imageChecksum == pixelChecksumHex(image) &&
                             p.varianceChecksum == pixelChecksumHex(variance)));
    } catch (const std::runtime_error& e) {
        require(e.what()[0] != '\0');
    }
    return 0;
}
