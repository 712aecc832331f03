// The one progress bar the tools draw on a terminal's stderr: "[#########.....................]".
#pragma once

#include <cstddef>
#include <string>

namespace stipple::render {

inline std::string progressBar(size_t done, size_t total, int width = 30) {
    const int filled = total ? int(double(done) / double(total) * width) : width;
    std::string bar(size_t(filled < width ? filled : width), '#');
    bar.resize(size_t(width), '.');
    return "[" + bar + "]";
}

} // namespace stipple::render
