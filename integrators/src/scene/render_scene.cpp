// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "scene/render_scene.h"

#include <chrono>
#include <mutex>
#include <stdexcept>

namespace stipple::render {

namespace {

// ---- analytic spheres as Embree user geometry ---------------------------------------------------------------

void sphereBounds(const RTCBoundsFunctionArguments* args) {
    const auto* s = static_cast<const SphereShape*>(args->geometryUserPtr);
    RTCBounds* b = args->bounds_o;
    b->lower_x = s->center.x - s->radius;
    b->lower_y = s->center.y - s->radius;
    b->lower_z = s->center.z - s->radius;
    b->upper_x = s->center.x + s->radius;
    b->upper_y = s->center.y + s->radius;
    b->upper_z = s->center.z + s->radius;
}

// Both roots of |o + t d - c|^2 = r^2 (d need not be unit: instances may scale). Uses the numerically careful
// form of Ray Tracing Gems ch. 7: the discriminant from the closest-approach vector, q without cancellation.
bool sphereRoots(const SphereShape& s, const Vec3& o, const Vec3& d, float& t0, float& t1) {
    Vec3 f = o - s.center;
    float a = dot(d, d);
    float bh = -dot(f, d);
    Vec3 v = f + d * (bh / a);
    float disc = s.radius * s.radius - dot(v, v);
    if (disc < 0) return false;
    float sq = std::sqrt(a * disc);
    float q = bh + std::copysign(sq, bh);
    float c = dot(f, f) - s.radius * s.radius;
    if (q == 0) {
        t0 = t1 = 0;
        return c <= 0;
    }
    t0 = c / q;
    t1 = q / a;
    if (t0 > t1) std::swap(t0, t1);
    return true;
}

void sphereIntersect(const RTCIntersectFunctionNArguments* args) {
    const auto* s = static_cast<const SphereShape*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
        RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
        Vec3 o(RTCRayN_org_x(ray, args->N, i), RTCRayN_org_y(ray, args->N, i), RTCRayN_org_z(ray, args->N, i));
        Vec3 d(RTCRayN_dir_x(ray, args->N, i), RTCRayN_dir_y(ray, args->N, i), RTCRayN_dir_z(ray, args->N, i));
        float tnear = RTCRayN_tnear(ray, args->N, i);
        float& tfar = RTCRayN_tfar(ray, args->N, i);
        float t0, t1;
        if (!sphereRoots(*s, o, d, t0, t1)) continue;
        float t = t0 > tnear ? t0 : t1;
        if (t <= tnear || t >= tfar) continue;
        tfar = t;
        Vec3 n = o + d * t - s->center;
        RTCHitN_Ng_x(hit, args->N, i) = n.x;
        RTCHitN_Ng_y(hit, args->N, i) = n.y;
        RTCHitN_Ng_z(hit, args->N, i) = n.z;
        RTCHitN_u(hit, args->N, i) = 0;
        RTCHitN_v(hit, args->N, i) = 0;
        RTCHitN_primID(hit, args->N, i) = args->primID;
        RTCHitN_geomID(hit, args->N, i) = args->geomID;
        RTCHitN_instID(hit, args->N, i, 0) = args->context->instID[0];
    }
}

void sphereOccluded(const RTCOccludedFunctionNArguments* args) {
    const auto* s = static_cast<const SphereShape*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        RTCRayN* ray = args->ray;
        Vec3 o(RTCRayN_org_x(ray, args->N, i), RTCRayN_org_y(ray, args->N, i), RTCRayN_org_z(ray, args->N, i));
        Vec3 d(RTCRayN_dir_x(ray, args->N, i), RTCRayN_dir_y(ray, args->N, i), RTCRayN_dir_z(ray, args->N, i));
        float tnear = RTCRayN_tnear(ray, args->N, i);
        float& tfar = RTCRayN_tfar(ray, args->N, i);
        float t0, t1;
        if (!sphereRoots(*s, o, d, t0, t1)) continue;
        if ((t0 > tnear && t0 < tfar) || (t1 > tnear && t1 < tfar)) tfar = -kInf; // Embree's "occluded" mark
    }
}

std::mutex embreeErrorMutex;
std::string embreeError;

void onEmbreeError(void*, RTCError code, const char* str) {
    std::lock_guard<std::mutex> lock(embreeErrorMutex);
    if (embreeError.empty()) embreeError = "Embree error " + std::to_string(int(code)) + ": " + (str ? str : "");
}

void throwIfEmbreeError(const char* what) {
    std::lock_guard<std::mutex> lock(embreeErrorMutex);
    if (!embreeError.empty()) {
        std::string e = embreeError;
        embreeError.clear();
        throw std::runtime_error(std::string(what) + ": " + e);
    }
}

RTCRay makeRay(const Ray& r) {
    RTCRay ray;
    ray.org_x = r.o.x;
    ray.org_y = r.o.y;
    ray.org_z = r.o.z;
    ray.tnear = 0;
    ray.dir_x = r.d.x;
    ray.dir_y = r.d.y;
    ray.dir_z = r.d.z;
    ray.time = 0;
    ray.tfar = r.tMax;
    ray.mask = 0xFFFFFFFFu; // masks are compiled into Debian's Embree: 0 would hit nothing
    ray.id = 0;
    ray.flags = 0;
    return ray;
}

} // namespace

RenderScene::RenderScene(SceneDescription desc) : desc_(std::move(desc)) {
    device_ = rtcNewDevice(nullptr);
    if (!device_)
        throw std::runtime_error("cannot create an Embree device (error " +
                                 std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
    rtcSetDeviceErrorFunction(device_, onEmbreeError, nullptr);

    auto start = std::chrono::steady_clock::now();
    objects_.resize(desc_.objects.size());
    for (size_t i = 0; i < desc_.objects.size(); ++i) buildGroup(objects_[i], desc_.objects[i], false);

    // Lights: top-level shapes first (in geometry order), then each instance's emitters in world space.
    buildGroup(top_, desc_.shapes, true);
    {
        std::vector<int> lightOfGeom;
        addLightsOf(desc_.shapes, nullptr, lightOfGeom, "");
        for (size_t g = 0; g < lightOfGeom.size(); ++g) top_.geoms[g].light = lightOfGeom[g];
    }
    for (size_t i = 0; i < desc_.instances.size(); ++i) {
        const InstanceShape& inst = desc_.instances[i];
        InstanceRecord rec;
        rec.object = inst.object;
        rec.toWorld = inst.objectToWorld;
        rec.toObject = inst.objectToWorld.inverse();
        addLightsOf(desc_.objects[size_t(inst.object)], &rec.toWorld, rec.lightOfGeom, inst.origin);
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(g, objects_[size_t(inst.object)].scene);
        float m[12]; // column-major 3x4
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 3; ++r) m[c * 3 + r] = rec.toWorld.m[r][c];
        rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, m);
        rtcCommitGeometry(g);
        unsigned id = rtcAttachGeometry(top_.scene, g);
        rtcReleaseGeometry(g);
        if (id != top_.geoms.size()) throw std::logic_error("unexpected Embree geometry id");
        top_.geoms.push_back({GeomRecord::Kind::Instance, int(instances_.size()), -1});
        for (const MeshShape& m2 : desc_.objects[size_t(inst.object)].meshes) triangleCount_ += m2.indices.size() / 3;
        instances_.push_back(std::move(rec));
    }
    rtcCommitScene(top_.scene);
    throwIfEmbreeError("building the scene");
    buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    std::vector<double> power;
    // By power unless the scene asks for uniform choice (Veach's MIS scene: a bright fill light would take
    // nearly every light sample away from the four lights the scene is about).
    for (const Light& l : lights_) power.push_back(desc_.settings.uniformLightSelection ? 1.0 : l.power());
    lightChoice_ = DiscreteDistribution(power);
}

RenderScene::~RenderScene() {
    for (Group& g : objects_)
        if (g.scene) rtcReleaseScene(g.scene);
    if (top_.scene) rtcReleaseScene(top_.scene);
    if (device_) rtcReleaseDevice(device_);
}

void RenderScene::buildGroup(Group& group, const ShapeGroup& shapes, bool topLevel) {
    group.shapes = &shapes;
    group.scene = rtcNewScene(device_);
    rtcSetSceneBuildQuality(group.scene, RTC_BUILD_QUALITY_MEDIUM);
    for (size_t i = 0; i < shapes.meshes.size(); ++i) {
        const MeshShape& mesh = shapes.meshes[i];
        std::vector<float>& vb = vertexBuffers_.emplace_back();
        vb.reserve(mesh.positions.size() * 3 + 1);
        for (const Vec3& p : mesh.positions) vb.insert(vb.end(), {p.x, p.y, p.z});
        vb.push_back(0.0f); // padding: Embree may read 16 bytes at the last vertex
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, vb.data(), 0, 3 * sizeof(float),
                                   mesh.positions.size());
        rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.indices.data(), 0,
                                   3 * sizeof(uint32_t), mesh.indices.size() / 3);
        rtcCommitGeometry(g);
        unsigned id = rtcAttachGeometry(group.scene, g);
        rtcReleaseGeometry(g);
        if (id != group.geoms.size()) throw std::logic_error("unexpected Embree geometry id");
        group.geoms.push_back({GeomRecord::Kind::Mesh, int(i), -1});
        if (topLevel) {
            triangleCount_ += mesh.indices.size() / 3;
            std::vector<Vec3>& normals = topMeshNormals_.emplace_back();
            normals.reserve(mesh.indices.size() / 3);
            for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
                const Vec3 &a = mesh.positions[mesh.indices[t]], &b = mesh.positions[mesh.indices[t + 1]],
                           &c = mesh.positions[mesh.indices[t + 2]];
                normals.push_back(normalize(cross(b - a, c - a)));
            }
        }
    }
    for (size_t i = 0; i < shapes.spheres.size(); ++i) {
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(g, 1);
        rtcSetGeometryUserData(g, const_cast<SphereShape*>(&shapes.spheres[i]));
        rtcSetGeometryBoundsFunction(g, sphereBounds, nullptr);
        rtcSetGeometryIntersectFunction(g, sphereIntersect);
        rtcSetGeometryOccludedFunction(g, sphereOccluded);
        rtcCommitGeometry(g);
        unsigned id = rtcAttachGeometry(group.scene, g);
        rtcReleaseGeometry(g);
        if (id != group.geoms.size()) throw std::logic_error("unexpected Embree geometry id");
        group.geoms.push_back({GeomRecord::Kind::Sphere, int(i), -1});
    }
    if (!topLevel) rtcCommitScene(group.scene);
    throwIfEmbreeError("building an Embree scene");
}

void RenderScene::addLightsOf(const ShapeGroup& shapes, const Transform* toWorld, std::vector<int>& lightOfGeom,
                              const std::string& where) {
    auto P = [&](const Vec3& p) { return toWorld ? toWorld->point(p) : p; };
    lightOfGeom.assign(shapes.meshes.size() + shapes.spheres.size(), -1);
    for (size_t i = 0; i < shapes.meshes.size(); ++i) {
        const MeshShape& m = shapes.meshes[i];
        if (!m.emission.isEmitter() || m.indices.empty()) continue;
        lightOfGeom[i] = int(lights_.size());
        if (m.isParallelogram) {
            Vec3 p0 = P(m.positions[0]), p1 = P(m.positions[1]), p3 = P(m.positions[3]);
            lights_.push_back(Light::parallelogram(p0, p1 - p0, p3 - p0, m.emission.radiance, m.emission.twoSided));
        } else {
            std::vector<Vec3> tri;
            tri.reserve(m.indices.size());
            for (uint32_t idx : m.indices) tri.push_back(P(m.positions[idx]));
            lights_.push_back(Light::mesh(std::move(tri), m.emission.radiance, m.emission.twoSided));
        }
    }
    for (size_t i = 0; i < shapes.spheres.size(); ++i) {
        const SphereShape& s = shapes.spheres[i];
        if (!s.emission.isEmitter()) continue;
        float scale = 1;
        if (toWorld && !toWorld->isSimilarity(scale))
            throw std::runtime_error(where + ": an emissive sphere (" + s.origin +
                                     ") is instanced with a non-uniform scale; emitters must stay spheres");
        lightOfGeom[shapes.meshes.size() + i] = int(lights_.size());
        lights_.push_back(Light::sphere(P(s.center), s.radius * scale, s.emission.radiance, s.emission.twoSided));
    }
}

void RenderScene::resolveHit(unsigned instID, unsigned geomID, unsigned primID, float hitT, float u, float v,
                             const Ray& ray, SurfaceHit& hit) const {
    const Group* group = &top_;
    const InstanceRecord* inst = nullptr;
    const GeomRecord* rec = nullptr;
    if (instID != RTC_INVALID_GEOMETRY_ID) {
        inst = &instances_[size_t(top_.geoms[instID].index)];
        group = &objects_[size_t(inst->object)];
    }
    rec = &group->geoms[geomID];
    hit.t = hitT;
    hit.light = inst ? inst->lightOfGeom[geomID] : rec->light;
    Vec3 pObj, nObj;
    if (rec->kind == GeomRecord::Kind::Mesh) {
        const MeshShape& m = group->shapes->meshes[size_t(rec->index)];
        const uint32_t* idx = &m.indices[3 * size_t(primID)];
        const Vec3 &a = m.positions[idx[0]], &b = m.positions[idx[1]], &c = m.positions[idx[2]];
        pObj = a * (1 - u - v) + b * u + c * v;
        hit.material = &desc_.materials[size_t(m.material)];
        if (!inst) { // the common case: the normal computed at build time
            hit.p = pObj;
            hit.ng = topMeshNormals_[size_t(rec->index)][primID];
            return;
        }
        nObj = cross(b - a, c - a);
    } else {
        const SphereShape& s = group->shapes->spheres[size_t(rec->index)];
        Vec3 o = ray.o, d = ray.d;
        if (inst) {
            o = inst->toObject.point(o);
            d = inst->toObject.vector(d);
        }
        nObj = normalize(o + d * hit.t - s.center);
        pObj = s.center + nObj * s.radius;
        hit.material = &desc_.materials[size_t(s.material)];
    }
    if (inst) {
        hit.p = inst->toWorld.point(pObj);
        hit.ng = normalize(inst->toObject.normalByInverse(nObj));
    } else {
        hit.p = pObj;
        hit.ng = normalize(nObj);
    }
}

bool RenderScene::intersect(const Ray& ray, SurfaceHit& hit) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRayHit rh;
    rh.ray = makeRay(ray);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(top_.scene, &ctx, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    resolveHit(rh.hit.instID[0], rh.hit.geomID, rh.hit.primID, rh.ray.tfar, rh.hit.u, rh.hit.v, ray, hit);
    return true;
}

void RenderScene::intersectPacket(const Ray* rays, int count, TracedHit* hits) const {
    static_assert(kPacketSize == 16, "the packet query below is rtcIntersect16");
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT; // a hint only: the hits do not depend on it
    alignas(64) RTCRayHit16 rh;
    alignas(64) int valid[16];
    for (int i = 0; i < 16; ++i) {
        valid[i] = i < count ? -1 : 0;
        const Ray& r = rays[i < count ? i : 0]; // lanes past count hold a valid ray Embree ignores
        rh.ray.org_x[i] = r.o.x;
        rh.ray.org_y[i] = r.o.y;
        rh.ray.org_z[i] = r.o.z;
        rh.ray.tnear[i] = 0;
        rh.ray.dir_x[i] = r.d.x;
        rh.ray.dir_y[i] = r.d.y;
        rh.ray.dir_z[i] = r.d.z;
        rh.ray.time[i] = 0;
        rh.ray.tfar[i] = r.tMax;
        rh.ray.mask[i] = 0xFFFFFFFFu;
        rh.ray.id[i] = unsigned(i);
        rh.ray.flags[i] = 0;
        rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect16(valid, top_.scene, &ctx, &rh);
    for (int i = 0; i < count; ++i) {
        hits[i].found = rh.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID;
        if (hits[i].found)
            resolveHit(rh.hit.instID[0][i], rh.hit.geomID[i], rh.hit.primID[i], rh.ray.tfar[i], rh.hit.u[i],
                       rh.hit.v[i], rays[i], hits[i].hit);
    }
}

bool RenderScene::occluded(const Ray& ray) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRay r = makeRay(ray);
    rtcOccluded1(top_.scene, &ctx, &r);
    return r.tfar < 0;
}

bool RenderScene::shadowRay(const Vec3& p, const Vec3& ng, const Vec3& target, Ray& ray) {
    Vec3 w = target - p;
    Vec3 o = offsetRayOrigin(p, ng, w);
    Vec3 d = target - o;
    float dist = length(d);
    if (dist == 0) return false;
    ray = Ray{o, d / dist, dist * (1 - 1e-5f) - surfaceEpsilon(target)};
    return ray.tMax > 0;
}

bool RenderScene::occludedBetween(const Vec3& p, const Vec3& ng, const Vec3& target) const {
    Ray r;
    return shadowRay(p, ng, target, r) && occluded(r);
}

void RenderScene::occludedPacket(const Ray* rays, int count, bool* blocked) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    alignas(64) RTCRay16 rr;
    alignas(64) int valid[16];
    for (int i = 0; i < 16; ++i) {
        valid[i] = i < count ? -1 : 0;
        const Ray& r = rays[i < count ? i : 0];
        rr.org_x[i] = r.o.x;
        rr.org_y[i] = r.o.y;
        rr.org_z[i] = r.o.z;
        rr.tnear[i] = 0;
        rr.dir_x[i] = r.d.x;
        rr.dir_y[i] = r.d.y;
        rr.dir_z[i] = r.d.z;
        rr.time[i] = 0;
        rr.tfar[i] = r.tMax;
        rr.mask[i] = 0xFFFFFFFFu;
        rr.id[i] = unsigned(i);
        rr.flags[i] = 0;
    }
    rtcOccluded16(valid, top_.scene, &ctx, &rr);
    for (int i = 0; i < count; ++i) blocked[i] = rr.tfar[i] < 0;
}

bool RenderScene::anyMaterialUsesLobeChoice() const {
    for (const Material& m : desc_.materials)
        if (m.usesLobeChoice()) return true;
    return false;
}

bool RenderScene::anyNonSpecularMaterial() const {
    for (const Material& m : desc_.materials)
        if (!m.isSpecular()) return true;
    return false;
}

} // namespace stipple::render
