// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Scratch folders for tests: one per process under the system's temporary folder, removed when the process exits
// normally, so a test run leaves nothing behind (a crashed run leaves its folder for the post-mortem).
#pragma once

#include <filesystem>
#include <string>

namespace stipple::testing {

// <temp>/stipple-test-<pid>, made on the first call; its removal at exit is registered then.
const std::filesystem::path& scratchRoot();

// scratchRoot()/name, emptied and made: each call starts from nothing.
std::filesystem::path freshScratchFolder(const std::string& name);

} // namespace stipple::testing
