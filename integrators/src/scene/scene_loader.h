// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Reads a scene YAML file (integrators/SCENE_FORMAT.md) into a SceneDescription. Every error throws SceneError
// with "file:line:column: key 'k': expected ..., got ...".
#pragma once

#include "scene/scene_description.h"

#include <string>

namespace stipple::render {

SceneDescription loadSceneDescription(const std::string& path);

} // namespace stipple::render
