// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The scene as the integrators see it: Embree geometry (triangle meshes, analytic spheres as user geometry,
// one level of instances), materials, world-space lights with a by-power light choice, and ray queries that
// return a fully resolved surface hit.
#pragma once

#include "sampling/discrete_distribution.h"
#include "lights/light.h"
#include "scene/scene_description.h"

#include <embree3/rtcore.h>

#include <memory>
#include <vector>

namespace stipple::render {

struct SurfaceHit {
    Vec3 p;  // world position (reconstructed from the primitive, not o + t d)
    Vec3 ng; // unit geometric normal, the shape's front side (CCW winding / sphere outside)
    float t = 0;
    const Material* material = nullptr;
    int light = -1; // index into RenderScene::lights(), -1 when the surface does not emit
};

// A ray's closest hit as a packet query returns it: `found` false when the ray leaves the scene.
struct TracedHit {
    bool found = false;
    SurfaceHit hit;
};

class RenderScene {
public:
    // Builds every Embree scene and commits it (timed: buildSeconds). Throws std::runtime_error on Embree errors.
    explicit RenderScene(SceneDescription desc);
    ~RenderScene();
    RenderScene(const RenderScene&) = delete;
    RenderScene& operator=(const RenderScene&) = delete;

    const SceneDescription& description() const { return desc_; }
    double buildSeconds() const { return buildSeconds_; }
    uint64_t triangleCount() const { return triangleCount_; }

    // Closest hit along ray within (0, ray.tMax). Sets the FTZ/DAZ-independent results only.
    bool intersect(const Ray& ray, SurfaceHit& hit) const;
    // Closest hits of up to kPacketSize rays that start together (one pixel's camera rays) in one packet query,
    // traversing the BVH once for the bundle. The hits are intersect()'s on each ray, except inside instances,
    // where Embree's packet kernels transform rays in their own order and a hit may move in its last bits; a
    // pixel's packets are fixed by the sample count, so an image still depends on the seed and spp alone.
    static constexpr int kPacketSize = 16;
    void intersectPacket(const Ray* rays, int count, TracedHit* hits) const;
    // Whether each of up to kPacketSize rays (tMax set) is blocked, in one packet query.
    void occludedPacket(const Ray* rays, int count, bool* blocked) const;
    // The shadow ray occludedBetween traces: false when there is none to trace (the points coincide).
    static bool shadowRay(const Vec3& p, const Vec3& ng, const Vec3& target, Ray& ray);
    // Any hit along ray within (0, tMax).
    bool occluded(const Ray& ray) const;
    // Shadow ray between a surface point (normal ng) and a light point; true when something lies between.
    bool occludedBetween(const Vec3& p, const Vec3& ng, const Vec3& target) const;

    const std::vector<Light>& lights() const { return lights_; }
    // Light choice by power (one distribution shared by every integrator).
    const DiscreteDistribution& lightChoice() const { return lightChoice_; }
    float lightChoicePmf(int light) const { return lightChoice_.pmf(size_t(light)); }
    bool anyMaterialUsesLobeChoice() const;
    bool anyNonSpecularMaterial() const;

private:
    struct GeomRecord {
        enum class Kind { Mesh, Sphere, Instance } kind = Kind::Mesh;
        int index = 0; // into the group's meshes / spheres, or into instances_
        int light = -1;
    };
    struct Group {
        const ShapeGroup* shapes = nullptr;
        std::vector<GeomRecord> geoms; // by Embree geomID
        RTCScene scene = nullptr;
    };
    struct InstanceRecord {
        int object = 0;
        Transform toWorld, toObject;
        std::vector<int> lightOfGeom; // per geomID of the object's scene
    };

    void buildGroup(Group& group, const ShapeGroup& shapes, bool topLevel);
    void addLightsOf(const ShapeGroup& shapes, const Transform* toWorld, std::vector<int>& lightOfGeom,
                     const std::string& where);
    // The hit record's primitive as a surface point; hitT/u/v/ids as Embree returned them.
    void resolveHit(unsigned instID, unsigned geomID, unsigned primID, float hitT, float u, float v, const Ray& ray,
                    SurfaceHit& hit) const;

    SceneDescription desc_;
    RTCDevice device_ = nullptr;
    Group top_;
    std::vector<Group> objects_;
    std::vector<InstanceRecord> instances_;
    std::vector<std::vector<float>> vertexBuffers_; // padded by one float (Embree reads 16 bytes)
    // Per top-level mesh, per triangle: the unit geometric normal, computed once at build time exactly as a hit
    // would compute it (instanced meshes transform the unnormalized cross product instead, so they have none).
    std::vector<std::vector<Vec3>> topMeshNormals_;
    std::vector<Light> lights_;
    DiscreteDistribution lightChoice_;
    double buildSeconds_ = 0;
    uint64_t triangleCount_ = 0;
};

} // namespace stipple::render
