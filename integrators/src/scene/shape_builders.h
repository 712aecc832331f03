// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Procedural triangle meshes for the scene format's shapes, with outward-facing (CCW) triangles.
#pragma once

#include "scene/mesh_io.h"

namespace stipple::render {

TriangleMesh makeQuad(const Vec3 v[4]);
TriangleMesh makeBox(const Vec3& lo, const Vec3& hi);
TriangleMesh makeCylinder(const Vec3& base, const Vec3& axis, float height, float radius, int segments, bool caps);
// profile: (radius, height) pairs revolved about +y. The outside is to the right of the profile's direction in
// the (radius, height) plane (a profile going up at radius > 0 faces outwards).
TriangleMesh makeLathe(const std::vector<std::pair<float, float>>& profile, int segments);
// A unit-radius UV sphere around the origin (for spheres under non-uniform scale: ellipsoids).
TriangleMesh makeSphereMesh(int rings, int segments);

} // namespace stipple::render
