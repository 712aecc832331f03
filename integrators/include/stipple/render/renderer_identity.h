// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// What names the renderer in results, image metadata and reference-cache keys.
#pragma once

#include <string>

namespace stipple::render {

// "stipple-render <project version>": what results and image metadata name as their Software.
const char* rendererVersion();
// Short hash of the renderer library's own sources (generated at build time): changes whenever its code does.
const char* rendererSourceHash();
// rendererVersion() plus rendererSourceHash(): the renderer's part of every reference-cache key.
std::string rendererIdentity();

} // namespace stipple::render
