// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Bounds on what an input file or argument may ask for, checked before anything is allocated, so a hostile or
// mistaken input ends in a clear error naming the limit and the offending value instead of std::bad_alloc, a
// stack overflow or an Embree assertion. GUARANTEES.md lists the same numbers.
// Header-only: the renderer and validation's renderer-free core both read files through readFileBounded.
#pragma once

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace stipple::render {

namespace limits {
inline constexpr uint64_t kMaxYamlFileBytes = 16ull << 20; // a scene, matrix or results file
inline constexpr uint64_t kMaxMeshFileBytes = 1ull << 30;  // a PLY / OBJ mesh file
inline constexpr int kMaxIncludeDepth = 32;                // nested `type: include` files
inline constexpr double kMaxCoordinate = 1e12;             // |x| of any point the ray tracer sees (floats)
inline constexpr uint64_t kMaxTrianglesPerShape = 1ull << 26;
inline constexpr uint64_t kMaxPixels = 1ull << 25;           // width × height of one render (33.5 M)
inline constexpr uint64_t kMaxSamplesPerRender = 1ull << 36; // width × height × spp of one render
inline constexpr int kMaxThreads = 1024;   // render threads (TBB's arena takes at most 65536, and far more than
                                           // any machine this runs on has cores)
inline constexpr int kMaxImageSide = 1 << 15; // width or height of a render, in pixels
inline constexpr int kMaxPathDepth = 1000;    // max_depth of a path

// Not a check but a guarantee, tested (integrators.load_memory, validation.matrix_memory): loading a scene or a matrix
// file raises the process's peak memory by at most kLoadBytesPerInputByte × its size + kLoadBaseBytes. The parsed YAML
// is a compact document (16 bytes per node, 4 per child reference, the scalars' text once); measured on 4-12 MiB
// inputs: 5-6 bytes per input byte for a mesh scene with inline vertices, 10 for a matrix, 16 for the worst case (a
// file of one-digit integers, one node per two bytes), against 60-250 with yaml-cpp's node tree. So a scene or
// matrix at the file limit above needs at most about 400 MiB to load.
inline constexpr uint64_t kLoadBytesPerInputByte = 24;
inline constexpr uint64_t kLoadBaseBytes = 16ull << 20;
} // namespace limits

// An input beyond one of the limits above, or a file that cannot be read as a bounded regular file.
class InputLimitError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Reads a whole regular file of at most `limit` bytes. Devices, FIFOs and directories are refused before any
// read (/dev/zero never starts), and a file that grows past the limit while being read stops at limit + 1
// bytes. `what` names the kind of file in the message ("scene file", "matrix file", ...).
inline std::string readFileBounded(const std::string& path, uint64_t limit, const std::string& what) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) throw InputLimitError(path + ": cannot open " + what + ": " + std::strerror(errno));
    struct FdCloser {
        int fd;
        ~FdCloser() { ::close(fd); }
    } closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0) throw InputLimitError(path + ": cannot stat " + what + ": " + std::strerror(errno));
    if (!S_ISREG(st.st_mode)) throw InputLimitError(path + ": " + what + " is not a regular file");
    if (uint64_t(st.st_size) > limit)
        throw InputLimitError(path + ": " + what + " is " + std::to_string(st.st_size) + " bytes; the limit is " +
                              std::to_string(limit) + " bytes");
    std::string text;
    text.resize(size_t(st.st_size));
    size_t used = 0;
    for (;;) {
        if (used == text.size()) {
            if (used > limit) break;
            text.resize(std::min<uint64_t>(limit + 1, used + 65536));
            if (used == text.size()) break;
        }
        const ssize_t n = ::read(fd, text.data() + used, text.size() - used);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw InputLimitError(path + ": cannot read " + what + ": " + std::strerror(errno));
        if (n == 0) break;
        used += size_t(n);
    }
    if (used > limit)
        throw InputLimitError(path + ": " + what + " grew beyond the limit of " + std::to_string(limit) +
                              " bytes while being read");
    text.resize(used);
    return text;
}

// Throws std::invalid_argument when one render would exceed the pixel or sample budget.
inline void checkRenderBudget(int width, int height, uint64_t spp) {
    const uint64_t pixels = uint64_t(width) * uint64_t(height);
    if (pixels > limits::kMaxPixels)
        throw std::invalid_argument("image " + std::to_string(width) + "x" + std::to_string(height) + " = " +
                                    std::to_string(pixels) + " pixels exceeds the limit of " +
                                    std::to_string(limits::kMaxPixels) + " pixels");
    if (pixels * spp > limits::kMaxSamplesPerRender)
        throw std::invalid_argument("image " + std::to_string(width) + "x" + std::to_string(height) + " at " +
                                    std::to_string(spp) + " spp = " + std::to_string(pixels * spp) +
                                    " samples exceeds the limit of " + std::to_string(limits::kMaxSamplesPerRender) +
                                    " samples per render");
}

// Throws std::invalid_argument naming the setting when one numeric render setting is outside its range: threads in
// [0, kMaxThreads] (0: all hardware threads), width and height in [0, kMaxImageSide] (0: the scene's), max depth
// in [-1, kMaxPathDepth] (-1: the scene's). The command lines and the matrix check the same ranges with positions.
inline void checkRenderSettings(int threads, int width, int height, int maxDepth) {
    auto check = [](const char* what, long long v, long long lo, long long hi) {
        if (v < lo || v > hi)
            throw std::invalid_argument(std::string(what) + " " + std::to_string(v) + " is outside [" +
                                        std::to_string(lo) + ", " + std::to_string(hi) + "]");
    };
    check("threads", threads, 0, limits::kMaxThreads);
    check("width", width, 0, limits::kMaxImageSide);
    check("height", height, 0, limits::kMaxImageSide);
    check("max depth", maxDepth, -1, limits::kMaxPathDepth);
}

} // namespace stipple::render
