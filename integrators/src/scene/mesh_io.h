// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Triangle mesh files: PLY (ascii and binary_little_endian; float/double x y z; a face list property
// vertex_indices/vertex_index of any integer type; triangles and quads) and a small OBJ subset (v, f with
// triangles/quads/polygons fanned, v/vt/vn index forms, negative indices). Errors throw MeshFileError naming the
// file and line (ascii) or element (binary).
#pragma once

#include "core/geometry.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace stipple::render {

class MeshFileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct TriangleMesh {
    std::vector<Vec3> positions;
    std::vector<uint32_t> indices; // 3 per triangle
};

TriangleMesh readPly(const std::string& path);
TriangleMesh readObj(const std::string& path);
// By extension (.ply / .obj, case-insensitive).
TriangleMesh readMeshFile(const std::string& path);

} // namespace stipple::render
