// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// What makes a cached reference trustworthy: its provenance names the full key it was rendered for and a
// checksum of the pixel data of both EXRs. The cache uses an entry only when all of it verifies; anything else
// (edited provenance, wrong or flipped pixels, a truncated file, a missing part) is re-rendered and replaced.
#pragma once

#include <cstdint>
#include <string>

#include <stipple/render/renderer.h>

namespace stipple::validation {

// The fields of a provenance JSON the cache relies on.
struct Provenance {
    std::string key;         // 16 hex digits, the entry's file name
    std::string keyMaterial; // everything the key hashes, in full (a hash collision cannot pass)
    int width = 0, height = 0;
    std::string imageChecksum, varianceChecksum; // pixelChecksumHex of each EXR's pixels
};

// FNV-1a 64 over the width, the height and the bytes of the float data, as 16 hex digits.
std::string pixelChecksumHex(const render::Image& image);

// Parses a provenance JSON text; throws std::runtime_error naming what is missing or malformed.
Provenance parseProvenance(const std::string& jsonText);

// Empty when the provenance is the one for (key, keyMaterial, width × height); otherwise what differs.
std::string verifyProvenance(const Provenance& p, const std::string& key, const std::string& keyMaterial, int width,
                             int height);

// Throws std::runtime_error unless `path` is a regular file, opened without following a symlink and without
// blocking (a FIFO, a device, a folder or a symlink in a cache is refused before any read; a FIFO never hangs).
void requireRegularFile(const std::string& path);

// Empty when both images have the provenance's size and checksums; otherwise what differs.
std::string verifyPixels(const Provenance& p, const render::Image& image, const render::Image& variance);

} // namespace stipple::validation
