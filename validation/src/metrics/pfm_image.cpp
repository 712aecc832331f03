// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "metrics/pfm_image.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace stipple::validation {

render::Image readPfm(const std::string& path, int expectedWidth, int expectedHeight) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot open");
    // The header is a few short tokens: read at most 256 bytes of it, never a line of any length.
    std::string header;
    int fields = 0;
    for (char c; fields < 4 && header.size() < 256 && in.get(c);) {
        const bool space = c == ' ' || c == '\n' || c == '\r' || c == '\t';
        if (space && !header.empty() && header.back() != ' ') {
            ++fields;
            header += ' ';
        } else if (!space)
            header += c;
    }
    if (fields < 4) throw std::runtime_error(path + ": not a PFM file (header)");
    std::istringstream tokens(header);
    std::string magic;
    long long width = 0, height = 0;
    double scale = 0;
    tokens >> magic >> width >> height >> scale;
    if (!tokens || (magic != "PF" && magic != "Pf")) throw std::runtime_error(path + ": not a PFM file (header)");
    if (width < 1 || height < 1 || width > 65536 || height > 65536 || scale == 0 || !std::isfinite(scale))
        throw std::runtime_error(path + ": bad PFM size or scale");
    // The size the matrix expects is compared before anything is allocated: memory is bounded by the matrix.
    if (expectedWidth > 0 && (width != expectedWidth || height != expectedHeight))
        throw std::runtime_error(path + ": the image is " + std::to_string(width) + "x" + std::to_string(height) +
                                 "; the matrix asks for " + std::to_string(expectedWidth) + "x" +
                                 std::to_string(expectedHeight));
    const int channels = magic == "PF" ? 3 : 1;
    const std::streamoff dataStart = in.tellg();
    in.seekg(0, std::ios::end);
    const std::streamoff dataBytes = std::streamoff(in.tellg()) - dataStart;
    in.seekg(dataStart);
    if (dataBytes < std::streamoff(width * height * channels * 4))
        throw std::runtime_error(path + ": PFM data shorter than " + std::to_string(width) + "x" +
                                 std::to_string(height) + "x" + std::to_string(channels) + " floats");
    std::vector<float> data(size_t(width) * height * channels);
    if (!in.read(reinterpret_cast<char*>(data.data()), std::streamsize(data.size() * sizeof(float))))
        throw std::runtime_error(path + ": PFM data shorter than " + std::to_string(width) + "x" +
                                 std::to_string(height) + "x" + std::to_string(channels) + " floats");
    const bool bigEndian = scale > 0;
    if (bigEndian)
        for (float& v : data) {
            uint32_t bits;
            std::memcpy(&bits, &v, 4);
            bits = __builtin_bswap32(bits);
            std::memcpy(&v, &bits, 4);
        }
    render::Image image;
    image.width = int(width);
    image.height = int(height);
    image.rgb.resize(size_t(width) * height * 3);
    for (long long y = 0; y < height; ++y) // PFM rows run bottom to top
        for (long long x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c)
                image.rgb[(size_t(height - 1 - y) * width + x) * 3 + c] =
                    data[(size_t(y) * width + x) * channels + (channels == 3 ? c : 0)];
    return image;
}

} // namespace stipple::validation
