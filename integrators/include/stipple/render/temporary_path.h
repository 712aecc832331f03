// The temporary file every writer of the project uses before renaming into place, so a failed run never
// leaves a half-written file under the real name.
#pragma once

#include <filesystem>
#include <string>

#include <unistd.h>

namespace stipple::render {

// Beside `path` (the rename stays on one file system), unique per process, the extension kept (OIIO picks
// the format from it): "<stem>.tmp<pid><ext>".
inline std::string temporaryPathFor(const std::string& path) {
    const std::filesystem::path p(path);
    return (p.parent_path() / (p.stem().string() + ".tmp" + std::to_string(getpid()) + p.extension().string()))
        .string();
}

} // namespace stipple::render
