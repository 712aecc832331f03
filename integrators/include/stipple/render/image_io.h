// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Reading and writing images (OpenImageIO underneath): float EXR with the project's metadata, sRGB PNG previews.
#pragma once

#include <stipple/render/image.h>

#include <string>
#include <utility>
#include <vector>

namespace stipple::render {

// EXR metadata: bare snake_case keys (scene, content_hash, integrator, pattern, spp, seed, max_depth,
// renderer, reference_key, render_seconds, ...), stored as "stipple:<key>". One vocabulary for every writer.
using ImageMetadata = std::vector<std::pair<std::string, std::string>>;
inline constexpr const char* kMetadataPrefix = "stipple:";

// Writes a float EXR (scene-linear Rec.709) via a temporary file renamed into place, with the standard
// attributes Software (rendererVersion()), chromaticities and oiio:ColorSpace, and each metadata key under
// kMetadataPrefix. Throws std::invalid_argument for a key that is empty or already has a prefix.
void writeExr(const std::string& path, const Image& image, const ImageMetadata& metadata);
// The kMetadataPrefix attributes of an EXR, prefix removed, as strings.
ImageMetadata readExrMetadata(const std::string& path);
// Writes an sRGB PNG preview, exposure in stops: through $OCIO's default display and view when $OCIO is set,
// else OIIO's built-in linear -> sRGB.
void writePng(const std::string& path, const Image& image, float exposureStops = 0.0f);
// Reads an EXR written by writeExr (or any RGB image OIIO reads).
Image readImage(const std::string& path);

} // namespace stipple::render
