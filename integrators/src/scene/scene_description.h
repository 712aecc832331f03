// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The parsed scene: what the YAML says, in world or object space, before any acceleration structure exists.
// The loader (scene_loader.cpp) fills it; RenderScene (render_scene.h) turns it into Embree scenes and lights.
#pragma once

#include "camera/camera.h"
#include "materials/material.h"
#include "core/transform.h"

#include <string>
#include <vector>

namespace stipple::render {

struct Emission {
    Spectrum radiance;     // black: not a light
    bool twoSided = false; // one-sided emitters radiate on the side their normal points to
    bool isEmitter() const { return !radiance.isBlack(); }
};

// Triangles (CCW seen from the front). A quad light keeps its parallelogram so it can be sampled directly.
struct MeshShape {
    std::vector<Vec3> positions;
    std::vector<uint32_t> indices; // 3 per triangle
    int material = 0;
    Emission emission;
    bool isParallelogram = false; // exactly two triangles (v0 v1 v2) (v0 v2 v3) forming a parallelogram
    std::string origin;           // "file:line" of its YAML, for messages
};

struct SphereShape {
    Vec3 center;
    float radius = 1;
    int material = 0;
    Emission emission;
    std::string origin;
};

struct ShapeGroup {
    std::vector<MeshShape> meshes;
    std::vector<SphereShape> spheres;
};

struct InstanceShape {
    int object = 0; // index into SceneDescription::objects
    Transform objectToWorld;
    std::string origin;
};

struct RenderSettings {
    std::string integrator = "path";
    int maxDepth = 8;
    int width = 256;
    int height = 256;
    uint32_t spp = 16;
    uint32_t lightSamples = 1;
    bool uniformLightSelection = false; // light_selection: uniform; default power
};

struct SceneDescription {
    std::string name;
    std::string path;
    RenderSettings settings;
    CameraDesc camera;
    std::vector<Material> materials;
    std::vector<std::string> materialNames;
    std::vector<ShapeGroup> objects;
    std::vector<std::string> objectNames;
    ShapeGroup shapes; // the top level
    std::vector<InstanceShape> instances;
    std::vector<std::string> files; // the scene file and every file it includes or loads (for the hash)
};

} // namespace stipple::render
