// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "film/output_publish.h"

#include <stipple/render/publish_journal.h>
#include <stipple/render/temp_files.h>

#include <filesystem>
#include <stdexcept>

namespace stipple::render {

namespace fs = std::filesystem;

std::string safeOutputStem(const std::string& sceneName) {
    std::string s;
    for (char c : sceneName) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                        c == '_' || c == '-';
        s += ok ? c : '_';
    }
    while (!s.empty() && s[0] == '.') s.erase(0, 1); // no hidden files, no "..": the name stays a plain file
    if (s.size() > 100) s.resize(100);
    return s.empty() ? "render" : s;
}

std::string publishRenderOutputs(const std::string& exrPath, const Image& image,
                                 const std::vector<std::pair<std::string, std::string>>& metadata,
                                 float exposureStops) {
    const std::string pngPath = fs::path(exrPath).replace_extension(".png").string();
    TempPath exrTemp(exrPath), pngTemp(pngPath);
    writeExr(exrTemp.path(), image, metadata);
    writePng(pngTemp.path(), image, exposureStops);
    // Journaled: a SIGKILL between the two renames is finished (or undone) by the next run's sweep.
    renameTogether({{exrTemp.path(), exrPath}, {pngTemp.path(), pngPath}});
    exrTemp.release();
    pngTemp.release();
    return pngPath;
}

} // namespace stipple::render
