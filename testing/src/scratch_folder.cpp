// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
#include <stipple/testing/scratch_folder.h>

#include <cstdlib>
#include <unistd.h>

namespace stipple::testing {

namespace {

std::filesystem::path& rootPath() {
    static std::filesystem::path root;
    return root;
}

void removeRoot() {
    std::error_code ec;
    std::filesystem::remove_all(rootPath(), ec);
}

} // namespace

const std::filesystem::path& scratchRoot() {
    // A function-local static: made once even when tests run cases on several threads.
    static const bool made = [] {
        rootPath() = std::filesystem::temp_directory_path() / ("stipple-test-" + std::to_string(::getpid()));
        std::filesystem::create_directories(rootPath());
        std::atexit(removeRoot);
        return true;
    }();
    (void)made;
    return rootPath();
}

std::filesystem::path freshScratchFolder(const std::string& name) {
    const std::filesystem::path dir = scratchRoot() / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace stipple::testing
