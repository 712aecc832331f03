// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Publishing one render's outputs together: the EXR and its PNG preview are both written to temporaries beside
// their targets and renamed into place by renameTogether (publish_journal.h): a SIGINT / SIGTERM waits for both
// renames, and a SIGKILL between them is completed by the next run's sweep, so a new EXR never stays beside an
// old PNG; when writing fails both temporaries are removed and the old pair stays.
#pragma once

#include <stipple/render/image_io.h>

#include <string>
#include <utility>
#include <vector>

namespace stipple::render {

// A file name made from a scene's `name:` that stays in the working folder: characters outside
// [A-Za-z0-9._-] become '_', leading dots are dropped, empty becomes "render", at most 100 characters.
std::string safeOutputStem(const std::string& sceneName);

// Writes `exrPath` (float EXR with metadata) and the PNG beside it (same stem), all or nothing.
// Returns the PNG path.
std::string publishRenderOutputs(const std::string& exrPath, const Image& image,
                                 const std::vector<std::pair<std::string, std::string>>& metadata, float exposureStops);

} // namespace stipple::render
