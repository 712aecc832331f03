// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "scene/scene_extent.h"

#include <stipple/render/input_limits.h>
#include <stipple/render/scene_error.h>

#include <cmath>
#include <sstream>

namespace stipple::render {

namespace {

std::string show(double v) {
    std::ostringstream o;
    o << v;
    return o.str();
}

struct Box {
    Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    bool empty() const { return !(lo.x <= hi.x); }
    void add(const Vec3& p) {
        lo = Vec3(std::fmin(lo.x, p.x), std::fmin(lo.y, p.y), std::fmin(lo.z, p.z));
        hi = Vec3(std::fmax(hi.x, p.x), std::fmax(hi.y, p.y), std::fmax(hi.z, p.z));
    }
};

// Checks a group's own coordinates; returns their bounds (for the instances of an object).
Box checkGroup(const ShapeGroup& g) {
    Box box;
    for (const MeshShape& m : g.meshes)
        for (const Vec3& p : m.positions) {
            if (std::string bad = beyondCoordinateLimit(p); !bad.empty())
                throw SceneError(m.origin + ": a vertex " + bad);
            box.add(p);
        }
    for (const SphereShape& s : g.spheres) {
        const Vec3 r(s.radius, s.radius, s.radius);
        for (const Vec3& p : {s.center - r, s.center + r}) {
            if (std::string bad = beyondCoordinateLimit(p); !bad.empty())
                throw SceneError(s.origin + ": the sphere's bounds " + bad);
            box.add(p);
        }
    }
    return box;
}

} // namespace

std::string beyondCoordinateLimit(const Vec3& p) {
    // Compared as floats: 1e12 read into a float is 999999995904, which a double comparison would let through.
    for (float v : {p.x, p.y, p.z})
        if (!(std::fabs(v) < float(limits::kMaxCoordinate)))
            return "has coordinate " + show(v) + ", beyond the limit of +-" + show(limits::kMaxCoordinate) +
                   " that the ray tracer can represent";
    return {};
}

void checkSceneExtent(const SceneDescription& desc) {
    checkGroup(desc.shapes);
    std::vector<Box> objectBounds;
    for (const ShapeGroup& g : desc.objects) objectBounds.push_back(checkGroup(g));
    for (const InstanceShape& inst : desc.instances) {
        const Box& b = objectBounds.at(size_t(inst.object));
        if (b.empty()) continue;
        for (int c = 0; c < 8; ++c) {
            const Vec3 corner(c & 1 ? b.hi.x : b.lo.x, c & 2 ? b.hi.y : b.lo.y, c & 4 ? b.hi.z : b.lo.z);
            if (std::string bad = beyondCoordinateLimit(inst.objectToWorld.point(corner)); !bad.empty())
                throw SceneError(inst.origin + ": the instanced object's bounds " + bad);
        }
    }
}

} // namespace stipple::render
