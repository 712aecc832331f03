// FNV-1a 64 over bytes and files: the one content hash behind scene hashes, the shim's identity and the
// reference-cache keys. Not cryptographic; it tells apart inputs, nobody forges them.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace stipple::render {

class ContentHash {
public:
    ContentHash& add(std::string_view bytes);
    ContentHash& add(unsigned char byte);
    // The file's bytes; false (hash unchanged) when it cannot be read.
    bool addFile(const std::string& path);
    uint64_t value() const { return h_; }
    std::string hex() const; // 16 lowercase hex digits

private:
    uint64_t h_ = 1469598103934665603ull;
};

} // namespace stipple::render
