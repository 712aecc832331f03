#include <stipple/render/content_hash.h>

#include <cstdio>
#include <fstream>

namespace stipple::render {

ContentHash& ContentHash::add(unsigned char byte) {
    h_ ^= byte;
    h_ *= 1099511628211ull;
    return *this;
}

ContentHash& ContentHash::add(std::string_view bytes) {
    for (char c : bytes) add(static_cast<unsigned char>(c));
    return *this;
}

bool ContentHash::addFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) add(std::string_view(buffer, size_t(in.gcount())));
    return true;
}

std::string ContentHash::hex() const {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h_));
    return buf;
}

} // namespace stipple::render
