// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The scene-specific input bounds (limits in <stipple/render/input_limits.h>): coordinates the ray tracer can
// represent, checked on the parsed description before any Embree object exists.
#pragma once

#include "scene/scene_description.h"

#include <string>

namespace stipple::render {

// Empty when every component of p is finite with |x| < limits::kMaxCoordinate; otherwise what is wrong,
// with the offending value and the limit.
std::string beyondCoordinateLimit(const Vec3& p);

// Throws SceneError (naming the shape's file:line:column) when any mesh vertex, sphere bound or instanced
// object bound lies beyond limits::kMaxCoordinate. Embree asserts (and aborts) on such bounds.
void checkSceneExtent(const SceneDescription& desc);

} // namespace stipple::render
