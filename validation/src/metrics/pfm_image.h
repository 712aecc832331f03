// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The PFM reader of external renderers' images (external_renderer.h). Memory is bounded by what the caller
// expects, never by the file: the header's size is compared with the expected one, and the file's length with the
// header's, before any pixel memory is allocated.
#pragma once

#include <string>

#include <stipple/render/renderer.h>

namespace stipple::validation {

// Reads an RGB PFM ("PF", little- or big-endian, rows bottom to top) or a greyscale one ("Pf", copied to RGB).
// When expectedWidth > 0, a header of another size is refused before any pixel memory is allocated, and the
// file's length is compared with the header's before reading. Throws std::runtime_error naming the file and
// what is wrong.
render::Image readPfm(const std::string& path, int expectedWidth = 0, int expectedHeight = 0);


} // namespace stipple::validation
