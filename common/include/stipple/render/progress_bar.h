// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The one progress bar the tools draw on a terminal's stderr: "[#########.....................]", and the
// estimate of the time left that goes beside it.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>

namespace stipple::render {

inline std::string progressBar(size_t done, size_t total, int width = 30) {
    const int filled = total ? int(double(done) / double(total) * width) : width;
    std::string bar(size_t(filled < width ? filled : width), '#');
    bar.resize(size_t(width), '.');
    return "[" + bar + "]";
}

// Time left when `done` of `total` equal parts took `elapsedSeconds`: "ETA 1m05s" ("ETA ?" before the first
// part, "done" at the end).
inline std::string progressEta(size_t done, size_t total, double elapsedSeconds) {
    if (done >= total) return "done";
    if (done == 0 || !(elapsedSeconds >= 0)) return "ETA ?";
    const double left = elapsedSeconds / double(done) * double(total - done);
    char buf[48];
    if (left >= 3600)
        std::snprintf(buf, sizeof buf, "ETA %dh%02dm", int(left / 3600), int(left / 60) % 60);
    else
        std::snprintf(buf, sizeof buf, "ETA %dm%02ds", int(left / 60), int(left) % 60);
    return buf;
}

} // namespace stipple::render
