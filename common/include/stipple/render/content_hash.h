// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// FNV-1a 64 over bytes and files: the one content hash behind scene hashes, the shim's identity, the
// reference-cache keys and the cached references' pixel checksums. Not cryptographic; it tells apart inputs,
// nobody forges them. Header-only, so validation's renderer-free core uses the same one.
#pragma once

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <string_view>

namespace stipple::render {

class ContentHash {
public:
    ContentHash& add(unsigned char byte) {
        h_ ^= byte;
        h_ *= 1099511628211ull;
        return *this;
    }
    ContentHash& add(std::string_view bytes) {
        for (char c : bytes) add(static_cast<unsigned char>(c));
        return *this;
    }
    ContentHash& addBytes(const void* data, size_t size) {
        return add(std::string_view(static_cast<const char*>(data), size));
    }
    // The file's bytes; false (hash unchanged) when it cannot be read.
    bool addFile(const std::string& path) {
        std::ifstream in(path, std::ios::binary);
        if (!in) return false;
        char buffer[1 << 16];
        while (in.read(buffer, sizeof buffer) || in.gcount() > 0) add(std::string_view(buffer, size_t(in.gcount())));
        return true;
    }
    uint64_t value() const { return h_; }
    // 16 lowercase hex digits.
    std::string hex() const {
        char buf[17];
        std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h_));
        return buf;
    }

private:
    uint64_t h_ = 1469598103934665603ull;
};

} // namespace stipple::render
