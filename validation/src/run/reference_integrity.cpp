// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "run/reference_integrity.h"

#include <stipple/render/content_hash.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace stipple::validation {

std::string pixelChecksumHex(const render::Image& image) {
    const int32_t size[2] = {image.width, image.height};
    return render::ContentHash()
        .addBytes(size, sizeof size)
        .addBytes(image.rgb.data(), image.rgb.size() * sizeof(float))
        .hex();
}

void requireRegularFile(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        throw std::runtime_error(path + (errno == ELOOP ? ": a symlink" : std::string(": ") + std::strerror(errno)));
    struct stat st {};
    const bool regular = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
    ::close(fd);
    if (!regular) throw std::runtime_error(path + " is not a regular file");
}

Provenance parseProvenance(const std::string& jsonText) {
    nlohmann::json j = nlohmann::json::parse(jsonText, nullptr, /*allow_exceptions=*/false);
    if (j.is_discarded() || !j.is_object()) throw std::runtime_error("provenance is not a JSON object");
    auto text = [&](const char* k) {
        auto it = j.find(k);
        if (it == j.end() || !it->is_string())
            throw std::runtime_error(std::string("provenance lacks the string '") + k + "'");
        return it->get<std::string>();
    };
    auto count = [&](const char* k) {
        auto it = j.find(k);
        if (it == j.end() || !it->is_number_integer() || it->get<long long>() < 1 || it->get<long long>() > (1 << 15))
            throw std::runtime_error(std::string("provenance lacks the size '") + k + "'");
        return int(it->get<long long>());
    };
    Provenance p;
    p.key = text("key");
    p.keyMaterial = text("key_material");
    p.width = count("width");
    p.height = count("height");
    p.imageChecksum = text("image_checksum");
    p.varianceChecksum = text("variance_checksum");
    return p;
}

std::string verifyProvenance(const Provenance& p, const std::string& key, const std::string& keyMaterial, int width,
                             int height) {
    if (p.key != key) return "provenance key '" + p.key + "' is not the entry's '" + key + "'";
    if (p.keyMaterial != keyMaterial) return "provenance was made for other settings ('" + p.keyMaterial + "')";
    if (p.width != width || p.height != height)
        return "provenance size " + std::to_string(p.width) + "x" + std::to_string(p.height) + " is not " +
               std::to_string(width) + "x" + std::to_string(height);
    return {};
}

std::string verifyPixels(const Provenance& p, const render::Image& image, const render::Image& variance) {
    for (const render::Image* im : {&image, &variance})
        if (im->width != p.width || im->height != p.height)
            return "image size " + std::to_string(im->width) + "x" + std::to_string(im->height) +
                   " is not the provenance's";
    if (std::string c = pixelChecksumHex(image); c != p.imageChecksum)
        return "image checksum " + c + " is not the provenance's " + p.imageChecksum;
    if (std::string c = pixelChecksumHex(variance); c != p.varianceChecksum)
        return "variance checksum " + c + " is not the provenance's " + p.varianceChecksum;
    return {};
}

} // namespace stipple::validation
